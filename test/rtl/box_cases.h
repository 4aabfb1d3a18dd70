// Box test operations for the RTL tests: random boxes and rays over many scales and the hard
// cases of docs/numerics.md (shared by box_pipeline_test.cpp and transactor_test.cpp).
#pragma once

#include <algorithm>
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


struct BoxOp {
  float bmin[3], bmax[3];
  BoxRay ray;
};

inline constexpr float kBoxInf = std::numeric_limits<float>::infinity();
inline constexpr float kBoxNaN = std::numeric_limits<float>::quiet_NaN();

// Random boxes and rays over many scales, and the hard cases of docs/numerics.md: zero
// direction components (inverse +-inf), origins exactly on a slab plane (0 * inf = NaN),
// flat boxes, empty boxes, tiny (subnormal) and huge scales, signed zeros, infinite and NaN
// t bounds, invalid rays, and raw bit patterns.
inline std::vector<BoxOp> box_cases(uint64_t random_count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto unit = [&] { return std::uniform_real_distribution<float>(-1.0f, 1.0f)(rng); };
  auto pick = [&](std::initializer_list<float> v) { return *(v.begin() + rng() % v.size()); };
  auto raw = [&] { return bits_float(static_cast<uint32_t>(rng())); };
  std::vector<BoxOp> out;
  for (uint64_t n = 0; n < random_count; ++n) {
    BoxOp op{};
    const float scale = std::ldexp(1.0f, static_cast<int>(rng() % 80) - 40);
    const unsigned kind = static_cast<unsigned>(rng() % 10);
    for (int i = 0; i < 3; ++i) {
      float lo = unit() * scale, hi = unit() * scale;
      if (lo > hi) std::swap(lo, hi);
      op.bmin[i] = lo;
      op.bmax[i] = hi;
    }
    Vec3f o{unit() * 2 * scale, unit() * 2 * scale, unit() * 2 * scale};
    Vec3f d{unit(), unit(), unit()};
    float* oc[3] = {&o.x, &o.y, &o.z};
    float* dc[3] = {&d.x, &d.y, &d.z};
    if (rng() % 2) {  // aimed at a point of the box (mostly hits), not normalised
      for (int i = 0; i < 3; ++i) {
        const float f = std::uniform_real_distribution<float>(0.0f, 1.0f)(rng);
        *dc[i] = (op.bmin[i] + f * (op.bmax[i] - op.bmin[i])) - *oc[i];
      }
    }
    switch (kind) {
      case 0:  // axis-parallel: one or two zero direction components, either sign
        *dc[rng() % 3] = pick({0.0f, -0.0f});
        if (rng() % 2) *dc[rng() % 3] = pick({0.0f, -0.0f});
        break;
      case 1: {  // origin on a slab plane with a zero direction component: NaN distances
        const int axis = static_cast<int>(rng() % 3);
        *dc[axis] = pick({0.0f, -0.0f});
        *oc[axis] = (rng() % 2) ? op.bmin[axis] : op.bmax[axis];
        break;
      }
      case 2: {  // flat box, origin in its plane or not
        const int axis = static_cast<int>(rng() % 3);
        op.bmax[axis] = op.bmin[axis];
        if (rng() % 2) *oc[axis] = op.bmin[axis];
        if (rng() % 2) *dc[axis] = pick({0.0f, -0.0f});
        break;
      }
      case 3:  // origin on a face or corner
        for (int i = 0; i < 3; ++i)
          if (rng() % 2) *oc[i] = (rng() % 2) ? op.bmin[i] : op.bmax[i];
        break;
      case 4:  // tiny and huge scales
        for (int i = 0; i < 3; ++i) {
          const float s = pick({1e-38f, 1e-42f, 1e30f, 3e38f, 1e-20f});
          op.bmin[i] *= s / scale;
          op.bmax[i] *= s / scale;
          *oc[i] *= s / scale;
        }
        break;
      case 5:  // raw bit patterns everywhere
        for (int i = 0; i < 3; ++i) {
          op.bmin[i] = raw();
          op.bmax[i] = raw();
          *oc[i] = raw();
          *dc[i] = raw();
        }
        break;
      case 6:  // non-finite ray components
        if (rng() % 2) *oc[rng() % 3] = pick({kBoxInf, -kBoxInf, kBoxNaN});
        else *dc[rng() % 3] = pick({kBoxInf, -kBoxInf, kBoxNaN});
        break;
      case 7:  // empty box (min > max on an axis)
        {
          const int axis = static_cast<int>(rng() % 3);
          std::swap(op.bmin[axis], op.bmax[axis]);
        }
        break;
      default:
        break;
    }
    op.ray.origin = o;
    op.ray.inv_dir = inverse_direction(d);
    op.ray.tmin = pick({0.0f, -0.0f, 0.0f, unit() * scale, 1e-4f});
    op.ray.tmax = pick({kBoxInf, kBoxInf, unit() * 4 * scale, 0.0f, 1e30f});
    if (rng() % 50 == 0) op.ray.tmin = kBoxNaN;
    if (rng() % 50 == 0) op.ray.tmax = kBoxNaN;
    out.push_back(op);
  }
  // The unit box against every combination of special direction components and origins on
  // its planes, with tmin/tmax specials.
  const float dirs[] = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, kBoxInf, kBoxNaN};
  const float origins[] = {-1.0f, 0.0f, 1.0f, 2.0f, -0.0f};
  for (float dx : dirs)
    for (float dy : dirs)
      for (float ox : origins)
        for (float oy : origins)
          for (float tmax : {kBoxInf, 0.5f}) {
            BoxOp op{};
            for (int i = 0; i < 3; ++i) {
              op.bmin[i] = -1.0f;
              op.bmax[i] = 1.0f;
            }
            op.ray = {{ox, oy, 0.25f}, inverse_direction({dx, dy, 1.0f}), 0.0f, tmax};
            out.push_back(op);
          }
  return out;
}

}  // namespace strata::rtl_test
