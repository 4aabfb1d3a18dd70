#include "scenes/scene_spec.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "scenes/load_gltf.h"
#include "scenes/load_obj.h"
#include "scenes/procedural/procedural.h"
#include "scenes/scene_description.h"
#include "scenes/validate.h"

namespace strata::scenes {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

ProceduralParams parse_procedural_options(const std::string& spec, const std::string& options) {
  ProceduralParams params;
  size_t pos = 0;
  while (pos < options.size()) {
    const size_t comma = std::min(options.find(',', pos), options.size());
    const std::string item = options.substr(pos, comma - pos);
    const size_t eq = item.find('=');
    if (eq == std::string::npos) throw SceneError(spec + ": expected key=value, got '" + item + "'");
    const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    try {
      size_t used = 0;
      if (key == "size") {
        params.size = std::stod(value, &used);
      } else if (key == "seed") {
        if (!value.empty() && value[0] == '-') throw std::invalid_argument("negative");
        params.seed = std::stoull(value, &used);
      } else {
        throw SceneError(spec + ": unknown option '" + key + "' (expected size or seed)");
      }
      if (used != value.size()) throw std::invalid_argument("trailing characters");
    } catch (const std::logic_error&) {
      throw SceneError(spec + ": " + key + ": '" + value + "' is not a valid number");
    }
    pos = comma + 1;
  }
  return params;
}

}  // namespace

void frame_bounds(Scene& scene, const std::string& source) {
  const Bounds b = scene.bounds();
  const glm::vec3 c = b.center();
  const float radius = std::max(0.5f * glm::length(b.extent()), 1e-6f);
  scene.camera.target = c;
  scene.camera.up = {0.0f, 1.0f, 0.0f};
  scene.camera.vfov_degrees = 45.0f;
  scene.camera.eye = c + glm::vec3(0.0f, 0.0f, radius / std::tan(glm::radians(22.5f)) * 1.1f);
  scene.light.position = c + glm::vec3(0.0f, radius * 1.5f, radius * 1.5f);
  const float power = 4.0f * radius * radius;  // about unit irradiance at the scene's scale
  scene.light.intensity = {power, power, power};
  // Finite coordinates near float's limit (1e38) put the camera or the light's power beyond it.
  // Said here, naming the file and its bounds: the scene image's own check could only say
  // "camera_eye is not finite", which points at a camera the user never gave (issue 39).
  const auto finite = [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  if (!finite(scene.camera.eye) || !finite(scene.light.position) || !finite(scene.light.intensity) ||
      !std::isfinite(radius)) {
    const auto text = [](const glm::vec3& v) {
      char s[96];
      std::snprintf(s, sizeof s, "(%g, %g, %g)", double(v.x), double(v.y), double(v.z));
      return std::string(s);
    };
    throw SceneError(source + ": scene bounds are too large for the camera: " + text(b.min) + " to " +
                     text(b.max) + " puts the camera or the light beyond float range (about 3.4e38); "
                     "scale the model down, or give a camera and light in a scene description (.json)");
  }
}

Scene load_scene(const std::string& spec, const std::filesystem::path& source_dir) {
  const size_t colon = spec.find(':');
  const std::string name = lower(spec.substr(0, colon));
  const std::string options = colon == std::string::npos ? "" : spec.substr(colon + 1);
  if (name == "cornell") return make_cornell(parse_procedural_options(spec, options));
  if (name == "hairball") return make_hairball(parse_procedural_options(spec, options));
  if (name == "vegetation") return make_vegetation(parse_procedural_options(spec, options));
  if (name == "sibenik") {
    if (!options.empty()) throw SceneError(spec + ": sibenik takes no options");
    return load_scene_description(source_dir / "scenes" / "data" / "sibenik.json");
  }

  const std::filesystem::path path(spec);
  const std::string ext = lower(path.extension().string());
  if (ext == ".json") return load_scene_description(path);
  if (ext == ".obj" || ext == ".gltf" || ext == ".glb") {
    Scene scene;
    scene.name = spec;
    if (ext == ".obj") load_obj(scene, path); else load_gltf(scene, path);
    require_triangles(scene, spec);
    frame_bounds(scene, spec);
    return scene;
  }
  if (!std::filesystem::exists(path))
    throw SceneError(spec + ": no such file, and not a procedural scene name "
                     "(cornell, hairball, vegetation, sibenik)");
  throw SceneError(spec + ": unsupported extension '" + ext +
                   "' (expected .json, .obj, .gltf or .glb)");
}

}  // namespace strata::scenes
