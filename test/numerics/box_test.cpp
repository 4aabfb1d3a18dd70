// The slab test against an exact reference: it must never cull a box the ray really touches
// (rays through box corners, edges and faces, flat boxes, rays inside a slab plane), must
// treat zero direction components and origins on slab planes by the documented NaN rule, and
// must reject non-finite rays at once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

#include "numerics_support.h"
#include "scenes/procedural/procedural.h"

#include <glm/geometric.hpp>

namespace strata::numerics {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Grid values k * 2^-20 with |k| < 2^22: every coordinate, every difference of two of them and
// every direction built as such a difference is a float with at most 24 significant bits, so
// the products below are exact in double and the reference decides exactly.
float grid(Pcg32& rng, float lo, float hi) {
  const double v = double(lo) + (double(hi) - double(lo)) * rng.uniform();
  return round_f(std::ldexp(std::floor(std::ldexp(v, 20)), -20));
}

// Exact: does {o + t d : t >= 0} touch the closed box? Interval per axis as fractions with a
// positive denominator, compared by exact cross-multiplication.
bool exact_box_hit(const float bmin[3], const float bmax[3], Vec3f o3, Vec3f d3) {
  const float o[3] = {o3.x, o3.y, o3.z}, d[3] = {d3.x, d3.y, d3.z};
  // lo = lo_num / lo_den, hi = hi_num / hi_den; hi_den == 0 means +inf.
  double lo_num = 0.0, lo_den = 1.0, hi_num = 1.0, hi_den = 0.0;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0f) {
      if (o[a] < bmin[a] || o[a] > bmax[a]) return false;
      continue;
    }
    double n0 = double(bmin[a]) - o[a], n1 = double(bmax[a]) - o[a], den = d[a];
    if (den < 0) {
      n0 = -n0;
      n1 = -n1;
      den = -den;
      std::swap(n0, n1);
    }
    if (n0 * lo_den > lo_num * den) {  // n0/den > lo
      lo_num = n0;
      lo_den = den;
    }
    if (hi_den == 0.0 || n1 * hi_den < hi_num * den) {
      hi_num = n1;
      hi_den = den;
    }
  }
  if (hi_den == 0.0) return true;
  return lo_num * hi_den <= hi_num * lo_den;
}

// The production algorithm with another pad, to show what the pad is for.
bool box_with_pad(const float bmin[3], const float bmax[3], const BoxRay& ray, float pad) {
  const float o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  const float inv[3] = {ray.inv_dir.x, ray.inv_dir.y, ray.inv_dir.z};
  float t_near = ray.tmin, t_far = ray.tmax;
  for (int axis = 0; axis < 3; ++axis) {
    const bool positive = !(inv[axis] < 0.0f);
    const float near_plane = positive ? bmin[axis] : bmax[axis];
    const float far_plane = positive ? bmax[axis] : bmin[axis];
    t_near = max_ignore_nan(t_near, (near_plane - o[axis]) * inv[axis]);
    t_far = min_ignore_nan(t_far, ((far_plane - o[axis]) * inv[axis]) * pad);
  }
  return t_near <= t_far;
}

struct BoxCounts {
  uint64_t rays = 0, exact_hits = 0, false_culls = 0, false_culls_old_pad = 0,
           false_culls_no_pad = 0, conservative_extra = 0, loose = 0;
};

