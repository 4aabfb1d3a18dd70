#include "scenes/scene.h"

#include <glm/common.hpp>

namespace strata::scenes {

void Bounds::extend(const glm::vec3& p) {
  min = glm::min(min, p);
  max = glm::max(max, p);
}

void Bounds::extend(const Bounds& b) {
  min = glm::min(min, b.min);
  max = glm::max(max, b.max);
}

float Bounds::surface_area() const {
  if (empty()) return 0.0f;
  const glm::vec3 e = extent();
  return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
}

Bounds Scene::bounds() const {
  Bounds b;
  for (const Triangle& t : triangles) {
    b.extend(t.v0);
    b.extend(t.v1);
    b.extend(t.v2);
  }
  return b;
}

}  // namespace strata::scenes
