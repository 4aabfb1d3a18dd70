// The triangle test on hard cases: exact signs of the edge terms, antisymmetry at shared
// edges, accuracy against a double-precision reference over scales 1e-6 .. 1e6 and
// translations up to 1e5, axis-aligned rays on exact edges and vertices, grazing and coplanar
// rays, degenerate / needle / duplicate-vertex triangles, and non-finite input.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>

#include "numerics_support.h"

namespace strata::numerics {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

int sign_of(double x) { return (x > 0) - (x < 0); }
int sign_of_f(float x) { return (x > 0.0f) - (x < 0.0f); }

// A float of random sign, magnitude 2^[lo, hi) with a random mantissa.
float random_float(Pcg32& rng, int lo, int hi) {
  const float m = 1.0f + rng.uniform();
  const int e = lo + int(rng.below(uint32_t(hi - lo)));
  return (rng.below(2) ? -1.0f : 1.0f) * std::ldexp(m, e);
}

// Products of two floats are exact in double, so the sign of the double difference is exact.
TEST(NumericsTriangle, EdgeFunctionSignIsExact) {
  Pcg32 rng = Pcg32::keyed(1, 1);
  uint64_t checked = 0, ties = 0, wrong = 0;
  for (int i = 0; i < 2000000; ++i) {
    const int lo = -40 + int(rng.below(70));
    float xi = random_float(rng, lo, lo + 4), yi = random_float(rng, lo, lo + 4);
    float xj = random_float(rng, lo, lo + 4), yj = random_float(rng, lo, lo + 4);
    switch (i % 4) {
      case 1:  // nearly collinear with the origin: (xj, yj) ~ s (xi, yi)
        xj = xi * 3.0f;
        yj = round_f(double(yi) * 3.0 * (1.0 + 1e-7 * (rng.uniform() - 0.5)));
        break;
      case 2:  // products that round to the same float
        xj = std::nextafter(xi * 1.5f, kInf);
        yj = yi * 1.5f;
        break;
      case 3:  // small integers: exact zeros and exact ties
        xi = round_f(int(rng.below(7)) - 3);
        yi = round_f(int(rng.below(7)) - 3);
        xj = round_f(int(rng.below(7)) - 3);
        yj = round_f(int(rng.below(7)) - 3);
        break;
      default:
        break;
    }
    const float e = detail::edge_function(xi, yi, xj, yj);
    const double exact = double(xi) * double(yj) - double(yi) * double(xj);
    ++checked;
    if (xi * yj - yi * xj == 0.0f) ++ties;
    if (sign_of_f(e) != sign_of(exact)) ++wrong;
    // Antisymmetric bit for bit (up to the sign of zero).
    const float r = detail::edge_function(xj, yj, xi, yi);
    if (!(r == -e)) ++wrong;
  }
  report_rate("edge function wrong signs", wrong, checked);
  std::cout << "[numerics] edge function: " << ties << " of " << checked << " cases needed the exact tie-break\n";
  EXPECT_EQ(wrong, 0u);
  EXPECT_GT(ties, checked / 10);  // the tie-break path really ran
}

TEST(NumericsTriangle, ProductErrorIsExact) {
  Pcg32 rng = Pcg32::keyed(2, 1);
  for (int i = 0; i < 200000; ++i) {
    const float a = random_float(rng, -50, 50), b = random_float(rng, -50, 50);
    const float p = a * b;
    const float e = detail::product_error(a, b, p);
    ASSERT_EQ(double(p) + double(e), double(a) * double(b)) << a << " " << b;
    ASSERT_EQ(float_bits(e), float_bits(detail::product_error(b, a, p)));
  }
}

// Random triangles of size `scale` around `center`, rays aimed at points with every
// barycentric >= 0.02 (must hit) or some barycentric <= -0.02 (must miss), from origins at
// distance ~scale. t and barycentrics against the double reference.
struct AccuracyStats {
  uint64_t rays = 0, false_miss = 0, false_hit = 0, bad = 0;
  double max_t_err = 0, max_b_err = 0;
};

AccuracyStats accuracy_run(double scale, double offset, int count, uint64_t seed) {
  Pcg32 rng = Pcg32::keyed(seed, uint64_t(std::log2(scale) + 100));
  AccuracyStats s;
  const Vec3f c{round_f(offset), round_f(-0.75 * offset), round_f(0.5 * offset)};
  auto around = [&](double r) {
    return Vec3f{round_f(double(c.x) + r * (2.0 * rng.uniform() - 1.0)), round_f(double(c.y) + r * (2.0 * rng.uniform() - 1.0)),
                 round_f(double(c.z) + r * (2.0 * rng.uniform() - 1.0))};
  };
  for (int i = 0; i < count; ++i) {
    const Vec3f v0 = around(scale), v1 = around(scale), v2 = around(scale);
    const Vec3f o = around(4.0 * scale);
    // Barycentric target in double, rounded once.
    double w1 = rng.uniform(), w2 = rng.uniform();
    const bool inside = (i % 2) == 0;
    if (inside) {
      w1 = 0.02 + 0.96 * w1;
      w2 = 0.02 + (0.96 - w1 + 0.02) * w2;
    } else {
      w1 = -0.5 * w1 - 0.02;
    }
    const double w0 = 1.0 - w1 - w2;
    const Vec3f target{round_f(w0 * v0.x + w1 * v1.x + w2 * v2.x), round_f(w0 * v0.y + w1 * v1.y + w2 * v2.y),
                       round_f(w0 * v0.z + w1 * v1.z + w2 * v2.z)};
    Vec3f d = target - o;
    if (i % 3 == 0) d = d * 1024.0f;  // direction length must not matter
    const RefHit ref = reference_hit(v0, v1, v2, o, d);
    if (!ref.valid || ref.t <= 0) continue;
    const double bmin = std::min({ref.b0, ref.b1, ref.b2});
    if (std::fabs(bmin) < 0.01) continue;  // rounding of target moved it onto an edge
    // Skip badly conditioned (grazing or sliver) cases; those have their own tests.
    const double n[3] = {(double(v1.y) - v0.y) * (double(v2.z) - v0.z) - (double(v1.z) - v0.z) * (double(v2.y) - v0.y),
                         (double(v1.z) - v0.z) * (double(v2.x) - v0.x) - (double(v1.x) - v0.x) * (double(v2.z) - v0.z),
                         (double(v1.x) - v0.x) * (double(v2.y) - v0.y) - (double(v1.y) - v0.y) * (double(v2.x) - v0.x)};
    const double nl = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double dl = std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z);
    const double cosang = std::fabs(n[0] * d.x + n[1] * d.y + n[2] * d.z) / (nl * dl);
    if (cosang < 0.05 || nl < 0.01 * scale * scale) continue;
    ++s.rays;
    TrianglePartial p;
    const bool hit = triangle_hit_test(v0, v1, v2, o, d, &p);
    if (bmin > 0 && !hit) ++s.false_miss;
    if (bmin < 0 && hit) ++s.false_hit;
    if (!hit || bmin < 0) continue;
    const TriangleHit h = triangle_finish(p);
    if (!(std::isfinite(h.t) && h.t > 0 && h.b1 >= 0 && h.b2 >= 0 && h.b1 <= 1 && h.b2 <= 1)) ++s.bad;
    s.max_t_err = std::max(s.max_t_err, std::fabs(h.t - ref.t) / ref.t);
    s.max_b_err = std::max({s.max_b_err, std::fabs(h.b1 - ref.b1), std::fabs(h.b2 - ref.b2)});
  }
  return s;
}

