// Energy per access of the shared SRAMs (L2, ray stream memory) by size: STRaTA's CACTI 6.5
// table at 65 nm (docs: ../shared/ARCHITECTURE.md, "Energy per access").
#pragma once

#include <cstdint>

namespace strata::memory {

// nJ per access for an SRAM of `bytes`: the table entry, or a log-log interpolation between
// the two entries around it. Throws std::invalid_argument outside 512 KB..16 MB.
double sram_access_energy_nj(uint64_t bytes);

}  // namespace strata::memory
