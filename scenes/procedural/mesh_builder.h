// Triangle-emitting building blocks shared by the procedural generators.
#pragma once

#include "scenes/scene.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace strata::scenes::procedural {

// Planar quad a-b-c-d (in order round its edge) cut into n x n cells of two triangles each,
// wound so their geometric normal points along `facing` (renderers may cull or shade by it).
void add_grid_quad(std::vector<Triangle>& out, const glm::vec3& a, const glm::vec3& b,
                   const glm::vec3& c, const glm::vec3& d, int n, const glm::vec3& facing,
                   uint32_t material);

// Open tube (no end caps) along the polyline centers[0..rings), with a regular `sides`-gon
// cross-section whose radius goes linearly from r_first to r_last. Frames are parallel
// transported so the tube does not twist. Emits (rings - 1) * sides * 2 triangles.
void add_tube(std::vector<Triangle>& out, const glm::vec3* centers, std::size_t rings,
              int sides, float r_first, float r_last, uint32_t material);

constexpr int kMaxTubeSides = 16;

// Some unit vector perpendicular to unit vector v.
glm::vec3 any_perpendicular(const glm::vec3& v);

}  // namespace strata::scenes::procedural
