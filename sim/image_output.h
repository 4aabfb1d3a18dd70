// Writes rendered images: linear float OpenEXR, and an sRGB PNG preview.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "firmware/abi/frame_abi.h"

namespace strata::sim {

void write_exr(const std::filesystem::path& file, uint32_t width, uint32_t height,
               const std::vector<kernels::Pixel>& pixels);

// Clamps to [0, 1] after `exposure` and applies the sRGB transfer curve.
void write_png_preview(const std::filesystem::path& file, uint32_t width, uint32_t height,
                       const std::vector<kernels::Pixel>& pixels, float exposure = 1.0f);

}  // namespace strata::sim