TEST(NumericsTriangle, AccurateOverScalesAndTranslations) {
  struct Case { double scale, offset; };
  const Case cases[] = {{1e-6, 0}, {1e-6, 1e-3}, {1e-3, 0}, {1e-3, 1}, {1, 0}, {1, 1e3},
                        {1e3, 0}, {1e3, 1e5}, {1e5, 1e5}, {1e6, 0}};
  for (const Case& c : cases) {
    const AccuracyStats s = accuracy_run(c.scale, c.offset, 40000, 9);
    std::ostringstream what;
    what << "scale " << c.scale << " offset " << c.offset;
    std::cout << "[numerics] triangle accuracy " << what.str() << ": " << s.rays << " rays, max rel t err "
              << s.max_t_err << ", max barycentric err " << s.max_b_err << "\n";
    EXPECT_GT(s.rays, 10000u) << what.str();
    EXPECT_EQ(s.false_miss, 0u) << what.str();
    EXPECT_EQ(s.false_hit, 0u) << what.str();
    EXPECT_EQ(s.bad, 0u) << what.str();
    // The float inputs are the truth; the error comes from the float arithmetic only, so
    // it does not grow with scale or translation (the vertices are taken relative to o).
    EXPECT_LT(s.max_t_err, 2e-5) << what.str();
    EXPECT_LT(s.max_b_err, 2e-4) << what.str();
  }
}

