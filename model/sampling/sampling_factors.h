// Sampled timing counts its events in the measured parts of the detailed windows only; each
// count is extrapolated to the frame by the cause its basis names, whose whole-frame count the
// ISS knows exactly (docs/sampled-timing.md). 1 for every basis in the other modes.
#pragma once

#include <vector>

#include "model/stats/stat_values.h"

namespace strata::sampling {

// From a snapshot of the chip's tree (its instructions and sampling groups are exact).
stats::Factors extrapolation_factors(const stats::Values& root);

// The frame time the samples imply: instructions retired x measured cycles / measured
// instructions (0 if nothing was measured).
double sampled_model_cycles(const stats::Values& raw);

// The frame as sampled timing estimates it from raw counts: the middle stratum's (measured
// counts weighted by their windows, exact totals whole) and the strata timed in full (the
// frame's head and drain, batch_means.h), each scaled by its own factors: frame cycles by the
// change in the samples' frame time (so rates and static energies vary with it), every count
// by its basis, then the ratios and formulas. The report and the error target's planner
// estimate through this one class, so the interval the planner aims at is the interval the
// report prints.
class SampledEstimate {
 public:
  // `weighted_raw`: the middle's raw totals the estimate is centred on; `strata`: the raw
  // counts of each stratum; `simulated_cycles`: the frame's simulated length so far.
  SampledEstimate(const stats::Values& weighted_raw, const std::vector<stats::Values>& strata, double simulated_cycles);
  // The estimate from the middle's raw totals `raw` (the centre, or a replicate), before the
  // ratios and formulas are derived.
  stats::Values scaled(stats::Values raw) const;
  // The samples' own estimate of the frame time: each stratum's instructions at its measured
  // cycles per instruction (the clock is what frame.cycles reports; docs/sampled-timing.md,
  // "The frame time").
  double samples_cycles() const { return full_model_cycles_; }
  stats::Values operator()(stats::Values raw) const {
    stats::Values v = scaled(std::move(raw));
    v.derive();
    return v;
  }

 private:
  std::vector<stats::Values> strata_;  // scaled
  double strata_model_cycles_ = 0;
  double simulated_cycles_;
  double full_model_cycles_;
};

}  // namespace strata::sampling
