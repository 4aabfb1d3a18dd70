// The one definition of the ray-box and ray-triangle tests. The fused pipelines of the chip
// model, the firmware (RISC-V and native twin) and the host tools all call these functions,
// so all of them compute bit-identical results. Freestanding: no library calls.
//
// Floating-point rules (docs/numerics.md gives the full semantics and the proofs):
// - Operation order is fixed by the source; the build uses -ffp-contract=off everywhere.
//   Round to nearest even, gradual underflow, no fast-math: every argument below relies on
//   rounding being monotone and symmetric (fl(-x) = -fl(x)).
// - max_ignore_nan / min_ignore_nan below define NaN behaviour explicitly: a NaN candidate
//   never replaces the running value. The compiler may not reorder these comparisons.
// - Non-finite input: a ray with a non-finite origin or direction, or a triangle with a
//   non-finite vertex, never hits. intersect_box rejects such a ray at once, so traversal
//   does not visit the tree.
#pragma once

#include <stdint.h>

#include "firmware/common/vec3.h"

namespace strata {

// Running maximum that ignores a NaN candidate (x > m is false for NaN).
inline float max_ignore_nan(float m, float x) { return x > m ? x : m; }
// Running minimum that ignores a NaN candidate.
inline float min_ignore_nan(float m, float x) { return x < m ? x : m; }

// Conservative far distance (Ize 2013, "Robust BVH Ray Traversal"). With u = 2^-24, a slab
// distance (plane - o) * inv_dir carries three roundings, so a computed near distance is at
// most (1+u)^3 times the real one and a computed far distance at least (1-u)^3 times it;
// the multiplication by the pad rounds once more. The pad must satisfy
// pad * (1-u)^4 >= (1+u)^3, i.e. pad >= 1 + 7u + O(u^2); the smallest float that does is
// 1 + 8u = 1 + 2^-21. (1 + 6u, the usual 1 + 2*gamma_3, misses the last rounding.)
// The near distance is left as is: a box entered slightly early is harmless.
constexpr float kFarPad = 0x1.000008p+0f;  // 1 + 2^-21 = 1.000000476837158

// Ray in the form the box pipeline consumes: origin, inverse direction, [tmin, tmax].
struct BoxRay {
  Vec3f origin;
  Vec3f inv_dir;
  float tmin, tmax;
};

// Inverse direction with IEEE semantics: a zero component gives +-inf of the zero's sign,
// an infinite component gives 0, a NaN gives NaN (intersect_box rejects the last two).
inline Vec3f inverse_direction(Vec3f d) { return {1.0f / d.x, 1.0f / d.y, 1.0f / d.z}; }

// True for every finite float, false for +-inf and NaN (x - x is NaN for those).
inline bool is_finite_float(float x) { return x - x == 0.0f; }

// A box ray is usable when its origin is finite and no inverse-direction component is NaN
// (NaN direction) or zero (infinite direction). +-inf components (zero direction) are fine.
inline bool box_ray_is_valid(const BoxRay& r) {
  const bool origin_ok =
      is_finite_float(r.origin.x) && is_finite_float(r.origin.y) && is_finite_float(r.origin.z);
  const bool inv_ok = (r.inv_dir.x == r.inv_dir.x && r.inv_dir.x != 0.0f) &&
                      (r.inv_dir.y == r.inv_dir.y && r.inv_dir.y != 0.0f) &&
                      (r.inv_dir.z == r.inv_dir.z && r.inv_dir.z != 0.0f);
  return origin_ok && inv_ok;
}

// Slab test in the style of Williams et al. (2005): the sign of each inverse direction picks
// which plane is near, so no per-axis min/max of t values is needed.
// When a direction component is zero and the origin lies exactly on that slab plane,
// (plane - origin) * inv_dir is 0 * inf = NaN: the ray runs inside the plane, and ignoring
// the NaN treats that axis as unbounded, which is the conservative (closed box) answer. For a
// flat box (bmin == bmax on that axis) both distances are NaN and the axis is unbounded too.
// A parallel ray off the plane gets +-inf distances, which decide the axis exactly.
// Conservative: whenever the real ray segment [max(tmin,0), tmax] touches the closed box,
// the test returns true (docs/numerics.md, "Box test"). An invalid ray (box_ray_is_valid)
// or a NaN tmin/tmax returns false.
// Returns true on overlap of [tmin, tmax] with the box; *t_entry gets the entry distance.
// intersect_box without the ray validity check, for callers that checked the ray once
// (traversal tests many boxes with one ray). Same result as intersect_box for a valid ray.
STRATA_INLINE bool intersect_box_valid_ray(const float bmin[3], const float bmax[3],
                                           const BoxRay& ray, float* t_entry) {
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

inline bool intersect_box(const float bmin[3], const float bmax[3], const BoxRay& ray,
                          float* t_entry) {
  const bool overlap = intersect_box_valid_ray(bmin, bmax, ray, t_entry);
  return box_ray_is_valid(ray) && overlap;
}

// Result of the division-free triangle stage: the edge terms and the numerator and
// denominator of t. Produced by the fused triangle pipeline; finished only on a hit.
struct TrianglePartial {
  float e0, e1, e2;  // edge terms; e_i weights vertex i
  float t_num, t_den;
};

namespace detail {

inline float abs_f(float x) { return x < 0.0f ? -x : x; }

// The rounding error of a product: a*b - fl(a*b), exactly (Dekker 1971, Veltkamp splitting;
// no FMA). Exact when |a|, |b| < 2^115 and the exponents of a and b sum to at least -103
// (|a*b| >~ 2^-102); p must be fl(a*b). The operands are put in a fixed order first, so
// product_error(a, b, p) == product_error(b, a, p) bitwise even outside that range.
inline float product_error(float a, float b, float p) {
  if (b < a) {
    const float s = a;
    a = b;
    b = s;
  }
  const float kSplit = 4097.0f;  // 2^12 + 1
  const float ca = kSplit * a;
  const float ah = ca - (ca - a);
  const float al = a - ah;
  const float cb = kSplit * b;
  const float bh = cb - (cb - b);
  const float bl = b - bh;
  return al * bl - (((p - ah * bh) - al * bh) - ah * bl);
}

// Edge function of the projected points i and j: x_i * y_j - y_i * x_j, with the exact sign.
// Rounding is monotone, so fl(x_i*y_j) and fl(y_i*x_j) are ordered like the exact products
// (or equal): a non-zero difference has the exact sign. When they round to the same value,
// the exact value is the difference of the two rounding errors, computed exactly above; its
// rounded difference again has the exact sign. Antisymmetric bit for bit:
// edge_function(j, i) == -edge_function(i, j), since products commute and a - b == -(b - a).
inline float edge_function(float xi, float yi, float xj, float yj) {
  const float p = xi * yj;
  const float q = yi * xj;
  const float e = p - q;
  if (e != 0.0f) return e;  // also NaN (inf - inf, NaN input)
  return product_error(xi, yj, p) - product_error(yi, xj, q);
}

// Exact powers of two that normalise a direction: for m = |dir[kz]| with biased exponent
// E (clamped to [1, 253]), *scale = 2^(127-E) and *unscale = 2^(E-127), so
// scale * unscale == 1 exactly and 1 <= m * scale < 4 for normal m (< 2 unless m >= 2^127).
// Built from the exponent bits: no division, no library call.
inline void direction_scale(float m, float* scale, float* unscale) {
  uint32_t bits;
  __builtin_memcpy(&bits, &m, sizeof bits);
  uint32_t exponent = (bits >> 23) & 0xFFu;
  if (exponent < 1u) exponent = 1u;
  if (exponent > 253u) exponent = 253u;
  const uint32_t scale_bits = (254u - exponent) << 23;
  const uint32_t unscale_bits = exponent << 23;
  __builtin_memcpy(scale, &scale_bits, sizeof scale_bits);
  __builtin_memcpy(unscale, &unscale_bits, sizeof unscale_bits);
}

inline float component(Vec3f v, int axis) { return axis == 0 ? v.x : (axis == 1 ? v.y : v.z); }

constexpr float kMinNormal = 0x1p-126f;

// One vertex relative to the ray origin, projected along d (triangle_hit_test, step 2), with
// depth_mag = sum of |a[i]*d[i]|, from the products the depth uses: it bounds the depth's
// rounding error.
struct Projected {
  float x, y, depth, depth_mag;
};

inline Projected project(Vec3f a, int kx, int ky, int kz, Vec3f d) {
  const float dx = component(d, kx);
  const float dy = component(d, ky);
  const float dz = component(d, kz);
  const float sx = a.x * d.x;
  const float sy = a.y * d.y;
  const float sz = a.z * d.z;
  return {dz * component(a, kx) - dx * component(a, kz), dz * component(a, ky) - dy * component(a, kz),
          (sx + sy) + sz,  // dot(a, d), in vec3.h's order
          (abs_f(sx) + abs_f(sy)) + abs_f(sz)};
}

// gamma(5) = 5u / (1 - 5u), u = 2^-24, rounded up: the relative error bound of a depth
// (the translation v - origin, three products, two sums; Higham).
constexpr float kDepthError = 0x1.400008p-22f;
// Shewchuk's orient3d filter bound, (7 + 56u) u, rounded up to 8u: the computed orientation
// below is within kOrientError * permanent of the exact one, translation included.
constexpr float kOrientError = 0x1p-21f;

// Whether the exact t of a hit is positive, not only the rounded one. The rounded t_num can
// have the sign of t_den when the exact t is 0 or negative: a ray whose origin lies in the
// triangle's plane (exact t = 0; tmin = 0 is open) would hit at t of about 1e-11 to 1e-8.
// (pbrt-v4 bounds t's rounding error for the same reason; docs/numerics.md, "Sign of t".)
//  - Tight case: every vertex lies farther along d than its depth's rounding error. Then the
//    exact depth of every point of the triangle is positive, so is t: far triangles and
//    grazing rays decide here, at the cost of three products.
//  - Otherwise the triangle straddles the origin's depth, and the sign of t comes from the
//    plane: t = orient / dot(n, d) with n = cross(v1 - v0, v2 - v0), orient = dot(n, a) =
//    dot(a, cross(b, c)) (a, b, c the vertices relative to the origin), and dot(n, d) has
//    det's sign. orient is taken only when it is farther from zero than Shewchuk's bound, so
//    an origin within rounding of the plane never hits. Unlike a bound on t_num, this does not
//    grow with the projection's cancellation, so an edge-on neighbour at a shared edge still
//    hits (NumericsTriangle.SharedEdgeNeverLetsARayThrough).
// A NaN anywhere fails both tests.
inline bool t_exactly_positive(Vec3f a, Vec3f b, Vec3f c, const Projected& pa, const Projected& pb,
                               const Projected& pc, float t_den) {
  if (pa.depth > kDepthError * pa.depth_mag && pb.depth > kDepthError * pb.depth_mag &&
      pc.depth > kDepthError * pc.depth_mag)
    return true;
  const float bxcy = b.x * c.y, cxby = c.x * b.y;
  const float cxay = c.x * a.y, axcy = a.x * c.y;
  const float axby = a.x * b.y, bxay = b.x * a.y;
  const float orient = (a.z * (bxcy - cxby) + b.z * (cxay - axcy)) + c.z * (axby - bxay);
  const float permanent = ((abs_f(bxcy) + abs_f(cxby)) * abs_f(a.z) + (abs_f(cxay) + abs_f(axcy)) * abs_f(b.z)) +
                          (abs_f(axby) + abs_f(bxay)) * abs_f(c.z);
  const float bound = kOrientError * permanent;
  return t_den > 0.0f ? orient > bound : orient < -bound;
}

}  // namespace detail

// Watertight ray-triangle test without a division: the Plücker edge terms evaluated in the
// ray's own sheared frame (as in Woop, Benthin and Wald 2013, but multiplying instead of
// dividing), so that every sign is exact.
//  1. kz is the axis of the largest |dir| component (ties: z, then y, then x); kx, ky follow
//     it cyclically and are swapped when dir[kz] < 0, so the frame keeps the handedness.
//     d = dir * 2^-k with 2^k <= |dir[kz]| < 2^(k+1), an exact scaling (direction_scale):
//     1 <= |d[kz]| < 2, so the terms do not depend on the length of dir.
//  2. Every vertex is translated to the ray origin, a = v - origin, and projected along d:
//       x = d[kz]*a[kx] - d[kx]*a[kz],  y = d[kz]*a[ky] - d[ky]*a[kz],  depth = dot(a, d).
//     (x, y) are two components of d x a: exactly the Plücker products of the ray with the
//     vertex. The projection of a vertex depends only on the vertex and the ray, so every
//     triangle sharing the vertex sees the same rounded point.
//  3. The term of edge (i, j) is the 2D cross product x_i*y_j - y_i*x_j = |d[kz]| times the
//     Plücker term dot(d, cross(a_i, a_j)), evaluated with its exact sign (edge_function).
//     A neighbour sharing the edge as (j, i) gets exactly the negated value.
// So the test is the exact point-in-triangle test of the projected origin against a fixed,
// consistently rounded projection of the mesh: no ray slips through a shared edge or a
// shared vertex of a closed mesh (docs/numerics.md, "Watertightness").
// A hit needs all three terms of one sign (zeros allowed on either side), a sum det that is
// finite with |det| >= 2^-126 (det == 0: the ray lies in the triangle's plane or the
// triangle has no area), and the plane strictly in front of the origin (t_num and t_den of
// one sign, both finite). NaN or infinite input fails one of these, so it never hits, and a
// reported hit always finishes to a finite t > 0 and barycentrics in [0, 1].
inline bool triangle_hit_test(Vec3f v0, Vec3f v1, Vec3f v2, Vec3f origin, Vec3f dir,
                              TrianglePartial* out) {
  const float adx = detail::abs_f(dir.x);
  const float ady = detail::abs_f(dir.y);
  const float adz = detail::abs_f(dir.z);
  int kz = 2;
  if (!(adz >= adx && adz >= ady)) kz = (ady >= adx) ? 1 : 0;
  int kx = kz == 2 ? 0 : kz + 1;
  int ky = kx == 2 ? 0 : kx + 1;
  const float dkz_raw = detail::component(dir, kz);
  if (dkz_raw < 0.0f) {
    const int s = kx;
    kx = ky;
    ky = s;
  }
  float scale, unscale;
  detail::direction_scale(detail::abs_f(dkz_raw), &scale, &unscale);
  const Vec3f d = dir * scale;  // exact unless a component drops below 2^-126

  const Vec3f a = v0 - origin;
  const Vec3f b = v1 - origin;
  const Vec3f c = v2 - origin;
  const detail::Projected pa = detail::project(a, kx, ky, kz, d);
  const detail::Projected pb = detail::project(b, kx, ky, kz, d);
  const detail::Projected pc = detail::project(c, kx, ky, kz, d);

  const float e0 = detail::edge_function(pb.x, pb.y, pc.x, pc.y);  // edge v1 -> v2, weights v0
  const float e1 = detail::edge_function(pc.x, pc.y, pa.x, pa.y);  // edge v2 -> v0, weights v1
  const float e2 = detail::edge_function(pa.x, pa.y, pb.x, pb.y);  // edge v0 -> v1, weights v2
  const bool all_nonneg = e0 >= 0.0f && e1 >= 0.0f && e2 >= 0.0f;
  const bool all_nonpos = e0 <= 0.0f && e1 <= 0.0f && e2 <= 0.0f;
  if (!(all_nonneg || all_nonpos)) return false;  // NaN terms miss here
  const float det = (e0 + e1) + e2;
  // One sign, so det is 0 only if all terms are; finite det means finite terms.
  const float abs_det = detail::abs_f(det);
  if (!(abs_det >= detail::kMinNormal && is_finite_float(det))) return false;
  // The hit point relative to the origin is (e0 a + e1 b + e2 c) / det, and t is its
  // projection on d divided by |d|^2: interpolating projections keeps t accurate. The
  // factor 2^k turns t along d back into t along dir (exact).
  const float t_num = (e0 * pa.depth + e1 * pb.depth) + e2 * pc.depth;
  const float t_den = (det * dot(d, d)) * unscale;
  if (!(is_finite_float(t_num) && is_finite_float(t_den) &&
        detail::abs_f(t_den) >= detail::kMinNormal))
    return false;
  // In front of the origin: t_num and t_den of one sign (t_den is non-zero here), and the
  // exact t positive too, not only the rounded one.
  if (!(t_den > 0.0f ? t_num > 0.0f : t_num < 0.0f)) return false;
  if (!detail::t_exactly_positive(a, b, c, pa, pb, pc, t_den)) return false;
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

// The division stage, run only after triangle_hit_test succeeded. The terms share det's sign
// and 2^-126 <= |det| < inf, so 1/det is finite and b1, b2 lie in [0, 1] (up to one rounding).
inline TriangleHit triangle_finish(const TrianglePartial& p) {
  const float det = (p.e0 + p.e1) + p.e2;
  const float inv_det = 1.0f / det;
  return {p.t_num / p.t_den, p.e1 * inv_det, p.e2 * inv_det};
}

}  // namespace strata
