// Shared helpers for the BVH, treelet and scene-image tests.
#pragma once

#include <cmath>
#include <vector>

#include "scenes/scene.h"

namespace strata::scenes::testing {

// Triangles in the z = 0 plane at x = 2^-i and size 2^-i / 4: disjoint, and so unbalanced
// that a plain SAH build peels off one triangle per level.
inline Scene geometric_series_scene(int count) {
  Scene s;
  s.name = "geometric-series";
  s.materials.push_back({"grey", {0.5f, 0.5f, 0.5f}});
  for (int i = 0; i < count; ++i) {
    const float x = std::ldexp(1.0f, -i);
    const float h = 0.25f * x;
    s.triangles.push_back({{x - h, -h, 0.0f}, {x + h, -h, 0.0f}, {x, h, 0.0f}, 0});
  }
  return s;
}

}  // namespace strata::scenes::testing
