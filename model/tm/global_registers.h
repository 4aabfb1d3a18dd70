// The chip's global registers: the work counters the firmware's atomic increments hand out
// (pixels, paths). Shared by all TMs; the TM hook applies operations in the order it executes
// them, which is deterministic for a given config and mode.
#pragma once

#include <array>
#include <cstdint>

#include "firmware/abi/strata_isa.h"

namespace strata::tm {

struct GlobalRegisters {
  std::array<uint32_t, STRATA_GLOBAL_REGISTERS> values{};
  uint64_t operations = 0;
};

}  // namespace strata::tm