// Rays through a corner, an edge point or a face point of a random (sometimes flat) box,
// from origins that sometimes sit exactly on a slab plane, sometimes with zero direction
// components, sometimes nudged by one grid step so they just miss or just hit.
BoxCounts run_box_rays(uint32_t count, uint64_t seed, float dir_scale) {
  Pcg32 rng = Pcg32::keyed(seed, 1);
  BoxCounts n;
  for (uint32_t i = 0; i < count; ++i) {
    float bmin[3], bmax[3], o[3], c[3];
    for (int a = 0; a < 3; ++a) {
      const float x = grid(rng, -2.0f, 2.0f), y = grid(rng, -2.0f, 2.0f);
      bmin[a] = std::min(x, y);
      bmax[a] = std::max(x, y);
      if (rng.below(5) == 0) bmax[a] = bmin[a];  // flat box on this axis
      o[a] = grid(rng, -4.0f, 4.0f);
    }
    // Target: every axis at a plane (corner), two (edge) or one (face), else inside the slab.
    const uint32_t at_planes = rng.below(4);
    for (int a = 0; a < 3; ++a) {
      if (uint32_t(a) < at_planes)
        c[a] = rng.below(2) ? bmin[a] : bmax[a];
      else
        c[a] = bmin[a] + round_f(std::ldexp(std::floor(std::ldexp(double(bmax[a] - bmin[a]) * rng.uniform(), 20)), -20));
    }
    // Origin exactly on a slab plane of one axis, and sometimes a parallel ray in that plane.
    if (rng.below(4) == 0) {
      const int a = int(rng.below(3));
      o[a] = rng.below(2) ? bmin[a] : bmax[a];
      if (rng.below(2)) c[a] = o[a];
    }
    if (rng.below(8) == 0) {  // axis-parallel on one more axis
      const int a = int(rng.below(3));
      c[a] = o[a];
    }
    Vec3f d{c[0] - o[0], c[1] - o[1], c[2] - o[2]};
    if (rng.below(4) == 0) {  // one grid step off: a near miss or near hit
      const float step = 0x1p-20f * (rng.below(2) ? 1.0f : -1.0f);
      const int a = int(rng.below(3));
      if (a == 0) d.x += step;
      if (a == 1) d.y += step;
      if (a == 2) d.z += step;
    }
    const Vec3f origin{o[0], o[1], o[2]};
    const bool exact = exact_box_hit(bmin, bmax, origin, d);
    float gmin[3], gmax[3];  // the box grown by 2^-16 (64 grid steps), still on the grid
    for (int a = 0; a < 3; ++a) {
      gmin[a] = bmin[a] - 0x1p-16f;
      gmax[a] = bmax[a] + 0x1p-16f;
    }
    const bool exact_grown = exact_box_hit(gmin, gmax, origin, d);
    // Scaling the direction by a power of two scales every t exactly; the test must not care.
    const Vec3f ds = d * dir_scale;
    const BoxRay ray{origin, inverse_direction(ds), 0.0f, kInf};
    float t_entry = 0.0f;
    const bool ours = intersect_box(bmin, bmax, ray, &t_entry);
    ++n.rays;
    if (exact) ++n.exact_hits;
    if (exact && !ours) ++n.false_culls;
    if (!exact && ours) ++n.conservative_extra;
    if (!exact_grown && ours) ++n.loose;
    if (exact && !box_with_pad(bmin, bmax, ray, 1.00000036f)) ++n.false_culls_old_pad;
    if (exact && !box_with_pad(bmin, bmax, ray, 1.0f)) ++n.false_culls_no_pad;
  }
  return n;
}

TEST(NumericsBox, NeverCullsABoxTheRayTouches) {
  BoxCounts total;
  for (float dir_scale : {1.0f, 0x1p-30f, 0x1p+30f}) {
    const BoxCounts n = run_box_rays(1000000, 17, dir_scale);
    total.rays += n.rays;
    total.exact_hits += n.exact_hits;
    total.false_culls += n.false_culls;
    total.false_culls_old_pad += n.false_culls_old_pad;
    total.false_culls_no_pad += n.false_culls_no_pad;
    total.conservative_extra += n.conservative_extra;
    total.loose += n.loose;
  }
  report_rate("box test false culls (pad 1 + 2^-21)", total.false_culls, total.exact_hits);
  report_rate("box test false culls with the old pad 1 + 3 * 2^-23", total.false_culls_old_pad, total.exact_hits);
  report_rate("box test false culls without a pad", total.false_culls_no_pad, total.exact_hits);
  report_rate("box test hits on exact misses (conservative extra)", total.conservative_extra,
              total.rays - total.exact_hits);
  EXPECT_GT(total.exact_hits, total.rays / 4);  // the ray set is mostly touching rays
  EXPECT_EQ(total.false_culls, 0u);
  // The set is hard enough that an unpadded test fails on it: the test can fail.
  EXPECT_GT(total.false_culls_no_pad, 0u);
  // Conservative, but only by rounding: a ray that misses the box grown by 2^-16 (the set's
  // coordinates are below 4, its distances below 14) is always culled.
  EXPECT_EQ(total.loose, 0u);
}

TEST(NumericsBox, PadCoversTheWorstCaseRoundingBound) {
  // pad * (1-u)^4 >= (1+u)^3 with u = 2^-24 (docs/numerics.md, "Box test").
  const long double u = std::ldexp(1.0L, -24);
  EXPECT_GE((long double)kFarPad * std::pow(1.0L - u, 4), std::pow(1.0L + u, 3));
  EXPECT_EQ(kFarPad, 1.0f + 0x1p-21f);
}

