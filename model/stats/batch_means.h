// Confidence intervals for sampled timing (docs/sampled-timing.md, "Confidence intervals").
//
// Each detailed window is one sample of the frame. The window sampler hands in the raw
// (unscaled) statistics tree at the end of every window; the difference from the previous one
// is that window's counts. Windows are kept in at most `max_batches` consecutive batches:
// when they are full, neighbours merge and each batch holds twice as many windows. Batching
// bounds the memory (a few trees, whatever the frame's length) and, because neighbouring
// windows are correlated (a TM stays on a treelet, a phase spans several periods), makes the
// batches closer to independent samples than the windows are.
//
// Windows may stand for different spans of the frame (an error target changes the period
// during it): each window's counts are weighted by its period over the first one's, so a
// window of a sparser stretch counts for more. The estimate is then the weighted ratio
// estimator (every count times the frame's exact basis over the weighted measured basis),
// which is what the report extrapolates from; with one period every weight is 1.
//
// The interval of any statistic (a count, a ratio, a formula) comes from delete-one-batch
// replicates: the frame is re-estimated as if each batch in turn had not been measured (its
// counts and its measured denominators removed, the exact totals kept), through the same
// scaling and derivation as the report. How their spread becomes a standard error is the
// IntervalMethod: the jackknife treats the batches as exchangeable, so a trend over the frame
// (a STRaTA frame's DRAM bytes per instruction rise several times from its camera rays to its
// last bounces) counts as variance, although windows spread evenly over the frame follow a
// trend closely; successive differences count only how much neighbouring batches differ.
#pragma once

#include "model/stats/interval_method.h"
#include "model/stats/stat_values.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace strata::stats {


// The half-width at `confidence` of a jackknife estimate from its delete-one replicates:
// Student's t with n - 1 degrees of freedom times sqrt((n - 1) / n x their sum of squares).
// 0 for fewer than 2 replicates.
double jackknife_half_width(const std::vector<double>& replicates, double confidence);
// The same by successive differences: `replicates` in the batches' order. 0 for fewer than 2.
double successive_difference_half_width(const std::vector<double>& replicates, double confidence);

class BatchMeans {
 public:
  // `measured`: the counts a window contributes to, by dotted path and statistic (the
  // extrapolated counts, and the measured denominators); everything else is an exact total
  // that stays whole in every replicate.
  using Selector = std::function<bool(const std::string&, const Values::Stat&)>;
  BatchMeans(Selector measured, size_t max_batches = 32, IntervalMethod method = IntervalMethod::kJackknife);
  IntervalMethod method() const { return method_; }

  // The raw tree as of the end of a window (cumulative since the frame began), and the weight
  // of its counts.
  void add_window(const Values& cumulative, double weight = 1.0);
  // The weight of what follows the last window (the frame's tail), by default 1.
  void set_tail_weight(double weight) { tail_weight_ = weight; }
  // What the frame did since the last window (or its start) is a stratum: every count,
  // measured or exact, in none of the batches. Before the first window only (the head).
  void add_head_stratum(const Values& cumulative);
  // What follows the last window is a stratum (the drain), not a partial batch.
  void set_tail_stratum(bool on) { tail_stratum_ = on; }
  // The strata's raw counts (every count the difference over its stretch; levels are not
  // meaningful there), the head first: each is estimated by its own ratio.
  std::vector<Values> strata(const Values& total) const;

  // The middle stratum's raw totals: the frame's exact counts less the strata's, and every
  // measured count the weighted sum over the batches (with one period and no strata, `total`).
  // What the report scales (by the middle's own factors) and derives.
  Values weighted_total(const Values& total) const;
  size_t windows() const { return windows_; }

  // The batches the final interval uses, given the frame's raw totals (what came after the
  // last window is one more, partial, batch).
  size_t batches(const Values& total) const;

  // For each element of measure(tree), the half-width at `confidence` (e.g. 0.95) of its
  // estimate, by the method. `measure` gets the weighted totals less one batch and must scale and derive
  // them as the report does, then read the figures of interest. Empty when there are fewer
  // than 2 batches (no interval can be given).
  // `replicates`, if given, receives each figure's delete-one-batch estimates, in batch order.
  // No finite-population correction (docs/sampled-timing.md, "Confidence intervals").
  std::vector<double> half_widths(const Values& total, const std::function<std::vector<double>(Values)>& measure,
                                  double confidence, std::vector<std::vector<double>>* replicates = nullptr) const;

 private:
  std::vector<Values> all_batches(const Values& total) const;

  Selector measured_;
  size_t max_batches_;
  IntervalMethod method_;
  size_t windows_ = 0;
  size_t per_batch_ = 1;       // windows in each full batch
  size_t in_current_ = 0;      // windows in the batch being filled
  std::vector<Values> full_;   // the full batches' counts
  Values current_;             // the batch being filled
  Values last_;                // the cumulative tree at the last window's end
  bool have_last_ = false;
  double tail_weight_ = 1.0;
  bool tail_stratum_ = false;
  std::vector<Values> head_;  // the head stratum, if any
};

}  // namespace strata::stats
