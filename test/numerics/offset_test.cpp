// offset_ray_origin: secondary rays leaving a surface (either side, any direction into the
// leaving hemisphere down to grazing angles, scales 1e-3 .. 1e5) must never hit the triangle
// they leave; the same rays from the unmoved hit point do, sometimes, so the test can fail.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "firmware/common/ray_offset.h"
#include "numerics_support.h"

namespace strata::numerics {
namespace {

struct SelfHits {
  uint64_t rays = 0, offset_hits = 0, raw_hits = 0;
  double max_move = 0;  // largest move / max(2^-15 |p_i|, 2^-16) over coordinates i
};

// Triangles of size `scale` at distance `where` from the world origin; the hit point is the
// barycentric interpolation the shading code uses, the normal the unnormalised cross product.
SelfHits self_hits(double scale, double where, int count, uint64_t seed) {
  Pcg32 rng = Pcg32::keyed(seed, uint64_t(std::log10(scale) + 10) * 100 + uint64_t(std::log10(where + 1)));
  SelfHits s;
  for (int i = 0; i < count; ++i) {
    const Vec3f center = random_unit(rng) * round_f(where);
    auto vertex = [&] {
      const Vec3f r = random_unit(rng);
      return Vec3f{round_f(double(center.x) + scale * r.x), round_f(double(center.y) + scale * r.y),
                   round_f(double(center.z) + scale * r.z)};
    };
    const Vec3f v0 = vertex(), v1 = vertex(), v2 = vertex();
    const Vec3f e1 = v1 - v0, e2 = v2 - v0;
    Vec3f n = cross(e1, e2);
    if (n.x == 0.0f && n.y == 0.0f && n.z == 0.0f) continue;
    float b1 = rng.uniform(), b2 = rng.uniform();
    if (b1 + b2 > 1.0f) {
      b1 = 1.0f - b1;
      b2 = 1.0f - b2;
    }
    const Vec3f p = (v0 + e1 * b1) + e2 * b2;
    if (rng.below(2)) n = n * -1.0f;  // leave towards either side
    // Direction into the hemisphere of n; a third of them grazing (1e-2 .. 1e-6 rad).
    const double nl = std::sqrt(double(dot(n, n)));
    const double nh[3] = {n.x / nl, n.y / nl, n.z / nl};
    double dd[3];
    const Vec3f r = random_unit(rng);
    const double rn = r.x * nh[0] + r.y * nh[1] + r.z * nh[2];
    if (i % 3 == 0) {
      double t[3] = {r.x - rn * nh[0], r.y - rn * nh[1], r.z - rn * nh[2]};
      const double tl = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
      if (tl == 0) continue;
      const double angle = std::pow(10.0, -2.0 - 4.0 * rng.uniform());
      for (int k = 0; k < 3; ++k) dd[k] = std::cos(angle) * t[k] / tl + std::sin(angle) * nh[k];
    } else {
      const double sgn = rn < 0 ? -1.0 : 1.0;
      dd[0] = sgn * r.x;
      dd[1] = sgn * r.y;
      dd[2] = sgn * r.z;
    }
    const Vec3f d{round_f(dd[0]), round_f(dd[1]), round_f(dd[2])};
    if (double(dot(d, n)) <= 0) continue;  // rounding put it back in the plane
    const Vec3f o = offset_ray_origin(p, n);
    TrianglePartial part;
    ++s.rays;
    if (triangle_hit_test(v0, v1, v2, o, d, &part)) ++s.offset_hits;
    if (triangle_hit_test(v0, v1, v2, p, d, &part)) ++s.raw_hits;
    // Each coordinate moves at most 256 ulps (<= 2^-15 of itself) or, near zero, 1/65536.
    const float pc[3] = {p.x, p.y, p.z}, oc[3] = {o.x, o.y, o.z};
    for (int k = 0; k < 3; ++k) {
      const double limit = std::max(0x1p-15 * std::fabs(pc[k]), 0x1p-16);
      s.max_move = std::max(s.max_move, std::fabs(double(oc[k]) - pc[k]) / limit);
    }
  }
  return s;
}

TEST(NumericsOffset, SecondaryRaysNeverHitTheTriangleTheyLeave) {
  struct Case { double scale, where; };
  // Triangle sizes 1e-3 .. 1e5, near the world origin and far from it (but not smaller than
  // ~1e-3 of their distance, or the float grid itself could not describe them).
  const Case cases[] = {{1e-3, 0},   {1e-3, 1},   {1e-2, 10},  {1, 0},     {1, 100},
                        {1, 1000},   {10, 1e4},   {1e3, 0},    {1e3, 1e5}, {1e5, 1e5}};
  uint64_t rays = 0, offset_hits = 0, raw_hits = 0;
  for (const Case& c : cases) {
    const SelfHits s = self_hits(c.scale, c.where, 30000, 31);
    std::ostringstream what;
    what << "triangle size " << c.scale << " at distance " << c.where;
    report_rate("self-hits with offset_ray_origin, " + what.str(), s.offset_hits, s.rays);
    report_rate("self-hits from the raw hit point, " + what.str(), s.raw_hits, s.rays);
    std::cout << "[numerics] largest move " << what.str() << ": " << s.max_move << " of the limit\n";
    EXPECT_EQ(s.offset_hits, 0u) << what.str();
    EXPECT_LE(s.max_move, 1.001) << what.str();  // plus the rounding of p + n / 65536
    rays += s.rays;
    offset_hits += s.offset_hits;
    raw_hits += s.raw_hits;
  }
  report_rate("self-hits with offset_ray_origin, all cases", offset_hits, rays);
  report_rate("self-hits from the raw hit point, all cases", raw_hits, rays);
  EXPECT_GT(raw_hits, rays / 1000);  // without the offset the problem is real
}

TEST(NumericsOffset, DefinedOnDegenerateInput) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const Vec3f p{1.0f, -2.0f, 0.01f};
  auto same = [](Vec3f a, Vec3f b) {
    return float_bits(a.x) == float_bits(b.x) && float_bits(a.y) == float_bits(b.y) && float_bits(a.z) == float_bits(b.z);
  };
  EXPECT_TRUE(same(offset_ray_origin(p, {0.0f, 0.0f, 0.0f}), p));
  EXPECT_TRUE(same(offset_ray_origin(p, {nan, 1.0f, 0.0f}), p));
  EXPECT_TRUE(same(offset_ray_origin(p, {inf, 1.0f, 0.0f}), p));
  const Vec3f bad{nan, 0.0f, 0.0f};
  EXPECT_TRUE(std::isnan(offset_ray_origin(bad, {0.0f, 0.0f, 1.0f}).x));
  // The normal's length does not matter, nor does a subnormal length.
  EXPECT_TRUE(same(offset_ray_origin(p, {0.0f, 3.0f, 4.0f}), offset_ray_origin(p, {0.0f, 3e-30f, 4e-30f})));
  EXPECT_TRUE(same(offset_ray_origin(p, {0.0f, 3.0f, 4.0f}), offset_ray_origin(p, {0.0f, 0x3p-140f, 0x4p-140f})));
  // Moves towards n in every coordinate: integer steps away from zero and towards it.
  const Vec3f up = offset_ray_origin(p, {1.0f, 1.0f, 1.0f});
  EXPECT_GT(up.x, p.x);
  EXPECT_GT(up.y, p.y);
  EXPECT_GT(up.z, p.z);
  EXPECT_EQ(up.x, bits_float(float_bits(1.0f) + 256));
  EXPECT_EQ(up.y, bits_float(float_bits(-2.0f) - 256));
  EXPECT_EQ(up.z, 0.01f + 1.0f / 65536.0f);  // near the origin: the float offset
}

}  // namespace
}  // namespace strata::numerics