// Axis-aligned rays make the projection exact, so the test is the exact closed triangle:
// points exactly on an edge or a vertex hit, one ulp outside misses.
TEST(NumericsTriangle, AxisRaysOnExactEdgesAndVertices) {
  const Vec3f v0{0.0f, 0.0f, 0.0f}, v1{1.0f, 0.0f, 0.0f}, v2{0.0f, 1.0f, 0.0f};
  TrianglePartial p;
  auto hit_at = [&](float x, float y, float dz) {
    return triangle_hit_test(v0, v1, v2, {x, y, dz > 0 ? -2.0f : 2.0f}, {0.0f, -0.0f, dz}, &p);
  };
  for (float dz : {1.0f, -1.0f, 0.5f, -3.0f}) {
    EXPECT_TRUE(hit_at(0.0f, 0.0f, dz));        // vertex
    EXPECT_TRUE(hit_at(1.0f, 0.0f, dz));        // vertex
    EXPECT_TRUE(hit_at(0.25f, 0.75f, dz));      // hypotenuse, exactly
    EXPECT_TRUE(hit_at(0.5f, 0.0f, dz));        // edge y = 0
    EXPECT_TRUE(hit_at(0.0f, 0.5f, dz));        // edge x = 0
    EXPECT_FALSE(hit_at(std::nextafter(0.25f, 1.0f), 0.75f, dz));
    EXPECT_FALSE(hit_at(0.5f, -0x1p-60f, dz));  // tiny, but inside the exact domain
    EXPECT_FALSE(hit_at(-0x1p-60f, 0.5f, dz));
    EXPECT_FALSE(hit_at(1.0f, std::nextafter(0.0f, 1.0f), dz));
    ASSERT_TRUE(hit_at(0.25f, 0.25f, dz));
    const TriangleHit h = triangle_finish(p);
    EXPECT_EQ(h.t, 2.0f / std::fabs(dz));
    EXPECT_EQ(h.b1, 0.25f);
    EXPECT_EQ(h.b2, 0.25f);
  }
  // Along each axis.
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3f w0 = axis == 0 ? Vec3f{0, 0, 0} : axis == 1 ? Vec3f{0, 0, 0} : Vec3f{0, 0, 0};
    const Vec3f w1 = axis == 0 ? Vec3f{0, 1, 0} : axis == 1 ? Vec3f{0, 0, 1} : Vec3f{1, 0, 0};
    const Vec3f w2 = axis == 0 ? Vec3f{0, 0, 1} : axis == 1 ? Vec3f{1, 0, 0} : Vec3f{0, 1, 0};
    const Vec3f dir = axis == 0 ? Vec3f{1, 0, 0} : axis == 1 ? Vec3f{0, 1, 0} : Vec3f{0, 0, 1};
    EXPECT_TRUE(triangle_hit_test(w0, w1, w2, (w1 + w2) * 0.5f - dir, dir, &p)) << axis;  // edge midpoint
    EXPECT_TRUE(triangle_hit_test(w0, w1, w2, w0 - dir * 3.0f, dir, &p)) << axis;          // vertex
    EXPECT_EQ(triangle_finish(p).t, 3.0f);
    EXPECT_FALSE(triangle_hit_test(w0, w1, w2, w0 + dir, dir, &p)) << axis;  // behind the origin
    EXPECT_FALSE(triangle_hit_test(w0, w1, w2, w0, dir, &p)) << axis;        // t = 0 is not a hit
  }
}

// The orientation dot(a, cross(b, c)) of the vertices relative to o, and its permanent (the
// same expression with absolute values), in double: the products of two floats are exact.
struct Orientation {
  double orient, permanent;
};
Orientation orientation(Vec3f v0, Vec3f v1, Vec3f v2, Vec3f o) {
  const double a[3] = {double(v0.x) - o.x, double(v0.y) - o.y, double(v0.z) - o.z};
  const double b[3] = {double(v1.x) - o.x, double(v1.y) - o.y, double(v1.z) - o.z};
  const double c[3] = {double(v2.x) - o.x, double(v2.y) - o.y, double(v2.z) - o.z};
  return {a[2] * (b[0] * c[1] - c[0] * b[1]) + b[2] * (c[0] * a[1] - a[0] * c[1]) + c[2] * (a[0] * b[1] - b[0] * a[1]),
          (std::fabs(b[0] * c[1]) + std::fabs(c[0] * b[1])) * std::fabs(a[2]) +
              (std::fabs(c[0] * a[1]) + std::fabs(a[0] * c[1])) * std::fabs(b[2]) +
              (std::fabs(a[0] * b[1]) + std::fabs(b[0] * a[1])) * std::fabs(c[2])};
}

// Whether o lies within rounding of the plane of (v0, v1, v2): the orientation within twice
// the filter bound of intersect.h's t_exactly_positive.
bool origin_near_plane(Vec3f v0, Vec3f v1, Vec3f v2, Vec3f o) {
  const Orientation r = orientation(v0, v1, v2, o);
  return std::fabs(r.orient) <= 2.0 * double(detail::kOrientError) * r.permanent;
}

