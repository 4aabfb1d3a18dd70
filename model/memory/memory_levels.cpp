#include "model/memory/memory_levels.h"

namespace strata::memory {

using stats::Requirement;
using stats::Unit;

// What the chip reads of each level: the summary's lines, the energy total, the fidelity
// sentinels (model/chip/chip_statistics.cpp, chip_report.cpp) and the default sampling targets.
const std::vector<Requirement>& DramLevel::contract() {
  static const std::vector<Requirement> c = {{"accesses", Unit::kCount},
                                             {"bytes", Unit::kBytes},
                                             {"bandwidth_gb_per_s", Unit::kGigabytesPerSecond},
                                             {"peak_gb_per_s", Unit::kGigabytesPerSecond},
                                             {"energy_nj", Unit::kNanojoules},
                                             {"calendar_overflow_bookings", Unit::kCount},
                                             {"by_data", Unit::kCount, true}};
  return c;
}

const std::vector<Requirement>& L2Level::contract() {
  static const std::vector<Requirement> c = {{"accesses", Unit::kCount},
                                             {"reordered", Unit::kCount},
                                             {"energy_nj", Unit::kNanojoules},
                                             {"calendar_overflow_bookings", Unit::kCount},
                                             {"by_data", Unit::kCount, true}};
  return c;
}

const std::vector<Requirement>& StreamLevel::contract() {
  static const std::vector<Requirement> c = {{"accesses", Unit::kCount},
                                             {"capacity", Unit::kCount},
                                             {"sram_bytes_per_ray", Unit::kBytes},
                                             {"energy_nj", Unit::kNanojoules},
                                             {"calendar_overflow_bookings", Unit::kCount},
                                             {"by_data", Unit::kCount, true}};
  return c;
}

}  // namespace strata::memory