TEST(NumericsBox, ZeroDirectionComponentsAndOriginsOnSlabPlanes) {
  const float bmin[3] = {-1.0f, 2.0f, -3.0f}, bmax[3] = {1.0f, 4.0f, 3.0f};
  float t = 0.0f;
  auto hit = [&](Vec3f o, Vec3f d) {
    return intersect_box(bmin, bmax, BoxRay{o, inverse_direction(d), 0.0f, kInf}, &t);
  };
  // Parallel to x inside the y and z slabs: hit, from either side of the box.
  EXPECT_TRUE(hit({-5.0f, 3.0f, 0.0f}, {1.0f, 0.0f, 0.0f}));
  EXPECT_TRUE(hit({5.0f, 3.0f, 0.0f}, {-1.0f, -0.0f, 0.0f}));
  EXPECT_FALSE(hit({5.0f, 3.0f, 0.0f}, {1.0f, 0.0f, 0.0f}));  // pointing away
  // Origin exactly on the y = 2 and y = 4 planes with d.y = +-0: 0 * inf = NaN is ignored,
  // the ray runs inside the box's face: hit (closed box).
  for (float y : {2.0f, 4.0f})
    for (float dy : {0.0f, -0.0f}) {
      EXPECT_TRUE(hit({-5.0f, y, 0.0f}, {1.0f, dy, 0.0f})) << y << " " << dy;
      EXPECT_TRUE(hit({-5.0f, y, 3.0f}, {1.0f, dy, 0.0f})) << "on an edge of the box";
    }
  // One ulp outside the slab: the parallel ray misses.
  EXPECT_FALSE(hit({-5.0f, std::nextafter(2.0f, 0.0f), 0.0f}, {1.0f, 0.0f, 0.0f}));
  EXPECT_FALSE(hit({-5.0f, std::nextafter(4.0f, 5.0f), 0.0f}, {1.0f, 0.0f, 0.0f}));
  // A flat box (zero extent in y) and a ray inside its plane: both y distances are NaN.
  const float fmin[3] = {-1.0f, 2.0f, -1.0f}, fmax[3] = {1.0f, 2.0f, 1.0f};
  EXPECT_TRUE(intersect_box(fmin, fmax, BoxRay{{-5.0f, 2.0f, 0.0f}, inverse_direction({1.0f, 0.0f, 0.0f}), 0.0f, kInf}, &t));
  EXPECT_FALSE(intersect_box(fmin, fmax, BoxRay{{-5.0f, 2.5f, 0.0f}, inverse_direction({1.0f, 0.0f, 0.0f}), 0.0f, kInf}, &t));
  // Crossing the flat box's plane.
  EXPECT_TRUE(intersect_box(fmin, fmax, BoxRay{{0.5f, 5.0f, 0.5f}, inverse_direction({0.0f, -1.0f, 0.0f}), 0.0f, kInf}, &t));
  EXPECT_EQ(t, 3.0f);
  // Axis ray along a box edge line (x = 1, z = 3).
  EXPECT_TRUE(hit({1.0f, -10.0f, 3.0f}, {0.0f, 1.0f, 0.0f}));
  EXPECT_EQ(t, 12.0f);
  // Zero direction: only a box containing the origin "overlaps".
  EXPECT_TRUE(hit({0.0f, 3.0f, 0.0f}, {0.0f, 0.0f, 0.0f}));
  EXPECT_FALSE(hit({0.0f, 5.0f, 0.0f}, {0.0f, 0.0f, 0.0f}));
}

TEST(NumericsBox, NonFiniteRaysAreRejected) {
  const float bmin[3] = {-1.0f, -1.0f, -1.0f}, bmax[3] = {1.0f, 1.0f, 1.0f};
  float t = 0.0f;
  const Vec3f o{0.0f, 0.0f, -5.0f}, d{0.0f, 0.0f, 1.0f};
  ASSERT_TRUE(intersect_box(bmin, bmax, BoxRay{o, inverse_direction(d), 0.0f, kInf}, &t));
  for (int axis = 0; axis < 3; ++axis)
    for (float bad : {kNaN, kInf, -kInf}) {
      Vec3f ob = o, db = d;
      (axis == 0 ? ob.x : axis == 1 ? ob.y : ob.z) = bad;
      (axis == 0 ? db.x : axis == 1 ? db.y : db.z) = bad;
      EXPECT_FALSE(intersect_box(bmin, bmax, BoxRay{ob, inverse_direction(d), 0.0f, kInf}, &t)) << axis << bad;
      EXPECT_FALSE(intersect_box(bmin, bmax, BoxRay{o, inverse_direction(db), 0.0f, kInf}, &t)) << axis << bad;
    }
  EXPECT_FALSE(intersect_box(bmin, bmax, BoxRay{o, inverse_direction(d), kNaN, kInf}, &t));
  EXPECT_FALSE(intersect_box(bmin, bmax, BoxRay{o, inverse_direction(d), 0.0f, kNaN}, &t));
}

struct CountingObserver {
  uint64_t nodes = 0, triangles = 0;
  void node_visited(uint32_t) { ++nodes; }
  void leaf_visited(uint32_t) {}
  void triangle_tested() { ++triangles; }
};

