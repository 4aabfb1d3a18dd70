// One frame's set-up, the same for `strata-sim run`, the statistics reference and the chip
// tests: the config completed from the scene image (the stream memory keeps one buffer head per
// treelet), the design's kernel (model/chip/design.h), and the inputs the chip loads.
#pragma once

#include <string>

#include "model/chip/chip.h"
#include "model/chip/chip_config.h"
#include "scenes/scene_image.h"
#include "sim/native_render.h"

namespace strata::sim {

struct PreparedFrame {
  chip::ChipConfig config;   // finalized for this scene
  chip::FrameInputs inputs;  // points into the scene image: keep it alive while the chip runs
  std::string kernel;        // the kernel's name, e.g. "streams_compact" (empty: one given by path)
};

// The image parameters a config needs: treelets of exactly one L1 data cache (ARCHITECTURE.md,
// "Treelets"), the rest as given.
scenes::SceneImageParams scene_image_params_for(const chip::ChipConfig& config, scenes::SceneImageParams params = {});

// `kernel_elf` empty: the design's kernel as built here. Throws chip::ConfigError for a config
// the scene does not fit, and std::runtime_error naming a missing kernel or an image built for
// another L1 size.
PreparedFrame prepare_frame(chip::ChipConfig config, const scenes::SceneImage& image, const RenderSettings& settings,
                            const std::string& kernel_elf = "");

}  // namespace strata::sim
