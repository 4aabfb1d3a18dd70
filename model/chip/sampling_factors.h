// Sampled timing counts its events in the measured parts of the detailed windows only; each
// count is extrapolated to the frame by the cause its basis names, whose whole-frame count the
// ISS knows exactly (docs/sampled-timing.md). 1 for every basis in the other modes.
#pragma once

#include "model/stats/stat_values.h"

namespace strata::chip {

// From a snapshot of the chip's tree (its instructions and sampling groups are exact).
stats::Factors extrapolation_factors(const stats::Values& root);

// The frame time the samples imply: instructions retired x measured cycles / measured
// instructions.
double sampled_model_cycles(const stats::Values& raw);

// The frame as sampled timing estimates it from raw counts (measured counts weighted by their
// windows, exact totals whole): frame cycles scaled by the change in the samples' frame time
// (so rates and static energies vary with it), every count by its basis, then the ratios and
// formulas. The report and the error target's planner estimate through this one function, so
// the interval the planner aims at is the interval the report prints.
class SampledEstimate {
 public:
  // `weighted_raw`: the raw totals the estimate is centred on; `simulated_cycles`: the frame's
  // simulated length so far.
  SampledEstimate(const stats::Values& weighted_raw, double simulated_cycles);
  stats::Values operator()(stats::Values raw) const;

 private:
  double simulated_cycles_;
  double full_model_cycles_;
};

}  // namespace strata::chip
