// RISC-V entry of the STRaTA "streams" kernel: stream memory and treelets, with the box and
// triangle tests in general-purpose instructions; path state in one record per path
// (design.path_state = on-chip or dram).
#include "firmware/kernels/streams_entry.h"

using namespace strata::kernels;

extern "C" {
__attribute__((used, section(".data"))) BootBlock strata_boot = {0, 0, 0, 0, 0, 0, 0, 0};
}

int main() { return streams_entry<RecordPaths, GeneralPurposeTests>(strata_boot); }
