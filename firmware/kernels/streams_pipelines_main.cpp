// RISC-V entry of the STRaTA "streams_pipelines" kernel: the streams kernel with every box test on
// the fused box pipeline and every triangle test on the fused triangle pipeline; path state in one
// record per path (design.path_state = on-chip or dram).
#include "firmware/kernels/fused_pipelines.h"
#include "firmware/kernels/streams_entry.h"

using namespace strata::kernels;

extern "C" {
__attribute__((used, section(".data"))) BootBlock strata_boot = {0, 0, 0, 0, 0, 0, 0, 0};
}

int main() { return streams_entry<RecordPaths, FusedPipelines>(strata_boot); }
