// Builds a small chip running the baseline kernel on a small scene, for the chip tests.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "model/chip/chip.h"
#include "scenes/procedural/procedural.h"
#include "scenes/scene_image.h"
#include "sim/iss_render.h"
#include "sim/native_render.h"

namespace strata::chip::test {

#define REQUIRE_KERNEL(name)                                                                  \
  do {                                                                                        \
    if (!std::filesystem::exists(sim::default_kernel_elf(name)))                              \
      GTEST_SKIP() << "no RISC-V toolchain: " << sim::default_kernel_elf(name) << " missing"; \
  } while (0)

inline ChipConfig small_chip(transport::TimingMode mode, uint32_t tms = 2, uint32_t tps = 8) {
  ChipConfig c;
  c.design = {"trax-baseline", false, false};
  c.tms = tms;
  c.tps_per_tm = tps;
  c.timing.mode = mode;
  c.l2.size_bytes = 1 << 20;
  c.finalize();
  return c;
}

struct SmallFrame {
  scenes::SceneImage image;
  sim::RenderSettings settings;
  FrameInputs inputs;
  SmallFrame(const scenes::Scene& scene, uint32_t size, const std::string& kernel = "baseline") {
    scenes::SceneImageParams p;
    image = scenes::build_scene_image(scene, p, nullptr);
    settings.width = settings.height = size;
    inputs.kernel_elf = sim::default_kernel_elf(kernel);
    inputs.scene_image = image.bytes();
    inputs.scene_image_bytes = image.size_bytes();
    inputs.treelet_bytes = image.header().treelet_bytes;
    inputs.frame = sim::make_frame_params(image.header(), settings);
  }
};

}  // namespace strata::chip::test