// A ray through the shared edge of two triangles (any orientation, any fold angle) hits at
// least one of them: the edge term is computed from the same two projected points with
// opposite orientation, and its sign is exact.
TEST(NumericsTriangle, SharedEdgeNeverLetsARayThrough) {
  Pcg32 rng = Pcg32::keyed(4, 4);
  uint64_t rays = 0, through = 0, through_near_plane = 0;
  for (int i = 0; i < 300000; ++i) {
    const double scale = std::ldexp(1.0, int(rng.below(60)) - 30);
    auto pt = [&] {
      return Vec3f{round_f(scale * (2.0 * rng.uniform() - 1.0)), round_f(scale * (2.0 * rng.uniform() - 1.0)),
                   round_f(scale * (2.0 * rng.uniform() - 1.0))};
    };
    const Vec3f a = pt(), b = pt();
    const Vec3f c = pt();
    Vec3f e = pt();
    const Vec3f o = pt() * 3.0f;
    // Keep c and e on opposite sides of the plane (o, a, b) so the pair is not folded over
    // as seen from o (a silhouette edge may legitimately be missed from both sides).
    const double side_c = double(dot(cross(a - o, b - o), c - o)), side_e = double(dot(cross(a - o, b - o), e - o));
    if (side_c * side_e > 0) e = o + (o - e);  // mirror e through o... then re-check
    const double side_e2 = double(dot(cross(a - o, b - o), e - o));
    if (!(side_c * side_e2 < 0)) continue;
    const float s = rng.uniform();
    const Vec3f target = a + (b - a) * s;
    const Vec3f d = target - o;
    TrianglePartial p;
    const bool h1 = triangle_hit_test(a, b, c, o, d, &p);
    const bool h2 = triangle_hit_test(b, a, e, o, d, &p);
    // Only rays that really go through the edge (in double) between the two triangles.
    const RefHit r1 = reference_hit(a, b, c, o, d), r2 = reference_hit(b, a, e, o, d);
    if (!r1.valid || !r2.valid || r1.t <= 1e-3 || r2.t <= 1e-3) continue;
    if (std::fabs(r1.b2) > 1e-4 || std::min(r1.b0, r1.b1) < 0.01 || std::min(r2.b0, r2.b1) < 0.01) continue;
    ++rays;
    if (h1 || h2) continue;
    // The one documented exception (docs/numerics.md, "Sign of t"): an origin within rounding
    // of a triangle's plane does not hit it, so a ray from the plane of an edge-on neighbour
    // can pass between the two.
    if (origin_near_plane(a, b, c, o) || origin_near_plane(b, a, e, o))
      ++through_near_plane;
    else
      ++through;
  }
  report_rate("rays through a shared edge that hit neither triangle", through, rays);
  report_rate("... of them with the origin within rounding of either plane", through_near_plane, rays);
  EXPECT_GT(rays, 50000u);
  EXPECT_EQ(through, 0u);
  EXPECT_LE(through_near_plane, rays / 10000) << "the near-plane exception is meant to be rare";
}

