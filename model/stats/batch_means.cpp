#include "model/stats/batch_means.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "model/stats/student_t.h"

namespace strata::stats {

BatchMeans::BatchMeans(Selector measured, size_t max_batches, IntervalMethod method)
    : measured_(std::move(measured)), max_batches_(max_batches < 2 ? 2 : max_batches), method_(method) {}

const char* interval_method_name(IntervalMethod m) {
  switch (m) {
    case IntervalMethod::kJackknife: return "jackknife";
    case IntervalMethod::kSuccessiveDifferences: return "successive differences";
  }
  return "?";
}

void BatchMeans::add_window(const Values& cumulative, double weight) {
  Values window = cumulative;
  if (have_last_) window.combine(last_, -1, measured_);
  if (weight != 1.0) {
    const Values plain = window;
    window.combine(plain, weight - 1.0, measured_);
  }
  last_ = cumulative;
  have_last_ = true;
  ++windows_;
  if (in_current_ == 0) current_ = std::move(window);
  else current_.combine(window, +1, measured_);
  if (++in_current_ < per_batch_) return;
  full_.push_back(std::move(current_));
  in_current_ = 0;
  if (full_.size() < max_batches_) return;
  // Full: merge neighbours, so every batch holds twice the windows (an odd last one waits).
  std::vector<Values> merged;
  for (size_t i = 0; i + 1 < full_.size(); i += 2) {
    merged.push_back(std::move(full_[i]));
    merged.back().combine(full_[i + 1], +1, measured_);
  }
  if (full_.size() % 2 == 1) {
    current_ = std::move(full_.back());
    in_current_ = per_batch_;
  }
  full_ = std::move(merged);
  per_batch_ *= 2;
}

namespace {
bool any_count(const std::string&, const Values::Stat&) { return true; }
}  // namespace

void BatchMeans::add_head_stratum(const Values& cumulative) {
  if (windows_ > 0 || !head_.empty()) throw std::logic_error("BatchMeans: the head stratum comes before every window");
  head_.push_back(cumulative);  // since the frame began: the cumulative tree is the difference
  last_ = cumulative;
  have_last_ = true;
}

std::vector<Values> BatchMeans::strata(const Values& total) const {
  std::vector<Values> out = head_;
  if (tail_stratum_) {
    Values tail = total;
    if (have_last_) tail.combine(last_, -1, any_count);
    out.push_back(std::move(tail));
  }
  return out;
}

std::vector<Values> BatchMeans::all_batches(const Values& total) const {
  std::vector<Values> batches = full_;
  if (in_current_ > 0) batches.push_back(current_);
  if (tail_stratum_) return batches;  // the tail is the drain stratum
  // What came after the last window's end: the frame's tail (its last, partial window).
  Values tail = total;
  if (have_last_) tail.combine(last_, -1, measured_);
  if (tail_weight_ != 1.0) {
    const Values plain = tail;
    tail.combine(plain, tail_weight_ - 1.0, measured_);
  }
  bool any = false;
  tail.visit([&](const std::string& path, const Values::Stat& s) {
    if (s.def->kind == Kind::kCount && measured_(path, s) && s.value() != 0) any = true;
  });
  if (any) batches.push_back(std::move(tail));
  return batches;
}

size_t BatchMeans::batches(const Values& total) const { return all_batches(total).size(); }

Values BatchMeans::weighted_total(const Values& total) const {
  Values est = total;
  const Values copy = total;
  est.combine(copy, -1, measured_);  // every measured count to 0, the exact totals kept
  for (const Values& s : strata(total)) est.combine(s, -1, any_count);  // the middle's exact totals
  for (const Values& b : all_batches(total)) est.combine(b, +1, measured_);
  return est;
}

std::vector<double> BatchMeans::half_widths(const Values& total,
                                            const std::function<std::vector<double>(Values)>& measure,
                                            double confidence,
                                            std::vector<std::vector<double>>* replicates_out) const {
  const std::vector<Values> batches = all_batches(total);
  const size_t n = batches.size();
  if (n < 2) return {};
  const Values est = weighted_total(total);
  std::vector<std::vector<double>> replicates;
  replicates.reserve(n);
  for (const Values& b : batches) {
    Values r = est;
    r.combine(b, -1, measured_);
    replicates.push_back(measure(std::move(r)));
    if (replicates.back().size() != replicates.front().size())
      throw std::logic_error("BatchMeans: measure() returned a different number of figures for a replicate");
  }
  std::vector<double> out(replicates.front().size(), 0.0);
  std::vector<double> column(n);
  if (replicates_out) replicates_out->assign(out.size(), std::vector<double>(n));
  for (size_t k = 0; k < out.size(); ++k) {
    for (size_t i = 0; i < n; ++i) column[i] = replicates[i][k];
    out[k] = method_ == IntervalMethod::kJackknife ? jackknife_half_width(column, confidence)
                                                   : successive_difference_half_width(column, confidence);
    if (replicates_out) (*replicates_out)[k] = column;
  }
  return out;
}

namespace {

// Student's t with `df` degrees of freedom times the standard error sqrt((n - 1) / n x ss), ss
// the replicates' sum of squares (or what stands for it).
double from_sum_of_squares(double ss, size_t n, unsigned df, double confidence) {
  return student_t_quantile(0.5 + 0.5 * confidence, df) * std::sqrt(ss * double(n - 1) / double(n));
}

}  // namespace

double jackknife_half_width(const std::vector<double>& replicates, double confidence) {
  const size_t n = replicates.size();
  if (n < 2) return 0.0;
  double mean = 0.0;
  for (double r : replicates) mean += r;
  mean /= double(n);
  double ss = 0.0;
  for (double r : replicates) ss += (r - mean) * (r - mean);
  return from_sum_of_squares(ss, n, static_cast<unsigned>(n - 1), confidence);
}

double successive_difference_half_width(const std::vector<double>& replicates, double confidence) {
  const size_t n = replicates.size();
  if (n < 2) return 0.0;
  // Half the squared differences of neighbours estimate what the sum of squares about the mean
  // does for exchangeable batches: E[sum (r_i+1 - r_i)^2] = 2 (n - 1) var, E[sum (r_i - mean)^2]
  // = (n - 1) var.
  double ss = 0.0;
  for (size_t i = 1; i < n; ++i) ss += (replicates[i] - replicates[i - 1]) * (replicates[i] - replicates[i - 1]);
  // The mean square successive difference's variance is 1.5 times the sample variance's (for
  // independent normal batches), so it carries about two thirds of the degrees of freedom.
  const unsigned df = std::max(1u, static_cast<unsigned>(std::lround(2.0 * double(n - 1) / 3.0)));
  return from_sum_of_squares(0.5 * ss, n, df, confidence);
}

}  // namespace strata::stats

