// RISC-V entry of the TRaX baseline kernel (baseline_kernel.h). Every thread runs main; the
// pixels are shared out through the global-register atomic increment.
#include "firmware/kernels/baseline_kernel.h"
#include "firmware/kernels/riscv_machine.h"

using namespace strata;
using namespace strata::kernels;

// In .data, not .bss: crt0 clears .bss after the platform has filled this in.
extern "C" {
__attribute__((used, section(".data"))) BootBlock strata_boot = {0, 0, 0, 0, 0, 0, 0, 0};
}

int main() {
  const BootBlock boot = strata_boot;
  const KernelContext ctx = kernel_context(boot, strata_thread_id());
  RiscvMachine machine;
  baseline_kernel(machine, ctx);
  return 0;
}
