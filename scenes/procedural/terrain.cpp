#include "scenes/procedural/terrain.h"

#include "scenes/procedural/random.h"

#include <algorithm>
#include <cmath>

namespace strata::scenes::procedural {

namespace {
constexpr uint64_t kTerrainKey = 1ull << 60;
constexpr double kTwoPi = 2.0 * 3.14159265358979323846;
}  // namespace

Heightfield::Heightfield(int cells, float half_extent, uint64_t seed)
    : cells_(cells),
      half_extent_(half_extent),
      cell_size_(2.0f * half_extent / static_cast<float>(cells)) {
  Pcg32 rng = Pcg32::keyed(seed, kTerrainKey);
  double phase[4];
  for (double& p : phase) p = kTwoPi * rng.uniform();
  // A few long sine waves: rolling hills within about +-1.6, slopes below ~0.3.
  heights_.resize(static_cast<std::size_t>((cells + 1) * (cells + 1)));
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i) {
      const double x = coord(i), z = coord(j);
      const double h = 0.9 * std::sin(0.13 * x + phase[0]) * std::sin(0.11 * z + phase[1]) +
                       0.5 * std::sin(0.07 * x - 0.09 * z + phase[2]) +
                       0.25 * std::sin(0.31 * x + 0.23 * z + phase[3]);
      heights_[static_cast<std::size_t>(j * (cells + 1) + i)] = static_cast<float>(h);
    }
  }
}

float Heightfield::coord(int i) const {
  // The last sample lands exactly on the edge, whatever the rounding of cell_size_.
  return i == cells_ ? half_extent_ : -half_extent_ + cell_size_ * static_cast<float>(i);
}

float Heightfield::height_at(float x, float z) const {
  const float gx = (x + half_extent_) / cell_size_, gz = (z + half_extent_) / cell_size_;
  const int i = std::clamp(static_cast<int>(std::floor(gx)), 0, cells_ - 1);
  const int j = std::clamp(static_cast<int>(std::floor(gz)), 0, cells_ - 1);
  const float fx = gx - static_cast<float>(i), fz = gz - static_cast<float>(j);
  const float h00 = sample(i, j), h10 = sample(i + 1, j), h01 = sample(i, j + 1),
              h11 = sample(i + 1, j + 1);
  // Each cell is split along its (0,0)-(1,1) diagonal, as in add_triangles.
  if (fx >= fz) return h00 + fx * (h10 - h00) + fz * (h11 - h10);
  return h00 + fz * (h01 - h00) + fx * (h11 - h01);
}

void Heightfield::add_triangles(std::vector<Triangle>& out, uint32_t material) const {
  for (int j = 0; j < cells_; ++j) {
    for (int i = 0; i < cells_; ++i) {
      const float x0 = coord(i), x1 = coord(i + 1), z0 = coord(j), z1 = coord(j + 1);
      const glm::vec3 p00(x0, sample(i, j), z0), p10(x1, sample(i + 1, j), z0),
          p01(x0, sample(i, j + 1), z1), p11(x1, sample(i + 1, j + 1), z1);
      out.push_back({p00, p11, p10, material});
      out.push_back({p00, p01, p11, material});
    }
  }
}

}  // namespace strata::scenes::procedural
