// Deterministic random numbers and sampling for the path tracer, in 32-bit integer and
// single-precision operations only (cheap on RV32, bit-identical on the host).
#pragma once

#include <stdint.h>

#include "firmware/common/vec3.h"

namespace strata::kernels {

// A 32-bit integer hash with good avalanche (the "lowbias32" constants of C. Wellons).
inline uint32_t hash32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// Counter-based stream: every path vertex draws from its own sequence, which depends only on
// the frame seed, the path's sample index and the vertex, never on which thread or in what
// order it runs, nor on what was drawn before. So no random state travels with a path: a
// kernel that keeps a path's state in its ray (the compact path state) re-derives it.
class PathRng {
 public:
  PathRng(uint32_t seed, uint32_t sample_index, uint32_t vertex)
      : state_(hash32(hash32(sample_index ^ hash32(seed ^ 0x5bd1e995u)) + vertex * 0x9e3779b9u)) {}
  uint32_t next_u32() {
    state_ = state_ * 747796405u + 2891336453u;  // 32-bit LCG, permuted as in PCG-RXS-M-XS
    uint32_t w = ((state_ >> ((state_ >> 28u) + 4u)) ^ state_) * 277803737u;
    return (w >> 22u) ^ w;
  }
  // Uniform in [0, 1): 24 random bits fill a float mantissa exactly.
  float uniform() { return float(next_u32() >> 8) * (1.0f / 16777216.0f); }

 private:
  uint32_t state_;
};

inline float sqrt_f(float x) { return __builtin_sqrtf(x); }  // fsqrt.s / sqrtss: exact IEEE

inline Vec3f normalize(Vec3f v) { return v * (1.0f / sqrt_f(dot(v, v))); }

// Cosine-weighted direction about the unit normal n: a uniform point of the unit disk
// (by rejection, so no trigonometry) lifted to the hemisphere (Malley's method).
inline Vec3f sample_cosine_hemisphere(Vec3f n, PathRng& rng) {
  float x, y, r2;
  do {
    x = 2.0f * rng.uniform() - 1.0f;
    y = 2.0f * rng.uniform() - 1.0f;
    r2 = x * x + y * y;
  } while (r2 >= 1.0f);
  const float z = sqrt_f(1.0f - r2);
  // Orthonormal basis after Duff et al. (2017), "Building an Orthonormal Basis, Revisited".
  const float sign = n.z >= 0.0f ? 1.0f : -1.0f;
  const float a = -1.0f / (sign + n.z);
  const float b = n.x * n.y * a;
  const Vec3f t{1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
  const Vec3f s{b, sign + n.y * n.y * a, -n.y};
  return (t * x + s * y) + n * z;
}

}  // namespace strata::kernels