// A ray whose origin lies in a triangle's plane: the exact t is 0 (or, after the origin's
// rounding, within rounding of 0), and tmin = 0 is open, so a hit may be reported only where
// the exact t is positive. The rounded t_num alone has the wrong sign in about a fifth of these
// rays (before the fix: 19,434 of 200,000 at translation 0 hit at exact t <= 0). The origin is
// a float-rounded point inside the triangle, so every ray's line goes through the triangle and
// only the sign of t decides. The exact sign comes from the orientation in double, where the
// products of two floats are exact; a case it cannot resolve is counted apart.
TEST(NumericsTriangle, OriginInThePlaneNeverHitsAtOrBehindIt) {
  struct Case { double scale, offset; };
  const Case cases[] = {{1, 0}, {1, 1e3}, {1, 1e5}, {1e-3, 0}, {1e-3, 1}, {1e3, 1e5}, {1e-6, 0}};
  for (const Case& c : cases) {
    Pcg32 rng = Pcg32::keyed(13, uint64_t(std::log2(c.scale) + 100) * 31 + uint64_t(std::log10(c.offset + 1)));
    auto pt = [&] {
      return Vec3f{round_f(c.offset + c.scale * (2.0 * rng.uniform() - 1.0)),
                   round_f(-0.5 * c.offset + c.scale * (2.0 * rng.uniform() - 1.0)),
                   round_f(0.25 * c.offset + c.scale * (2.0 * rng.uniform() - 1.0))};
    };
    uint64_t rays = 0, hits = 0, at_or_behind = 0, unresolved = 0;
    for (int i = 0; i < 40000; ++i) {
      const Vec3f v0 = pt(), v1 = pt(), v2 = pt();
      double w1 = rng.uniform(), w2 = rng.uniform();
      if (w1 + w2 > 1) {
        w1 = 1 - w1;
        w2 = 1 - w2;
      }
      auto mix = [&](float p0, float p1, float p2) {
        return round_f(double(p0) + w1 * (double(p1) - p0) + w2 * (double(p2) - p0));
      };
      const Vec3f o{mix(v0.x, v1.x, v2.x), mix(v0.y, v1.y, v2.y), mix(v0.z, v1.z, v2.z)};
      const Vec3f d = random_unit(rng);
      ++rays;
      TrianglePartial p;
      if (!triangle_hit_test(v0, v1, v2, o, d, &p)) continue;
      ++hits;
      const Orientation r = orientation(v0, v1, v2, o);
      // t = orient / dot(n, d), n = cross(v1 - v0, v2 - v0).
      const double e1[3] = {double(v1.x) - v0.x, double(v1.y) - v0.y, double(v1.z) - v0.z};
      const double e2[3] = {double(v2.x) - v0.x, double(v2.y) - v0.y, double(v2.z) - v0.z};
      const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
      const double nd = n[0] * d.x + n[1] * d.y + n[2] * d.z;
      if (std::fabs(r.orient) <= 1e-14 * r.permanent) {
        ++unresolved;
      } else if (!(r.orient / nd > 0)) {
        ++at_or_behind;
      }
    }
    std::ostringstream what;
    what << "scale " << c.scale << " offset " << c.offset;
    std::cout << "[numerics] origin in the plane, " << what.str() << ": " << hits << " of " << rays
              << " rays hit, " << at_or_behind << " at exact t <= 0, " << unresolved << " unresolved in double\n";
    EXPECT_EQ(at_or_behind, 0u) << what.str();
    EXPECT_EQ(unresolved, 0u) << what.str();
    // Without translation the rounded origin stays within rounding of the plane: almost no hit.
    if (c.offset == 0) {
      EXPECT_LT(hits, rays / 20) << what.str();
    }
  }
}

// An axis-aligned triangle and an origin exactly in its plane: orient is an exact 0, so no
// direction hits, whatever the projection's rounding makes of t_num.
TEST(NumericsTriangle, OriginExactlyInAnAxisPlaneNeverHits) {
  Pcg32 rng = Pcg32::keyed(14, 1);
  uint64_t hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const float z = round_f(1e5 * (2.0 * rng.uniform() - 1.0));
    const Vec3f v0{0.0f, 0.0f, z}, v1{1.0f, 0.0f, z}, v2{0.0f, 1.0f, z};
    const Vec3f o{round_f(0.3 * rng.uniform()), round_f(0.3 * rng.uniform()), z};
    TrianglePartial p;
    if (triangle_hit_test(v0, v1, v2, o, random_unit(rng), &p)) ++hits;
  }
  EXPECT_EQ(hits, 0u);
}

// Duplicate vertices: one term is an exact zero and the other two exact negatives of each
// other, so the triangle can only "hit" with det == 0, which is a miss. Never a hit.
TEST(NumericsTriangle, DuplicateVertexTrianglesNeverHit) {
  Pcg32 rng = Pcg32::keyed(5, 5);
  uint64_t hits = 0, rays = 0;
  for (int i = 0; i < 200000; ++i) {
    const double scale = std::ldexp(1.0, int(rng.below(50)) - 25);
    const Vec3f a{round_f(scale * rng.uniform()), round_f(scale * rng.uniform()), round_f(scale * rng.uniform())};
    const Vec3f b{round_f(scale * rng.uniform()), round_f(scale * rng.uniform()), round_f(scale * rng.uniform())};
    const Vec3f o{round_f(scale * (4 * rng.uniform() - 2)), round_f(scale * (4 * rng.uniform() - 2)),
                  round_f(scale * (4 * rng.uniform() - 2))};
    Vec3f target = i % 3 == 0 ? a : (i % 3 == 1 ? b : a + (b - a) * rng.uniform());
    const Vec3f d = target - o;
    TrianglePartial p;
    const Vec3f tris[4][3] = {{a, a, b}, {a, b, a}, {b, a, a}, {a, a, a}};
    for (const auto& t : tris) {
      ++rays;
      if (triangle_hit_test(t[0], t[1], t[2], o, d, &p)) ++hits;
    }
  }
  report_rate("duplicate-vertex triangles hit", hits, rays);
  EXPECT_EQ(hits, 0u);
}

