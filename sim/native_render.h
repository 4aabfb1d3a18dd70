// The native twin: the baseline firmware kernel compiled for the host and run on one
// thread. Its image and ray statistics are the golden reference for the chip model.
#pragma once

#include <cstdint>
#include <vector>

#include "firmware/common/traverse.h"
#include "firmware/abi/frame_abi.h"
#include "scenes/scene_image.h"

namespace strata::sim {

// How a path keeps its throughput and radiance between rays (firmware/kernels/path_shading.h):
// exact floats (TRaX, and STRaTA with a path record), or packed into the ray (STRaTA's compact
// path state). The native twin of a design computes with that design's arithmetic.
enum class PathArithmetic { kExact, kPacked };

struct RenderSettings {
  uint32_t width = 512, height = 512;
  uint32_t samples_per_pixel = 1;
  uint32_t max_path_vertices = 5;
  uint32_t seed = 1;
  PathArithmetic path_arithmetic = PathArithmetic::kExact;
};

struct RenderResult {
  std::vector<kernels::Pixel> image;  // row 0 is the top
  kernels::RayCounters counters{};
  double seconds = 0;  // wall clock of the kernel alone
  uint64_t total_rays() const;
};

// Host-side precomputation of the pinhole basis (double precision, rounded once to float).
kernels::FrameParams make_frame_params(const SceneImageHeader& scene, const RenderSettings& s);

void check_render_settings(const RenderSettings& s);  // throws std::invalid_argument

// `ray_log`, if given, receives every ray in the order the kernel traces them.
RenderResult render_native(const scenes::SceneImage& image, const RenderSettings& settings,
                           std::vector<TraceRay>* ray_log = nullptr);

}  // namespace strata::sim
