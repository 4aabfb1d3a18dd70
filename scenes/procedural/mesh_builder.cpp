#include "scenes/procedural/mesh_builder.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <array>
#include <cassert>
#include <cmath>

namespace strata::scenes::procedural {

namespace {

void add_oriented(std::vector<Triangle>& out, const glm::vec3& a, const glm::vec3& b,
                  const glm::vec3& c, const glm::vec3& facing, uint32_t material) {
  if (glm::dot(glm::cross(b - a, c - a), facing) >= 0.0f) {
    out.push_back({a, b, c, material});
  } else {
    out.push_back({a, c, b, material});
  }
}

}  // namespace

void add_grid_quad(std::vector<Triangle>& out, const glm::vec3& a, const glm::vec3& b,
                   const glm::vec3& c, const glm::vec3& d, int n, const glm::vec3& facing,
                   uint32_t material) {
  assert(n >= 1);
  const float inv = 1.0f / static_cast<float>(n);
  // Bilinear, so it also works for parallelograms and the blocks' rotated faces.
  auto at = [&](int i, int j) {
    const float u = static_cast<float>(i) * inv;
    const float v = static_cast<float>(j) * inv;
    const glm::vec3 ab = a + (b - a) * u;
    const glm::vec3 dc = d + (c - d) * u;
    return ab + (dc - ab) * v;
  };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const glm::vec3 p00 = at(i, j), p10 = at(i + 1, j), p11 = at(i + 1, j + 1),
                      p01 = at(i, j + 1);
      add_oriented(out, p00, p10, p11, facing, material);
      add_oriented(out, p00, p11, p01, facing, material);
    }
  }
}

glm::vec3 any_perpendicular(const glm::vec3& v) {
  // Cross with the axis least aligned with v, so the result is never tiny.
  const glm::vec3 a = glm::abs(v);
  const glm::vec3 axis = (a.x <= a.y && a.x <= a.z) ? glm::vec3(1, 0, 0)
                         : (a.y <= a.z)             ? glm::vec3(0, 1, 0)
                                                    : glm::vec3(0, 0, 1);
  return glm::normalize(glm::cross(v, axis));
}

void add_tube(std::vector<Triangle>& out, const glm::vec3* centers, std::size_t rings,
              int sides, float r_first, float r_last, uint32_t material) {
  assert(rings >= 2 && sides >= 3 && sides <= kMaxTubeSides);
  std::array<float, kMaxTubeSides> cs{}, sn{};
  for (int k = 0; k < sides; ++k) {
    const double angle = 2.0 * 3.14159265358979323846 * k / sides;
    cs[k] = static_cast<float>(std::cos(angle));
    sn[k] = static_cast<float>(std::sin(angle));
  }
  auto tangent = [&](std::size_t i) {
    const glm::vec3 prev = centers[i == 0 ? 0 : i - 1];
    const glm::vec3 next = centers[i + 1 == rings ? i : i + 1];
    glm::vec3 t = next - prev;
    // A strand that doubles back has next == prev; fall back to the incoming segment.
    if (glm::dot(t, t) < 1e-20f) t = centers[i] - prev;
    if (glm::dot(t, t) < 1e-20f) t = next - centers[i];
    return glm::normalize(t);
  };

  std::array<glm::vec3, kMaxTubeSides> prev_ring{}, ring{};
  glm::vec3 u{0.0f};
  const float r_step = rings > 1 ? (r_last - r_first) / static_cast<float>(rings - 1) : 0.0f;
  for (std::size_t i = 0; i < rings; ++i) {
    const glm::vec3 t = tangent(i);
    // Parallel transport: keep the previous ring's "u" as far as the new tangent allows.
    glm::vec3 w = i == 0 ? glm::vec3(0.0f) : u - t * glm::dot(u, t);
    u = glm::dot(w, w) < 1e-12f ? any_perpendicular(t) : glm::normalize(w);
    const glm::vec3 v = glm::cross(t, u);
    const float r = r_first + r_step * static_cast<float>(i);
    for (int k = 0; k < sides; ++k) ring[k] = centers[i] + (u * cs[k] + v * sn[k]) * r;
    if (i > 0) {
      // Winding (b - a) x (d - a) ~ u: outward normals.
      for (int k = 0; k < sides; ++k) {
        const int k1 = k + 1 == sides ? 0 : k + 1;
        const glm::vec3 &a = prev_ring[k], &b = prev_ring[k1], &c = ring[k1], &d = ring[k];
        out.push_back({a, b, d, material});
        out.push_back({b, c, d, material});
      }
    }
    prev_ring = ring;
  }
}

}  // namespace strata::scenes::procedural
