// Triangle test operations for the RTL tests: random triangles and rays over many scales and
// the hard cases of docs/numerics.md (shared by triangle_pipeline_test.cpp and
// transactor_test.cpp).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <random>
#include <vector>

#include "firmware/common/intersect.h"
#include "firmware/common/float_bits.h"

namespace strata::rtl_test {


struct TriOp {
  Vec3f v0, v1, v2, origin, dir;
};

inline constexpr float kTriInf = std::numeric_limits<float>::infinity();
inline constexpr float kTriNaN = std::numeric_limits<float>::quiet_NaN();

// Random triangles around random rays at many scales, and the hard cases: axis-parallel rays
// (zero direction components, either sign), rays through a vertex or an edge (shared edges; on
// integer grids the edge differences vanish exactly and the exact fallback runs), grazing
// rays, tiny and huge scales, subnormal and huge direction lengths, degenerate triangles,
// non-finite input and raw bit patterns.
inline std::vector<TriOp> triangle_cases(uint64_t count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto unit = [&] { return std::uniform_real_distribution<float>(-1.0f, 1.0f)(rng); };
  auto grid = [&] { return static_cast<float>(static_cast<int>(rng() % 9) - 4); };
  auto pick = [&](std::initializer_list<float> v) { return *(v.begin() + rng() % v.size()); };
  auto raw = [&] { return bits_float(static_cast<uint32_t>(rng())); };
  auto lerp = [](Vec3f a, Vec3f b, float t) { return a + (b - a) * t; };
  std::vector<TriOp> out;
  for (uint64_t n = 0; n < count; ++n) {
    TriOp op{};
    const float s = std::ldexp(1.0f, static_cast<int>(rng() % 60) - 30);
    const Vec3f shift{unit() * s * 4, unit() * s * 4, unit() * s * 4};
    op.v0 = Vec3f{unit() * s, unit() * s, unit() * s} + shift;
    op.v1 = Vec3f{unit() * s, unit() * s, unit() * s} + shift;
    op.v2 = Vec3f{unit() * s, unit() * s, unit() * s} + shift;
    op.origin = Vec3f{unit() * s * 8, unit() * s * 8, unit() * s * 8} + shift;
    // Aimed at a random point of the triangle's neighbourhood (about half hit).
    const float w1 = std::uniform_real_distribution<float>(-0.2f, 0.8f)(rng);
    const float w2 = std::uniform_real_distribution<float>(-0.2f, 1.0f - w1)(rng);
    Vec3f target = op.v0 + (op.v1 - op.v0) * w1 + (op.v2 - op.v0) * w2;
    switch (rng() % 12) {
      case 0:  // through a vertex
        target = pick({0.f, 1.f, 2.f}) == 0.f ? op.v0 : (rng() % 2 ? op.v1 : op.v2);
        break;
      case 1:  // through a point of an edge, computed in float (p - q close to 0)
        target = lerp(op.v0, op.v1, std::uniform_real_distribution<float>(0.0f, 1.0f)(rng));
        break;
      case 2: {  // integer grid: edge differences vanish exactly, the exact fallback runs
        op.v0 = {grid(), grid(), grid()};
        op.v1 = {grid(), grid(), grid()};
        op.v2 = {grid(), grid(), grid()};
        op.origin = {grid(), grid(), grid()};
        target = (rng() % 2) ? lerp(op.v1, op.v2, 0.5f) : op.v0;
        break;
      }
      case 3:  // tiny and huge scales
        {
          const float k = pick({1e-12f, 1e12f, 1e-30f, 1e30f, 1e-40f});
          op.v0 = op.v0 * (k / s);
          op.v1 = op.v1 * (k / s);
          op.v2 = op.v2 * (k / s);
          op.origin = op.origin * (k / s);
          target = target * (k / s);
        }
        break;
      case 4:  // degenerate: duplicate or collinear vertices
        if (rng() % 2) op.v2 = op.v1;
        else op.v2 = lerp(op.v0, op.v1, 2.0f);
        break;
      case 5:  // raw bit patterns
        op.v0 = {raw(), raw(), raw()};
        op.v1 = {raw(), raw(), raw()};
        op.v2 = {raw(), raw(), raw()};
        op.origin = {raw(), raw(), raw()};
        target = {raw(), raw(), raw()};
        break;
      case 6:  // non-finite input somewhere
        {
          float* c[] = {&op.v0.x, &op.v1.y, &op.v2.z, &op.origin.x, &op.origin.z};
          *c[rng() % 5] = pick({kTriInf, -kTriInf, kTriNaN});
        }
        break;
      default:
        break;
    }
    op.dir = target - op.origin;
    switch (rng() % 8) {
      case 0:  // axis-parallel: zero components of either sign
        (rng() % 2 ? op.dir.x : op.dir.y) = pick({0.0f, -0.0f});
        if (rng() % 2) op.dir.z = pick({0.0f, -0.0f});
        break;
      case 1:  // direction length extremes (direction_scale's clamps), and a zero direction
        op.dir = op.dir * pick({1e-40f, 1e-30f, 1e30f, 3e38f / (std::fabs(op.dir.x) + 1.0f), 0.0f});
        break;
      case 2:  // grazing: direction nearly in the triangle's plane
        op.dir = (op.v1 - op.v0) + (op.dir * 1e-5f);
        break;
      case 3:  // non-finite direction
        op.dir.y = pick({kTriInf, kTriNaN});
        break;
      case 4:  // ties between |dir| components (kz choice)
        op.dir = {pick({1.0f, -1.0f}), pick({1.0f, -1.0f}), pick({1.0f, -1.0f, 0.5f})};
        op.origin = target - op.dir * 3.0f;
        break;
      default:
        break;
    }
    out.push_back(op);
  }
  return out;
}

}  // namespace strata::rtl_test
