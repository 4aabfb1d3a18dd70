#include "sim/frame_setup.h"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>

#include "model/chip/design.h"
#include "sim/iss_render.h"

namespace strata::sim {

scenes::SceneImageParams scene_image_params_for(const chip::ChipConfig& config, scenes::SceneImageParams params) {
  params.treelet_bytes = config.l1d.size_bytes;
  return params;
}

PreparedFrame prepare_frame(chip::ChipConfig config, const scenes::SceneImage& image, const RenderSettings& settings,
                            const std::string& kernel_elf) {
  check_render_settings(settings);
  if (image.header().treelet_bytes != config.l1d.size_bytes)
    throw std::runtime_error("scene image: built with " + std::to_string(image.header().treelet_bytes) +
                             "-byte treelets, but memory.l1d.size_bytes is " + std::to_string(config.l1d.size_bytes) +
                             " (a treelet is one L1 data cache; build the image with scene_image_params_for)");
  config.stream.treelets = image.header().treelet_count;
  config.finalize();
  PreparedFrame f;
  f.kernel = kernel_elf.empty() ? chip::kernel_of(config.design) : "";
  f.inputs.kernel_elf = kernel_elf.empty() ? default_kernel_elf(f.kernel) : kernel_elf;
  if (!std::filesystem::exists(f.inputs.kernel_elf))
    throw std::runtime_error(f.inputs.kernel_elf + ": kernel firmware not found (built by the RISC-V toolchain" +
                             (f.kernel.empty() ? std::string(")") : "; the " + f.kernel + " kernel may not exist yet)"));
  f.inputs.scene_image = image.bytes();
  f.inputs.scene_image_bytes = image.size_bytes();
  f.inputs.treelet_bytes = image.header().treelet_bytes;
  f.inputs.frame = make_frame_params(image.header(), settings);
  f.config = std::move(config);
  return f;
}

}  // namespace strata::sim
