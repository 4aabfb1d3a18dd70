// The STRaTA intrinsics as the kernels' Machine policy, on the thread processors.
#pragma once

#include "firmware/abi/strata_isa.h"
#include "firmware/abi/boot_block.h"
#include "firmware/kernels/baseline_kernel.h"
#include "firmware/kernels/stream_ray.h"
#include "firmware/kernels/streams_compact_paths.h"

namespace strata::kernels {

struct RiscvMachine {
  uint32_t atomic_increment(uint32_t reg) { return strata_atomic_inc(reg); }
  uint32_t global_read(uint32_t reg) { return strata_global_read(reg); }
  uint32_t thread_count() { return strata_thread_count(); }
  uint32_t stream_capacity() { return strata_stream_capacity(); }
  bool stream_push(const StreamRay* r, uint32_t treelet) {
    return strata_stream_push(reinterpret_cast<const strata_stream_ray*>(r), treelet) != 0;
  }
  bool stream_pop(StreamRay* r) { return strata_stream_pop(reinterpret_cast<strata_stream_ray*>(r)) != 0; }
  bool stream_push(const CompactRay* r, uint32_t treelet) {
    return strata_stream_push64(reinterpret_cast<const strata_stream_ray64*>(r), treelet) != 0;
  }
  bool stream_pop(CompactRay* r) { return strata_stream_pop64(reinterpret_cast<strata_stream_ray64*>(r)) != 0; }
  uint32_t stream_assign() { return strata_stream_assign(); }
  void ray_issued(const TraceRay&, uint32_t) {}
};

// The kernel's inputs, from the boot block the platform filled in.
inline KernelContext kernel_context(const BootBlock& boot, uint32_t thread) {
  return {SceneView(reinterpret_cast<const uint8_t*>(boot.scene_image)),
          reinterpret_cast<const FrameParams*>(boot.frame_params),
          reinterpret_cast<Pixel*>(boot.framebuffer),
          reinterpret_cast<RayCounters*>(boot.counters) + thread};
}

}  // namespace strata::kernels
