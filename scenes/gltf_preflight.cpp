#include "scenes/gltf_preflight.h"

#include "scenes/scene.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

namespace strata::scenes {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

uint32_t u32(const std::vector<char>& b, size_t at) {
  uint32_t v = 0;
  std::memcpy(&v, b.data() + at, 4);
  return v;  // GLB is little-endian, as is every host we build for
}

// The JSON text of a GLB (its first chunk), or "" if the header is not one we can read (then
// tinygltf gives its own error).
std::string glb_json(const std::vector<char>& b, const std::string& source) {
  if (b.size() < 20 || std::memcmp(b.data(), "glTF", 4) != 0) return "";
  const uint32_t version = u32(b, 4);
  if (version == 1) throw SceneError(source + ": binary glTF 1.0 is not supported; convert the file to glTF 2.0");
  const uint32_t length = u32(b, 12), type = u32(b, 16);
  if (type != 0x4E4F534Au || 20 + uint64_t{length} > b.size()) return "";
  return std::string(b.data() + 20, length);
}

void check(const json& j, const fs::path& file, const std::string& source) {
  if (!j.is_object()) return;
  const auto asset = j.find("asset");
  if (asset == j.end() || !asset->is_object()) {
    if (j.contains("scenes") && j["scenes"].is_object())  // 1.0 keeps scenes and meshes in objects
      throw SceneError(source + ": a glTF 1.0 file (no \"asset\" object, objects where 2.0 has arrays); "
                       "convert it to glTF 2.0");
    return;
  }
  const auto version = asset->find("version");
  if (version != asset->end() && version->is_string()) {
    const std::string v = version->get<std::string>();
    if (v.rfind("1.", 0) == 0 || v == "1")
      throw SceneError(source + ": glTF " + v + " is not supported; convert the file to glTF 2.0");
  }
  if (const auto req = j.find("extensionsRequired"); req != j.end() && req->is_array())
    for (const json& e : *req)
      if (e.is_string()) {
        const std::string ext = e.get<std::string>();
        if (ext == "KHR_draco_mesh_compression" || ext == "EXT_meshopt_compression" || ext == "KHR_mesh_quantization")
          throw SceneError(source + ": requires unsupported extension " + ext +
                           " (compressed or quantized geometry); export it uncompressed");
      }
  if (const auto buffers = j.find("buffers"); buffers != j.end() && buffers->is_array())
    for (size_t i = 0; i < buffers->size(); ++i) {
      const json& b = (*buffers)[i];
      if (!b.is_object() || !b.contains("uri") || !b["uri"].is_string()) continue;
      const std::string uri = b["uri"].get<std::string>();
      if (uri.rfind("data:", 0) == 0) continue;
      const fs::path p = file.parent_path() / uri;
      std::error_code ec;
      if (uri.empty() || !fs::is_regular_file(p, ec))
        throw SceneError(source + ": buffers[" + std::to_string(i) + "].uri '" + uri + "': " +
                         (fs::exists(p, ec) ? "not a regular file" : "no such file"));
    }
}

}  // namespace

void gltf_preflight(const fs::path& file, bool binary) {
  const std::string source = file.string();
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError(source + ": cannot open file");
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string text = binary ? glb_json(bytes, source) : std::string(bytes.begin(), bytes.end());
  const json j = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return;  // tinygltf reports the syntax error with its position
  check(j, file, source);
}

}  // namespace strata::scenes
