// On the chip, mcycle counts a TP's cycles: a chain of dependent divides, each waiting for the
// last, takes far more cycles than instructions. Not a render kernel, but it has the boot
// block the chip fills, and writes what it read into its thread's RayCounters record:
// rays[0] = mcycle, rays[1] = minstret (low words), rays[2] = 1 when the arithmetic held.
#include "firmware/abi/boot_block.h"
#include "firmware/abi/frame_abi.h"
#include "strata_runtime.h"

using namespace strata::kernels;

extern "C" {
__attribute__((used, section(".data"))) BootBlock strata_boot = {0, 0, 0, 0, 0, 0, 0, 0};
}

int main() {
  volatile float seed = 1.0f;
  float y = seed;
  for (int i = 0; i < 64; ++i) y = y / 1.0009765625f;  // dependent: each divide waits for the last
  const uint32_t cycles = STRATA_CSR_READ(mcycle);
  const uint32_t retired = STRATA_CSR_READ(minstret);
  RayCounters* c = reinterpret_cast<RayCounters*>(strata_boot.counters);
  c->rays[0] = cycles;
  c->rays[1] = retired;
  c->rays[2] = y > 0.9f && y < 1.0f ? 1 : 0;
  return 0;
}
