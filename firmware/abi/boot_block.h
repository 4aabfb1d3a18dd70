// Where a kernel finds its inputs in guest memory. The firmware defines one BootBlock named
// `strata_boot` in .data; the platform (ISS driver or chip model) finds it by that symbol
// and fills it in before the first thread starts.
#pragma once

#include <stdint.h>

namespace strata::kernels {

struct BootBlock {
  uint32_t frame_params;  // guest address of the FrameParams
  uint32_t scene_image;   // guest address of the scene image (aligned to its treelet size)
  uint32_t framebuffer;   // width * height Pixels
  uint32_t counters;      // one RayCounters per thread, indexed by the global thread id
  uint32_t path_table;    // streaming kernels: one PathRecord per path in flight
  uint32_t path_slots;    // how many PathRecords there are
  // Compact streaming kernels at more than one sample per pixel: width * height * spp Pixels,
  // one per sample (pixel * spp + s), summed into the framebuffer in sample order once every
  // sample is done, so a pixel's samples can be in flight together. 0: none, a pixel's samples
  // run one after another.
  uint32_t sample_slots;
  uint32_t pad;
};

constexpr const char* kBootBlockSymbol = "strata_boot";

}  // namespace strata::kernels
