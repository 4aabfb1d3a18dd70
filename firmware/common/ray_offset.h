// Self-intersection avoidance for secondary rays (Wächter and Binder, "A Fast and Robust
// Method for Avoiding Self-Intersection", Ray Tracing Gems, ch. 6, 2019): move a surface
// point a few ulps along the geometric normal, in integer space, so the offset scales with
// the point's own magnitude; near the world origin, where ulps get tiny, fall back to a
// fixed float offset. Freestanding: bit casts via __builtin_memcpy, no <cmath>.
// Semantics, constants and the measured self-hit rates: docs/numerics.md, "Origin offset".
#pragma once

#include <stdint.h>

#include "firmware/common/vec3.h"

namespace strata {

namespace ray_offset_detail {

constexpr float kOriginRadius = 1.0f / 32.0f;  // below this |coordinate|, offset in float
constexpr float kFloatScale = 1.0f / 65536.0f;  // float offset per unit normal component
constexpr float kIntScale = 256.0f;             // ulps per unit normal component

inline float abs_f(float x) { return x < 0.0f ? -x : x; }
inline bool finite_f(float x) { return x - x == 0.0f; }

inline float offset_coordinate(float p, float n) {
  if (abs_f(p) < kOriginRadius) return p + kFloatScale * n;
  const int32_t ulps = static_cast<int32_t>(kIntScale * n);  // |n| <= 1: |ulps| <= 256
  int32_t bits;
  __builtin_memcpy(&bits, &p, sizeof bits);
  // The bit pattern of a float grows with its magnitude, so moving a negative coordinate
  // towards +n means making its bit pattern smaller.
  bits += p < 0.0f ? -ulps : ulps;
  float out;
  __builtin_memcpy(&out, &bits, sizeof out);
  return out;
}

}  // namespace ray_offset_detail

// Returns p moved off the surface towards n. n is the geometric normal on the side the new
// ray leaves towards (flip it for rays going through the surface); any length: it is first
// scaled so its largest component has magnitude 1 (max norm, so no square root). Each
// coordinate then moves by 256 * n_i ulps of itself, or by n_i / 65536 if |p_i| < 1/32.
// A zero or non-finite n, or a non-finite p, returns p unchanged.
inline Vec3f offset_ray_origin(Vec3f p, Vec3f n) {
  using namespace ray_offset_detail;
  if (!(finite_f(p.x) && finite_f(p.y) && finite_f(p.z))) return p;
  if (!(finite_f(n.x) && finite_f(n.y) && finite_f(n.z))) return p;
  float m = abs_f(n.x);
  if (abs_f(n.y) > m) m = abs_f(n.y);
  if (abs_f(n.z) > m) m = abs_f(n.z);
  if (!(m > 0.0f)) return p;
  if (m < 0x1p-100f) {  // tiny or subnormal: scale up exactly first, so 1/m stays finite
    n = n * 0x1p+100f;
    m = m * 0x1p+100f;
  }
  const float inv_m = 1.0f / m;
  const Vec3f u = {n.x * inv_m, n.y * inv_m, n.z * inv_m};  // max |u_i| = 1 (within rounding)
  return {offset_coordinate(p.x, u.x), offset_coordinate(p.y, u.y), offset_coordinate(p.z, u.z)};
}

}  // namespace strata
