#include "sim/image_output.h"

#include "sim/output_file.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfOutputFile.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace strata::sim {

namespace {

// OpenEXR writes through this into memory, so that the file is written, checked and renamed
// into place in one step (output_file.h) rather than by the library's unchecked stream.
class MemoryStream : public Imf::OStream {
 public:
  MemoryStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    const std::size_t end = pos_ + static_cast<std::size_t>(n);
    if (end > bytes_.size()) bytes_.resize(end);
    std::memcpy(bytes_.data() + pos_, c, static_cast<std::size_t>(n));
    pos_ = end;
  }
  uint64_t tellp() override { return pos_; }
  void seekp(uint64_t pos) override { pos_ = static_cast<std::size_t>(pos); }
  const std::vector<uint8_t>& bytes() const { return bytes_; }

 private:
  std::vector<uint8_t> bytes_;
  std::size_t pos_ = 0;
};

void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<uint8_t>*>(context);
  const auto* p = static_cast<const uint8_t*>(data);
  out->insert(out->end(), p, p + size);
}

}  // namespace

void write_exr(const std::filesystem::path& file, uint32_t width, uint32_t height,
               const std::vector<kernels::Pixel>& pixels) {
  MemoryStream stream;
  try {
    Imf::Header header{int(width), int(height)};
    for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
    Imf::OutputFile out(stream, header);
    Imf::FrameBuffer fb;
    char* base = const_cast<char*>(reinterpret_cast<const char*>(pixels.data()));
    const size_t xs = sizeof(kernels::Pixel), ys = xs * width;
    fb.insert("R", Imf::Slice(Imf::FLOAT, base, xs, ys));
    fb.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xs, ys));
    fb.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xs, ys));
    out.setFrameBuffer(fb);
    out.writePixels(int(height));
  } catch (const std::exception& e) {
    throw std::runtime_error(file.string() + ": cannot encode EXR: " + e.what());
  }
  // The OutputFile has written its line-offset table on destruction, above.
  write_file_atomically(file, stream.bytes(), "EXR");
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
  std::vector<uint8_t> png;
  if (!stbi_write_png_to_func(append_bytes, &png, int(width), int(height), 3, rgb.data(), int(width) * 3))
    throw std::runtime_error(file.string() + ": cannot encode PNG");
  write_file_atomically(file, png, "PNG");
}

}  // namespace strata::sim