// Exactly collinear vertices (v2 the exact midpoint) and needles. A zero-area triangle can
// only be "hit" by a ray through it within rounding; such a hit is never garbage: finite
// t > 0 inside the segment's extent along the ray, barycentrics in [0, 1]. Needles of width
// 1e-4 of their length, not seen edge-on, hit like any triangle.
TEST(NumericsTriangle, CollinearAndNeedleTrianglesGiveNoGarbage) {
  Pcg32 rng = Pcg32::keyed(6, 6);
  uint64_t collinear_rays = 0, collinear_hits = 0, garbage = 0, needle_rays = 0, needle_misses = 0;
  for (int i = 0; i < 200000; ++i) {
    const double scale = std::ldexp(1.0, int(rng.below(40)) - 20);
    const Vec3f a{round_f(scale * int(rng.below(64))), round_f(scale * int(rng.below(64))), round_f(scale * int(rng.below(64)))};
    Vec3f b{round_f(scale * int(rng.below(64))), round_f(scale * int(rng.below(64))), round_f(scale * int(rng.below(64)))};
    if (i % 2) b = a + (b - a) * 2.0f;  // even differences: the midpoint is exact
    const Vec3f m = (a + b) * 0.5f;
    const Vec3f o{round_f(scale * (160 * rng.uniform() - 48)), round_f(scale * (160 * rng.uniform() - 48)),
                  round_f(scale * (160 * rng.uniform() - 48))};
    const Vec3f target = a + (b - a) * rng.uniform();
    const Vec3f d = target - o;
    TrianglePartial p;
    ++collinear_rays;
    if (triangle_hit_test(a, b, m, o, d, &p)) {
      ++collinear_hits;
      const TriangleHit h = triangle_finish(p);
      const double b0 = 1.0 - double(h.b1) - h.b2;
      const bool ok = std::isfinite(h.t) && h.t > 0 && h.b1 >= 0 && h.b2 >= 0 && h.b1 <= 1 && h.b2 <= 1 && b0 >= -1e-6;
      // The weights of a zero-area triangle are rounding noise, so t is some convex
      // combination of the vertex depths: inside the segment's extent along the ray.
      const double dd = double(dot(d, d));
      const double ta = double(dot(a - o, d)) / dd, tb = double(dot(b - o, d)) / dd;
      const double lo = std::min(ta, tb), hi = std::max(ta, tb), slack = 1e-5 * (std::fabs(ta) + std::fabs(tb));
      if (!ok || h.t < lo - slack || h.t > hi + slack) ++garbage;
    }
    // Needle: width 1e-4 of the length, aimed at its centre line.
    const Vec3f ab = b - a;
    const Vec3f side = cross(ab, Vec3f{0.3f, -0.5f, 0.8f});
    const double sl = std::sqrt(double(dot(side, side))), abl = std::sqrt(double(dot(ab, ab)));
    if (sl == 0 || abl == 0) continue;
    const Vec3f c = m + side * round_f(1e-4 * abl / sl);
    const Vec3f nt = (a + (b - a) * (0.1f + 0.8f * rng.uniform())) + (c - m) * 0.3f;
    const RefHit ref = reference_hit(a, b, c, o, nt - o);
    if (!ref.valid || ref.t <= 0 || std::min({ref.b0, ref.b1, ref.b2}) < 0.05) continue;
    // Not seen edge-on: the needle's normal and the ray at least 3 degrees from perpendicular.
    const Vec3f nn = cross(b - a, c - a), nd = nt - o;
    const double cosang = std::fabs(double(dot(nn, nd))) /
                          std::sqrt(double(dot(nn, nn)) * double(dot(nd, nd)));
    if (!(cosang > 0.05)) continue;
    ++needle_rays;
    if (!triangle_hit_test(a, b, c, o, nt - o, &p)) ++needle_misses;
  }
  report_rate("exactly collinear triangles hit (rays aimed at the segment)", collinear_hits, collinear_rays);
  report_rate("collinear-triangle hits with garbage t or barycentrics", garbage, collinear_hits);
  report_rate("needle triangles missed (rays aimed inside)", needle_misses, needle_rays);
  EXPECT_EQ(garbage, 0u);
  EXPECT_GT(needle_rays, 50000u);
  EXPECT_EQ(needle_misses, 0u);
}