// A non-finite ray costs the traversal one node (the root's two box tests) and no triangle.
TEST(NumericsBox, TraversalOfNonFiniteRayVisitsAtMostTheRoot) {
  const scenes::Scene s = scenes::make_cornell({0.3, 1});
  const scenes::SceneImage img = scenes::build_scene_image(s, {}, nullptr);
  const Vec3f o{0.1f, 0.2f, 0.3f}, d{0.3f, -0.2f, 1.0f};
  CountingObserver ok;
  ASSERT_TRUE(trace_closest(img, img.header().root_node, TraceRay{o, d, 0.0f, kInf}, ok).hit);
  const TraceRay bad[] = {
      {{kNaN, 0.2f, 0.3f}, d, 0.0f, kInf},  {{0.1f, kInf, 0.3f}, d, 0.0f, kInf},
      {o, {0.3f, kNaN, 1.0f}, 0.0f, kInf},  {o, {0.3f, -0.2f, -kInf}, 0.0f, kInf},
      {o, {kNaN, kNaN, kNaN}, 0.0f, kInf},  {o, d, kNaN, kInf},
      {o, d, 0.0f, kNaN}};
  for (const TraceRay& r : bad) {
    CountingObserver obs;
    const ClosestHit h = trace_closest(img, img.header().root_node, r, obs);
    EXPECT_FALSE(h.hit);
    EXPECT_LE(obs.nodes, 1u);  // rejected before the root, or (NaN tmin/tmax) at its boxes
    EXPECT_EQ(obs.triangles, 0u);
  }
}

// Triangles lying exactly in box faces (axis-aligned triangles give flat boxes, and the
// 12-triangle box puts every triangle on a face of the root box): rays aimed exactly at their
// vertices and edges must be found by the traversal whenever brute force finds them.
TEST(NumericsBox, TraversalFindsHitsOnFlatBoxesAndBoxFaces) {
  Pcg32 rng = Pcg32::keyed(3, 3);
  std::vector<scenes::Triangle> tris;
  for (int i = 0; i < 300; ++i) {  // axis-aligned triangles on a coarse grid: shared planes
    const int axis = int(rng.below(3));
    const float plane = round_f(int(rng.below(9)) - 4) * 0.5f;
    float v[3][3];
    for (auto& p : v) {
      for (int a = 0; a < 3; ++a) p[a] = round_f(int(rng.below(17)) - 8) * 0.25f;
      p[axis] = plane;
    }
    tris.push_back({{v[0][0], v[0][1], v[0][2]}, {v[1][0], v[1][1], v[1][2]}, {v[2][0], v[2][1], v[2][2]}, 0});
  }
  for (const auto& t : box12().transformed(2.0, {0.0f, 0.0f, 0.0f}).triangles()) tris.push_back(t);
  scenes::Scene s;
  s.name = "flat";
  s.materials.push_back({"grey", {0.5f, 0.5f, 0.5f}});
  for (const auto& t : tris) {  // the image keeps zero-area triangles out of the way
    const glm::vec3 c = glm::cross(t.v1 - t.v0, t.v2 - t.v0);
    if (c.x != 0.0f || c.y != 0.0f || c.z != 0.0f) s.triangles.push_back(t);
  }
  SCOPED_TRACE(s.triangles.size());
  const scenes::SceneImage img = scenes::build_scene_image(s, {}, nullptr);
  uint64_t rays = 0, brute_hits = 0, missed = 0;
  for (int i = 0; i < 60000; ++i) {
    const scenes::Triangle& t = s.triangles[rng.below(uint32_t(s.triangles.size()))];
    const Vec3f v[3] = {to_vec(t.v0), to_vec(t.v1), to_vec(t.v2)};
    Vec3f target = v[rng.below(3)];
    if (i % 2) {
      const uint32_t e = rng.below(3);
      target = v[e] + (v[(e + 1) % 3] - v[e]) * rng.uniform();
    }
    Vec3f o{round_f(int(rng.below(41)) - 20) * 0.25f, round_f(int(rng.below(41)) - 20) * 0.25f,
            round_f(int(rng.below(41)) - 20) * 0.25f};
    if (i % 3 == 0) o = o * 1.1f;  // off the grid too
    const TraceRay ray{o, target - o, 0.0f, kInf};
    const ClosestHit b = brute_force(s.triangles, ray);
    const ClosestHit h = trace(img, ray);
    ++rays;
    if (b.hit) ++brute_hits;
    if (b.hit && (!h.hit || (h.t > b.t && !same_point(o, ray.dir, b.t, h.t)))) ++missed;
  }
  report_rate("flat boxes / box faces: traversal missed the brute-force closest hit", missed, brute_hits);
  EXPECT_GT(brute_hits, rays / 2);
  EXPECT_EQ(missed, 0u);
}

}  // namespace
}  // namespace strata::numerics
