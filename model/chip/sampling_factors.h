// Sampled timing counts its events in the measured parts of the detailed windows only; each
// count is extrapolated to the frame by the cause its basis names, whose whole-frame count the
// ISS knows exactly (docs/sampled-timing.md). 1 for every basis in the other modes.
#pragma once

#include "model/stats/stat_values.h"

namespace strata::chip {

// From a snapshot of the chip's tree (its instructions and sampling groups are exact).
stats::Factors extrapolation_factors(const stats::Values& root);

}  // namespace strata::chip
