// The statistics of one simulated frame, as JSON (every number named with its unit, and the
// timing mode it came from), and a short readable summary of it.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "model/chip/chip.h"

namespace strata::chip {

// `wall_seconds`: host time of the simulation itself (for the simulator's own speed).
nlohmann::json chip_report(const Chip& chip, double wall_seconds);

std::string summary_text(const nlohmann::json& report);

}  // namespace strata::chip
