#include "sim/image_output.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace strata::sim {

void write_exr(const std::filesystem::path& file, uint32_t width, uint32_t height,
               const std::vector<kernels::Pixel>& pixels) {
  try {
    Imf::Header header{int(width), int(height)};
    for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
    Imf::OutputFile out(file.c_str(), header);
    Imf::FrameBuffer fb;
    char* base = const_cast<char*>(reinterpret_cast<const char*>(pixels.data()));
    const size_t xs = sizeof(kernels::Pixel), ys = xs * width;
    fb.insert("R", Imf::Slice(Imf::FLOAT, base, xs, ys));
    fb.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xs, ys));
    fb.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xs, ys));
    out.setFrameBuffer(fb);
    out.writePixels(int(height));
  } catch (const std::exception& e) {
    throw std::runtime_error(file.string() + ": cannot write EXR: " + e.what());
  }
}

namespace {
uint8_t to_srgb8(float linear) {
  const float c = std::clamp(linear, 0.0f, 1.0f);
  const float s = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  return uint8_t(std::lround(s * 255.0f));
}
}  // namespace

void write_png_preview(const std::filesystem::path& file, uint32_t width, uint32_t height,
                       const std::vector<kernels::Pixel>& pixels, float exposure) {
  std::vector<uint8_t> rgb(size_t(width) * height * 3);
  for (size_t i = 0; i < size_t(width) * height; ++i)
    for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = to_srgb8(pixels[i].rgb[c] * exposure);
  if (!stbi_write_png(file.c_str(), int(width), int(height), 3, rgb.data(), int(width) * 3))
    throw std::runtime_error(file.string() + ": cannot write PNG");
}

}  // namespace strata::sim
