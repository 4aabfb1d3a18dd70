// The Vegetation scene's ground: a square heightfield of gentle hills, y up.
#pragma once

#include "scenes/scene.h"

#include <cstdint>
#include <vector>

namespace strata::scenes::procedural {

class Heightfield {
 public:
  // cells x cells grid over x, z in [-half_extent, half_extent]; hill phases from seed.
  Heightfield(int cells, float half_extent, uint64_t seed);

  // Height of the triangulated surface (not of the smooth hills it samples), so things
  // placed on the ground sit exactly on the triangles a ray would hit.
  float height_at(float x, float z) const;

  // 2 * cells^2 triangles, facing up.
  void add_triangles(std::vector<Triangle>& out, uint32_t material) const;

 private:
  float sample(int i, int j) const { return heights_[static_cast<std::size_t>(j * (cells_ + 1) + i)]; }
  float coord(int i) const;

  int cells_;
  float half_extent_;
  float cell_size_;
  std::vector<float> heights_;  // (cells + 1)^2 samples, row-major in z
};

}  // namespace strata::scenes::procedural
