// RISC-V entry of the STRaTA "streams" kernel: stream memory and treelets, with the box and
// triangle tests in general-purpose instructions.
#include "firmware/kernels/riscv_machine.h"
#include "firmware/kernels/streams_kernel.h"

using namespace strata::kernels;

extern "C" {
__attribute__((used, section(".data"))) BootBlock strata_boot = {0, 0, 0, 0, 0, 0, {0, 0}};
}

int main() {
  const BootBlock boot = strata_boot;
  RiscvMachine machine;
  GeneralPurposeTests tests;
  streams_kernel(machine, tests, streams_context(boot, strata_thread_id()));
  return 0;
}
