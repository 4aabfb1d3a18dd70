// The one definition of the ray-box and ray-triangle tests. The fused pipelines of the chip
// model, the firmware (RISC-V and native twin) and the host tools all call these functions,
// so all of them compute bit-identical results. Freestanding: no library calls.
//
// Floating-point rules (see docs/numerics.md):
// - Operation order is fixed by the source; the build uses -ffp-contract=off everywhere.
// - max_ignore_nan / min_ignore_nan below define NaN behaviour explicitly: a NaN candidate
//   never replaces the running value. The compiler may not reorder these comparisons.
#pragma once

#include "firmware/common/vec3.h"

namespace strata {

// Running maximum that ignores a NaN candidate (x > m is false for NaN).
inline float max_ignore_nan(float m, float x) { return x > m ? x : m; }
// Running minimum that ignores a NaN candidate.
inline float min_ignore_nan(float m, float x) { return x < m ? x : m; }

// Multiplying the far distance by 1 + 3 * 2^-23 covers the rounding error of the slab
// computation (Ize 2013, "Robust BVH Ray Traversal"), so traversal never culls a box the
// ray really hits. The near distance is left as is: a box entered slightly early is harmless.
constexpr float kFarPad = 1.00000036f;

// Ray in the form the box pipeline consumes: origin, inverse direction, [tmin, tmax].
struct BoxRay {
  Vec3f origin;
  Vec3f inv_dir;
  float tmin, tmax;
};

// Inverse direction with IEEE semantics: a zero component gives +-inf of the zero's sign.
inline Vec3f inverse_direction(Vec3f d) { return {1.0f / d.x, 1.0f / d.y, 1.0f / d.z}; }

// Slab test in the style of Williams et al. (2005): the sign of each inverse direction picks
// which plane is near, so no per-axis min/max of t values is needed.
// When a direction component is zero and the origin lies exactly on that slab plane,
// (plane - origin) * inv_dir is 0 * inf = NaN: the ray runs inside the plane, and ignoring
// the NaN treats that axis as unbounded, which is the conservative (closed box) answer.
// Returns true on overlap of [tmin, tmax] with the box; *t_entry gets the entry distance.
inline bool intersect_box(const float bmin[3], const float bmax[3], const BoxRay& ray,
                          float* t_entry) {
  const float o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  const float inv[3] = {ray.inv_dir.x, ray.inv_dir.y, ray.inv_dir.z};
  float t_near = ray.tmin;
  float t_far = ray.tmax;
  for (int axis = 0; axis < 3; ++axis) {
    const bool positive = !(inv[axis] < 0.0f);  // +0, +inf and NaN count as positive
    const float near_plane = positive ? bmin[axis] : bmax[axis];
    const float far_plane = positive ? bmax[axis] : bmin[axis];
    const float t0 = (near_plane - o[axis]) * inv[axis];
    const float t1 = ((far_plane - o[axis]) * inv[axis]) * kFarPad;
    t_near = max_ignore_nan(t_near, t0);
    t_far = min_ignore_nan(t_far, t1);
  }
  *t_entry = t_near;
  return t_near <= t_far;
}

// Result of the division-free triangle stage: the Plücker edge terms and the numerator and
// denominator of t. Produced by the fused triangle pipeline; finished only on a hit.
struct TrianglePartial {
  float e0, e1, e2;  // edge terms; e_i weights vertex i
  float t_num, t_den;
};

// Plücker-coordinate ray-triangle test without a division. Vertices are first translated
// to the ray origin. The term of edge (a, b) is dot(d, cross(a', b')); a neighbouring
// triangle that shares the edge as (b, a) computes cross(b', a') = -cross(a', b') exactly
// (round-to-nearest is symmetric), so a ray through a shared edge gets terms of opposite
// sign from the two triangles and can never slip between them (watertight).
// A hit needs all three terms of one sign (zeros allowed on either side), a non-zero sum,
// and the plane in front of the origin. The degenerate case (all terms zero: the ray lies in
// the triangle's plane, or the triangle has no area) is a miss.
inline bool triangle_hit_test(Vec3f v0, Vec3f v1, Vec3f v2, Vec3f origin, Vec3f dir,
                              TrianglePartial* out) {
  const Vec3f a = v0 - origin;
  const Vec3f b = v1 - origin;
  const Vec3f c = v2 - origin;
  const float e0 = dot(dir, cross(b, c));
  const float e1 = dot(dir, cross(c, a));
  const float e2 = dot(dir, cross(a, b));
  const bool all_nonneg = e0 >= 0.0f && e1 >= 0.0f && e2 >= 0.0f;
  const bool all_nonpos = e0 <= 0.0f && e1 <= 0.0f && e2 <= 0.0f;
  const float det = (e0 + e1) + e2;
  if (!(all_nonneg || all_nonpos) || !(det != 0.0f)) return false;  // NaN terms miss here
  // The hit point relative to the origin is (e0 a + e1 b + e2 c) / det, and t is its
  // projection on d divided by |d|^2: interpolating projections keeps t accurate.
  const float t_num = (e0 * dot(a, dir) + e1 * dot(b, dir)) + e2 * dot(c, dir);
  const float t_den = det * dot(dir, dir);
  // In front of the origin: t_num and t_den of one sign (t_den is non-zero here).
  if (!(t_den > 0.0f ? t_num > 0.0f : t_num < 0.0f)) return false;
  out->e0 = e0;
  out->e1 = e1;
  out->e2 = e2;
  out->t_num = t_num;
  out->t_den = t_den;
  return true;
}

struct TriangleHit {
  float t;
  float b1, b2;  // barycentric weights of v1 and v2 (v0 gets 1 - b1 - b2)
};

// The division stage, run only after triangle_hit_test succeeded.
inline TriangleHit triangle_finish(const TrianglePartial& p) {
  const float det = (p.e0 + p.e1) + p.e2;
  const float inv_det = 1.0f / det;
  return {p.t_num / p.t_den, p.e1 * inv_det, p.e2 * inv_det};
}

}  // namespace strata
