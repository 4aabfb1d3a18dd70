// RISC-V entry of the STRaTA "streams_compact" kernel: stream memory and treelets, with the box and
// triangle tests in general-purpose instructions; each ray carries its path's state in a 64-byte
// entry (design.path_state = compact).
#include "firmware/kernels/streams_entry.h"

using namespace strata::kernels;

extern "C" {
__attribute__((used, section(".data"))) BootBlock strata_boot = {0, 0, 0, 0, 0, 0, 0, 0};
}

int main() { return streams_entry<CompactPaths, GeneralPurposeTests>(strata_boot); }