// Grazing rays, 1e-1 .. 1e-6 radians off the triangle's plane, aimed at interior points:
// always hit; t degrades like rounding / sin(angle), as the problem's condition says.
TEST(NumericsTriangle, GrazingRaysHitWithConditionBoundedError) {
  Pcg32 rng = Pcg32::keyed(7, 7);
  for (double angle : {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6}) {
    uint64_t rays = 0, misses = 0;
    double max_err = 0;
    for (int i = 0; i < 20000; ++i) {
      const Vec3f v0{0.0f, 0.0f, 0.0f}, v1{1.0f, 0.1f, 0.0f}, v2{0.2f, 1.0f, 0.05f};
      const double w1 = 0.1 + 0.4 * rng.uniform(), w2 = 0.1 + 0.4 * rng.uniform();
      const double P[3] = {w1 * v1.x + w2 * v2.x, w1 * v1.y + w2 * v2.y, w1 * v1.z + w2 * v2.z};
      // In-plane direction at a random azimuth, tilted by `angle`, in double.
      const double e1[3] = {1.0, 0.1, 0.0}, e2[3] = {0.2, 1.0, 0.05};
      double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
      const double nl = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      for (double& x : n) x /= nl;
      double u[3] = {e1[0], e1[1], e1[2]};
      const double ul = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
      for (double& x : u) x /= ul;
      const double w[3] = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
      const double phi = 6.283185307179586 * rng.uniform();
      const double side = rng.below(2) ? 1.0 : -1.0;
      double dd[3];
      for (int k = 0; k < 3; ++k)
        dd[k] = std::cos(angle) * (std::cos(phi) * u[k] + std::sin(phi) * w[k]) + side * std::sin(angle) * n[k];
      const double dist = 2.0;
      const Vec3f o{round_f(P[0] - dist * dd[0]), round_f(P[1] - dist * dd[1]), round_f(P[2] - dist * dd[2])};
      const Vec3f d{round_f(dd[0]), round_f(dd[1]), round_f(dd[2])};
      const RefHit ref = reference_hit(v0, v1, v2, o, d);
      if (!ref.valid || std::min({ref.b0, ref.b1, ref.b2}) < 0.02) continue;
      ++rays;
      TrianglePartial p;
      if (!triangle_hit_test(v0, v1, v2, o, d, &p)) {
        ++misses;
        continue;
      }
      max_err = std::max(max_err, std::fabs(triangle_finish(p).t - ref.t) / ref.t);
    }
    std::cout << "[numerics] grazing angle " << angle << ": " << misses << " misses of " << rays
              << ", max rel t err " << max_err << "\n";
    EXPECT_GT(rays, 10000u);
    EXPECT_EQ(misses, 0u) << angle;
    EXPECT_LT(max_err, 1e-6 + 2e-7 / angle) << angle;
  }
}

// A ray lying in the triangle's plane: ill-posed. Reported or not, a hit is never garbage:
// finite t > 0 within the triangle's extent along the ray, barycentrics in [0, 1].
TEST(NumericsTriangle, CoplanarRaysGiveMissOrBoundedHit) {
  Pcg32 rng = Pcg32::keyed(8, 8);
  uint64_t rays = 0, hits = 0, garbage = 0;
  for (int i = 0; i < 200000; ++i) {
    // A triangle in the plane z = 0.25 x + 0.5 y (exactly representable points), rays in it.
    // Half the cases in an exactly representable plane (every term exactly zero), half in
    // z = 0.3 x + 0.7 y with rounded points (coplanar only up to rounding).
    const bool exact_plane = i % 2 == 0;
    auto on_plane = [&](float x, float y) {
      return exact_plane ? Vec3f{x, y, 0.25f * x + 0.5f * y} : Vec3f{x, y, round_f(0.3 * x + 0.7 * y)};
    };
    auto q = [&] {
      return exact_plane ? round_f(int(rng.below(256)) - 128) * 0.0625f : round_f(16.0 * rng.uniform() - 8.0);
    };
    const Vec3f v0 = on_plane(q(), q()), v1 = on_plane(q(), q()), v2 = on_plane(q(), q());
    const Vec3f o = on_plane(q(), q());
    const Vec3f target = i % 4 < 2 ? v0 : on_plane(q(), q());
    const Vec3f d = target - o;
    TrianglePartial p;
    ++rays;
    if (!triangle_hit_test(v0, v1, v2, o, d, &p)) continue;
    ++hits;
    const TriangleHit h = triangle_finish(p);
    const double dd = double(dot(d, d));
    double lo = 1e300, hi = -1e300;
    for (const Vec3f& v : {v0, v1, v2}) {
      const double proj = double(dot(v - o, d)) / dd;
      lo = std::min(lo, proj);
      hi = std::max(hi, proj);
    }
    const bool ok = std::isfinite(h.t) && h.t > 0 && h.b1 >= 0 && h.b2 >= 0 && h.b1 <= 1.0f + 1e-6f &&
                    h.b2 <= 1.0f + 1e-6f && h.t >= lo * (1 - 1e-5) && h.t <= hi * (1 + 1e-5);
    if (!ok) ++garbage;
  }
  report_rate("coplanar rays reported as hits", hits, rays);
  report_rate("coplanar hits outside the triangle's extent or with bad barycentrics", garbage, hits);
  EXPECT_EQ(garbage, 0u);
}

