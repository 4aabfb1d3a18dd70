// What the host (or the chip's loader) hands a render kernel, and what the kernel writes
// back, at fixed layouts: the same bytes natively and in simulated memory on RV32.
#pragma once

#include <stdint.h>

namespace strata::kernels {

// Camera rays are generated from a precomputed pinhole basis: the host computes it once
// in double precision, so the kernels need no trigonometry.
//   direction(x, y) = lower_left + du * x + dv * y, with (x, y) in pixels from the bottom left
struct FrameParams {
  uint32_t width, height;
  uint32_t samples_per_pixel;
  uint32_t max_path_vertices;  // closest-hit segments per path (5: primary + 4 bounces)
  uint32_t seed;
  uint32_t pad0[3];
  float camera_origin[3], pad1;
  float camera_lower_left[3], pad2;
  float camera_du[3], pad3;
  float camera_dv[3], pad4;
};
static_assert(sizeof(FrameParams) == 96, "FrameParams layout");

// Global registers (strata.atomic*, strata.global*) the kernels and the platform agree on.
constexpr uint32_t kPixelCounterRegister = 0;  // pixels handed out (baseline: also the pixels done)
// Streaming kernels: work items finished: pixels whose every sample is finished or, with sample
// slots, samples finished.
constexpr uint32_t kPixelsDoneRegister = 1;
constexpr uint32_t kFillSlotRegister = 2;      // streaming kernels: path slots handed out by the initial fill
// Compact streaming kernels with sample slots (BootBlock::sample_slots): the samples are the
// work, handed out in pixel-major order (pixel * spp + s), then the pixels are resolved.
constexpr uint32_t kSampleCounterRegister = 3;   // samples handed out
constexpr uint32_t kResolveCounterRegister = 4;  // pixels handed out to be summed from their slots

// The streaming kernels keep one record per path in flight in a table the platform places
// (BootBlock::path_table); the platform sizes the table from this.
constexpr uint32_t kPathRecordBytes = 96;

enum RayType : uint32_t { kPrimaryRay = 0, kBounceRay = 1, kShadowRay = 2, kRayTypes = 3 };

// Statistics a thread accumulates; each thread owns one record, so no atomics are needed.
struct RayCounters {
  uint64_t rays[kRayTypes];
  uint64_t hits[kRayTypes];  // shadow "hits" are occluded shadow rays
  uint64_t node_visits;      // BVH node reads
  uint64_t triangle_tests;
  uint64_t paths;
};
static_assert(sizeof(RayCounters) == 72, "RayCounters layout");

// One pixel of the framebuffer: linear radiance, averaged over the pixel's samples.
struct Pixel {
  float rgb[3];
};

}  // namespace strata::kernels
