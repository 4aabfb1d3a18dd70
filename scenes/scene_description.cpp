#include "scenes/scene_description.h"

#include "scenes/load_gltf.h"
#include "scenes/load_obj.h"
#include "scenes/validate.h"
#include "json_input/strict_json.h"

#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <initializer_list>

namespace strata::scenes {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Reads one JSON document, reporting every problem as "<file>: <field>: <problem>".
class DescriptionReader {
 public:
  explicit DescriptionReader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw SceneError(file_ + ": " + field + ": " + what);
  }

  void require_object(const json& j, const std::string& field) const {
    if (!j.is_object()) fail(field, "expected an object");
  }

  void check_keys(const json& object, const std::string& prefix,
                  std::initializer_list<const char*> allowed) const {
    for (const auto& item : object.items()) {
      const bool known = std::any_of(allowed.begin(), allowed.end(),
                                     [&item](const char* k) { return item.key() == k; });
      if (!known) fail(prefix + item.key(), "unknown key");
    }
  }

  float number(const json& j, const std::string& field) const {
    if (!j.is_number()) fail(field, "expected a number");
    const auto v = j.get<double>();
    // Checked after narrowing: 1e300 is a finite double but an infinite float.
    if (!std::isfinite(static_cast<float>(v))) fail(field, "expected a finite number");
    return static_cast<float>(v);
  }

  glm::vec3 vec3(const json& j, const std::string& field) const {
    if (!j.is_array() || j.size() != 3 ||
        !std::all_of(j.begin(), j.end(), [](const json& e) { return e.is_number(); })) {
      fail(field, "expected an array of 3 numbers");
    }
    return {number(j[0], field), number(j[1], field), number(j[2], field)};
  }

  glm::vec3 non_negative_rgb(const json& j, const std::string& field, bool allow_scalar) const {
    glm::vec3 v;
    if (allow_scalar && j.is_number()) {
      v = glm::vec3(number(j, field));
    } else if (allow_scalar && !j.is_array()) {
      fail(field, "expected a number or an array of 3 numbers");
    } else {
      v = vec3(j, field);
    }
    if (v.x < 0.0f || v.y < 0.0f || v.z < 0.0f) fail(field, "expected values >= 0");
    return v;
  }

  void read_camera(const json& j, Camera& cam) const {
    require_object(j, "camera");
    check_keys(j, "camera.", {"eye", "target", "up", "vfov_degrees"});
    if (j.contains("eye")) cam.eye = vec3(j["eye"], "camera.eye");
    if (j.contains("target")) cam.target = vec3(j["target"], "camera.target");
    if (j.contains("up")) cam.up = vec3(j["up"], "camera.up");
    if (j.contains("vfov_degrees")) {
      cam.vfov_degrees = number(j["vfov_degrees"], "camera.vfov_degrees");
      if (!(cam.vfov_degrees > 0.0f && cam.vfov_degrees < 180.0f)) {
        fail("camera.vfov_degrees", "expected a number in (0, 180)");
      }
    }
    // A camera basis cannot be built from these; better to say so here than to render NaN.
    const glm::vec3 dir = cam.target - cam.eye;
    if (glm::length(dir) == 0.0f) fail("camera", "eye and target coincide");
    const float sin_angle =
        glm::length(glm::cross(glm::normalize(dir), cam.up)) / glm::length(cam.up);
    if (!(sin_angle > 1e-6f)) fail("camera.up", "zero or parallel to the viewing direction");
  }

  void read_light(const json& j, PointLight& light) const {
    require_object(j, "light");
    check_keys(j, "light.", {"position", "intensity"});
    if (j.contains("position")) light.position = vec3(j["position"], "light.position");
    if (j.contains("intensity")) {
      light.intensity = non_negative_rgb(j["intensity"], "light.intensity", true);
    }
  }

  std::vector<fs::path> read_geometry(const json& j, const fs::path& dir) const {
    if (!j.is_array() || j.empty()) fail("geometry", "expected a non-empty array of file paths");
    std::vector<fs::path> files;
    for (size_t i = 0; i < j.size(); ++i) {
      if (!j[i].is_string()) fail("geometry[" + std::to_string(i) + "]", "expected a string");
      const fs::path p = j[i].get<std::string>();
      files.push_back(p.is_absolute() ? p : (dir / p).lexically_normal());
    }
    return files;
  }

 private:
  std::string file_;
};

json parse_file(const fs::path& file) {
  const std::string name = file.string();
  require_regular_file(file);
  std::ifstream in(file);
  if (!in) throw SceneError(name + ": cannot open file");
  try {  // as a config file: no duplicate key, bounded nesting, syntax errors placed
    return json_input::parse_strict(in, name);
  } catch (const json_input::JsonInputError& e) {
    throw SceneError(e.what());
  }
}

void load_geometry(Scene& scene, const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".obj") {
    load_obj(scene, file);
  } else if (ext == ".gltf" || ext == ".glb") {
    load_gltf(scene, file);
  } else {
    throw SceneError(file.string() + ": unsupported geometry extension '" +
                     file.extension().string() + "' (expected .obj, .gltf or .glb)");
  }
}

}  // namespace

Scene load_scene_description(const fs::path& json_file) {
  const std::string name = json_file.string();
  const json doc = parse_file(json_file);
  const DescriptionReader reader(name);
  reader.require_object(doc, "top level");
  reader.check_keys(doc, "", {"geometry", "camera", "light", "background"});
  if (!doc.contains("geometry")) reader.fail("geometry", "missing (required)");

  Scene scene;
  scene.name = name;
  // Read every setting before loading any geometry, so a typo fails in milliseconds.
  const std::vector<fs::path> files =
      reader.read_geometry(doc["geometry"], json_file.parent_path());
  if (doc.contains("camera")) reader.read_camera(doc["camera"], scene.camera);
  if (doc.contains("light")) reader.read_light(doc["light"], scene.light);
  if (doc.contains("background")) {
    scene.background = reader.non_negative_rgb(doc["background"], "background", false);
  }
  for (const fs::path& f : files) load_geometry(scene, f);
  require_triangles(scene, name);
  return scene;
}

}  // namespace strata::scenes
