// The in-memory scene every loader and generator produces: flat world-space triangles with
// a material each, plus camera, point light and background. The BVH builder consumes it.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace strata::scenes {

// Thrown for any bad input. The message always starts with the file (or scene name) at fault.
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Material {
  std::string name;
  glm::vec3 albedo{0.8f, 0.8f, 0.8f};  // Lambertian diffuse reflectance, linear RGB in [0,1]
};

struct Triangle {
  glm::vec3 v0, v1, v2;  // world space
  uint32_t material = 0;  // index into Scene::materials
};

struct Camera {
  glm::vec3 eye{0.0f, 0.0f, 5.0f};
  glm::vec3 target{0.0f, 0.0f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float vfov_degrees = 45.0f;  // full vertical field of view
};

struct PointLight {
  glm::vec3 position{0.0f, 5.0f, 0.0f};
  glm::vec3 intensity{50.0f, 50.0f, 50.0f};  // radiant intensity, W/sr per RGB channel
};

struct Bounds {
  glm::vec3 min{1e30f, 1e30f, 1e30f};
  glm::vec3 max{-1e30f, -1e30f, -1e30f};
  void extend(const glm::vec3& p);
  void extend(const Bounds& b);
  bool empty() const { return min.x > max.x; }
  glm::vec3 extent() const { return max - min; }
  glm::vec3 center() const { return (min + max) * 0.5f; }
  float surface_area() const;
};

struct Scene {
  std::string name;  // file path or procedural spec it came from
  std::vector<Triangle> triangles;
  std::vector<Material> materials;
  Camera camera;
  PointLight light;
  glm::vec3 background{0.0f, 0.0f, 0.0f};  // radiance of a ray that escapes
  std::vector<std::string> warnings;       // non-fatal problems found while loading
  uint64_t dropped_degenerate = 0;         // zero-area triangles removed (see validate.h)

  Bounds bounds() const;
};

}  // namespace strata::scenes
