// Helpers for the loader tests: a self-deleting temporary directory, file writers, and a
// tiny glTF writer that emits the same content as .gltf (base64 data URI) or .glb, so no
// binary fixtures need to live in the repository.
#pragma once

#include "scenes/scene.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <random>
#include <string>
#include <vector>

namespace strata::scenes::fixtures {

namespace fs = std::filesystem;

// A fresh directory per test (tests may run in parallel processes), removed afterwards.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::random_device rd;
    const std::string name = std::string("strata-") + (info ? info->name() : "test") + "-" +
                             std::to_string(rd()) + std::to_string(rd());
    path_ = fs::temp_directory_path() / name;
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

inline fs::path write_text(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  return file;
}

inline fs::path write_bytes(const fs::path& file, const std::vector<uint8_t>& bytes) {
  std::ofstream out(file, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
  return file;
}

inline std::string base64(const std::vector<uint8_t>& in) {
  static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < in.size(); i += 3) {
    uint32_t n = uint32_t{in[i]} << 16;
    if (i + 1 < in.size()) n |= uint32_t{in[i + 1]} << 8;
    if (i + 2 < in.size()) n |= in[i + 2];
    out += abc[(n >> 18) & 63];
    out += abc[(n >> 12) & 63];
    out += i + 1 < in.size() ? abc[(n >> 6) & 63] : '=';
    out += i + 2 < in.size() ? abc[n & 63] : '=';
  }
  return out;
}

inline ::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

inline bool any_warning_contains(const Scene& s, const std::string& part) {
  for (const std::string& w : s.warnings) {
    if (w.find(part) != std::string::npos) return true;
  }
  return false;
}

// Runs `f`, expecting a SceneError whose message contains every string in `parts`.
template <class F>
void expect_scene_error(F f, std::initializer_list<std::string> parts) {
  try {
    f();
    ADD_FAILURE() << "expected SceneError";
  } catch (const SceneError& e) {
    for (const std::string& p : parts) EXPECT_TRUE(contains(e.what(), p));
  }
}

// Triangles as sorted 9-float tuples: comparisons that do not depend on loader order.
using Coords = std::array<float, 9>;
inline std::vector<Coords> sorted_coords(const std::vector<Triangle>& tris) {
  std::vector<Coords> out;
  for (const Triangle& t : tris) {
    out.push_back({t.v0.x, t.v0.y, t.v0.z, t.v1.x, t.v1.y, t.v1.z, t.v2.x, t.v2.y, t.v2.z});
  }
  std::sort(out.begin(), out.end());
  return out;
}
inline Coords coords(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  return {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z};
}

// Builds a glTF document whose binary data lives in one buffer. The caller fills
// doc["nodes"], doc["meshes"], doc["scenes"], doc["materials"] directly.
class GltfBuilder {
 public:
  GltfBuilder() { doc = {{"asset", {{"version", "2.0"}}}}; }

  int add_positions(const std::vector<glm::vec3>& ps) {
    const size_t offset = append(ps.data(), ps.size() * sizeof(glm::vec3));
    glm::vec3 lo = ps.at(0), hi = ps.at(0);
    for (const auto& p : ps) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    const int view = add_view(offset, ps.size() * sizeof(glm::vec3), 34962);
    return add_accessor({{"bufferView", view},
                         {"componentType", 5126},
                         {"count", ps.size()},
                         {"type", "VEC3"},
                         {"min", {lo.x, lo.y, lo.z}},
                         {"max", {hi.x, hi.y, hi.z}}});
  }

  // component_type 5121 (u8), 5123 (u16) or 5125 (u32).
  int add_indices(const std::vector<uint32_t>& idx, int component_type = 5123) {
    std::vector<uint8_t> bytes;
    for (uint32_t i : idx) {
      const size_t size = component_type == 5121 ? 1 : component_type == 5123 ? 2 : 4;
      for (size_t b = 0; b < size; ++b) bytes.push_back(static_cast<uint8_t>(i >> (8 * b)));
    }
    const size_t offset = append(bytes.data(), bytes.size());
    const int view = add_view(offset, bytes.size(), 34963);
    return add_accessor({{"bufferView", view},
                         {"componentType", component_type},
                         {"count", idx.size()},
                         {"type", "SCALAR"}});
  }

  int add_view(size_t offset, size_t length, int target) {
    doc["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}, {"target", target}});
    return static_cast<int>(doc["bufferViews"].size()) - 1;
  }

  int add_accessor(const nlohmann::json& a) {
    doc["accessors"].push_back(a);
    return static_cast<int>(doc["accessors"].size()) - 1;
  }

  // Appends raw bytes, 4-byte aligned as glTF requires, and returns their offset.
  size_t append(const void* data, size_t size) {
    while (bin.size() % 4 != 0) bin.push_back(0);
    const size_t offset = bin.size();
    bin.resize(offset + size);
    if (size > 0) std::memcpy(bin.data() + offset, data, size);
    return offset;
  }

  std::string gltf() const {
    nlohmann::json d = doc;
    d["buffers"] = {{{"byteLength", bin.size()},
                     {"uri", "data:application/octet-stream;base64," + base64(bin)}}};
    return d.dump(1);
  }

  // GLB container: 12-byte header, JSON chunk padded with spaces, BIN chunk padded with 0.
  std::vector<uint8_t> glb() const {
    nlohmann::json d = doc;
    d["buffers"] = {{{"byteLength", bin.size()}}};
    std::string json = d.dump();
    while (json.size() % 4 != 0) json += ' ';
    std::vector<uint8_t> body = bin;
    while (body.size() % 4 != 0) body.push_back(0);
    std::vector<uint8_t> out;
    auto u32 = [&out](uint32_t v) {
      for (int b = 0; b < 4; ++b) out.push_back(static_cast<uint8_t>(v >> (8 * b)));
    };
    u32(0x46546C67);  // "glTF"
    u32(2);
    u32(static_cast<uint32_t>(12 + 8 + json.size() + 8 + body.size()));
    u32(static_cast<uint32_t>(json.size()));
    u32(0x4E4F534A);  // "JSON"
    out.insert(out.end(), json.begin(), json.end());
    u32(static_cast<uint32_t>(body.size()));
    u32(0x004E4942);  // "BIN\0"
    out.insert(out.end(), body.begin(), body.end());
    return out;
  }

  nlohmann::json doc;
  std::vector<uint8_t> bin;
};

}  // namespace strata::scenes::fixtures