TEST(NumericsTriangle, NonFiniteInputNeverHits) {
  const Vec3f v0{-1.0f, -1.0f, 0.0f}, v1{1.0f, -1.0f, 0.0f}, v2{0.0f, 1.0f, 0.0f};
  const Vec3f o{0.0f, 0.0f, -1.0f}, d{0.0f, 0.1f, 1.0f};
  TrianglePartial p;
  ASSERT_TRUE(triangle_hit_test(v0, v1, v2, o, d, &p));
  uint64_t cases = 0, hits = 0;
  for (int which = 0; which < 5; ++which)
    for (int axis = 0; axis < 3; ++axis)
      for (float bad : {kNaN, kInf, -kInf}) {
        Vec3f in[5] = {v0, v1, v2, o, d};
        (axis == 0 ? in[which].x : axis == 1 ? in[which].y : in[which].z) = bad;
        ++cases;
        if (triangle_hit_test(in[0], in[1], in[2], in[3], in[4], &p)) ++hits;
      }
  EXPECT_EQ(hits, 0u) << "of " << cases;
  // Overflow inside the arithmetic (finite but huge input) is a miss, never inf or NaN.
  const Vec3f big{3e38f, 3e38f, 0.0f};
  EXPECT_FALSE(triangle_hit_test(v0 * 1e30f, v1 * 1e30f, big, o, d, &p));
  // Zero direction.
  EXPECT_FALSE(triangle_hit_test(v0, v1, v2, o, {0.0f, 0.0f, 0.0f}, &p));
}

// The length of the direction does not change the decision, and scales t exactly.
TEST(NumericsTriangle, DirectionLengthOnlyScalesT) {
  Pcg32 rng = Pcg32::keyed(10, 10);
  for (int i = 0; i < 50000; ++i) {
    const Vec3f v0 = random_unit(rng), v1 = random_unit(rng), v2 = random_unit(rng);
    const Vec3f o = random_unit(rng) * 3.0f;
    const Vec3f d = (v0 * 0.4f + v1 * 0.3f + v2 * 0.3f) - o;
    TrianglePartial p, q;
    const bool h = triangle_hit_test(v0, v1, v2, o, d, &p);
    for (float s : {0x1p-40f, 0.5f, 2.0f, 0x1p+40f}) {
      ASSERT_EQ(h, triangle_hit_test(v0, v1, v2, o, d * s, &q));
      if (!h) continue;
      ASSERT_EQ(float_bits(p.e0), float_bits(q.e0));
      ASSERT_EQ(float_bits(p.e1), float_bits(q.e1));
      ASSERT_EQ(float_bits(p.e2), float_bits(q.e2));
      ASSERT_EQ(triangle_finish(q).t, triangle_finish(p).t / s);
    }
  }
}

// The sign convention of the terms is the Plücker one: det has the sign of dot(dir, N) with
// N = cross(v1 - v0, v2 - v0), so det < 0 means the ray meets the front (counter-clockwise)
// face. Callers may rely on it for facing.
TEST(NumericsTriangle, DetSignIsFacing) {
  Pcg32 rng = Pcg32::keyed(11, 11);
  int checked = 0;
  for (int i = 0; i < 50000; ++i) {
    const Vec3f v0 = random_unit(rng), v1 = random_unit(rng), v2 = random_unit(rng);
    const Vec3f o = random_unit(rng) * 3.0f;
    const Vec3f d = ((v0 * 0.4f + v1 * 0.3f) + v2 * 0.3f) - o;
    TrianglePartial p;
    if (!triangle_hit_test(v0, v1, v2, o, d, &p)) continue;
    const RefHit ref = reference_hit(v0, v1, v2, o, d);
    (void)ref;
    const Vec3f e1 = v1 - v0, e2 = v2 - v0;
    const double nx = double(e1.y) * e2.z - double(e1.z) * e2.y, ny = double(e1.z) * e2.x - double(e1.x) * e2.z,
                 nz = double(e1.x) * e2.y - double(e1.y) * e2.x;
    const double facing = nx * d.x + ny * d.y + nz * d.z;
    if (std::fabs(facing) < 1e-3) continue;
    ++checked;
    ASSERT_EQ(sign_of_f((p.e0 + p.e1) + p.e2), sign_of(facing));
  }
  EXPECT_GT(checked, 10000);
}

}  // namespace
}  // namespace strata::numerics
