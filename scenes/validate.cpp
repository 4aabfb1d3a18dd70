#include "scenes/validate.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <sstream>

namespace strata::scenes {

namespace {

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string describe(const Triangle& t) {
  std::ostringstream s;
  auto put = [&s](const char* label, const glm::vec3& v) {
    s << label << " = (" << v.x << ", " << v.y << ", " << v.z << ")";
  };
  put("v0", t.v0);
  s << ", ";
  put("v1", t.v1);
  s << ", ";
  put("v2", t.v2);
  return s.str();
}

}  // namespace

void validate_triangles(Scene& scene, size_t first, const std::string& source) {
  std::vector<Triangle>& tris = scene.triangles;
  if (first > tris.size()) first = tris.size();

  // Non-finite input is an error, not something to drop: silently losing geometry would
  // make a broken export look like a working one.
  for (size_t i = first; i < tris.size(); ++i) {
    const Triangle& t = tris[i];
    if (!finite(t.v0) || !finite(t.v1) || !finite(t.v2)) {
      throw SceneError(source + ": triangle " + std::to_string(i - first) +
                       " has a non-finite coordinate (" + describe(t) + ")");
    }
  }

  // Stable in-place compaction of the zero-area triangles.
  size_t out = first;
  for (size_t i = first; i < tris.size(); ++i) {
    const Triangle& t = tris[i];
    const glm::vec3 n = glm::cross(t.v1 - t.v0, t.v2 - t.v0);
    if (n.x == 0.0f && n.y == 0.0f && n.z == 0.0f) continue;
    if (out != i) tris[out] = t;
    ++out;
  }
  const size_t dropped = tris.size() - out;
  tris.resize(out);
  if (dropped > 0) {
    scene.dropped_degenerate += dropped;
    scene.warnings.push_back(source + ": dropped " + std::to_string(dropped) +
                             " zero-area triangle(s)");
  }
}

void append_validated(Scene& scene, Scene&& part, const std::string& source) {
  validate_triangles(part, 0, source);
  const auto base = static_cast<uint32_t>(scene.materials.size());
  scene.triangles.reserve(scene.triangles.size() + part.triangles.size());
  for (Triangle t : part.triangles) {
    t.material += base;
    scene.triangles.push_back(t);
  }
  scene.materials.insert(scene.materials.end(), part.materials.begin(), part.materials.end());
  scene.warnings.insert(scene.warnings.end(), part.warnings.begin(), part.warnings.end());
  scene.dropped_degenerate += part.dropped_degenerate;
}

void require_triangles(const Scene& scene, const std::string& source) {
  if (scene.triangles.empty()) {
    // The warnings say why (zero-area faces dropped, point or line primitives skipped), and
    // an error ends the program before they would be printed: so they go in its message.
    std::string why;
    for (const std::string& w : scene.warnings) why += "\n  " + w;
    throw SceneError(source + ": scene has no triangles" + (why.empty() ? "" : "; the loader said:" + why));
  }
}

void require_regular_file(const std::filesystem::path& file) {
  std::error_code ec;
  const std::filesystem::file_status st = std::filesystem::status(file, ec);  // follows symlinks
  if (!std::filesystem::exists(st)) throw SceneError(file.string() + ": file not found");
  if (!std::filesystem::is_regular_file(st))
    throw SceneError(file.string() + ": not a regular file (a folder, FIFO or device cannot be read as a scene file)");
}

}  // namespace strata::scenes
