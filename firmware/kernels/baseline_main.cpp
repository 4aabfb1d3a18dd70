// RISC-V entry of the TRaX baseline kernel (baseline_kernel.h). Every thread runs main; the
// pixels are shared out through the global-register atomic increment.
#include "firmware/common/strata_isa.h"
#include "firmware/kernels/baseline_kernel.h"
#include "firmware/kernels/boot_block.h"

using namespace strata;
using namespace strata::kernels;

// In .data, not .bss: crt0 clears .bss after the platform has filled this in.
extern "C" {
__attribute__((used, section(".data"))) BootBlock strata_boot = {0, 0, 0, 0};
}

namespace {

struct RiscvMachine {
  uint32_t atomic_increment(uint32_t reg) { return strata_atomic_inc(reg); }
  void ray_issued(const TraceRay&, uint32_t) {}
};

}  // namespace

int main() {
  const BootBlock boot = strata_boot;
  const uint32_t thread = strata_thread_id();
  const KernelContext ctx{SceneView(reinterpret_cast<const uint8_t*>(boot.scene_image)),
                          reinterpret_cast<const FrameParams*>(boot.frame_params),
                          reinterpret_cast<Pixel*>(boot.framebuffer),
                          reinterpret_cast<RayCounters*>(boot.counters) + thread};
  RiscvMachine machine;
  baseline_kernel(machine, ctx);
  return 0;
}
