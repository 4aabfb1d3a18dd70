// Leak tests: rays from inside closed meshes must always find a hit, by brute force over
// every triangle and by BVH traversal of a scene image. Rays are random, aimed exactly at
// vertices (the high-valence apices of the double cone included) and at points of edges,
// over scales 1e-6 .. 1e6 and translations up to 1e5. Measured rates go to stdout
// ("[numerics] ...") and to the test's XML properties; docs/numerics.md quotes them.
#include <gtest/gtest.h>

#include "numerics_support.h"

namespace strata::numerics {
namespace {

enum class Region { ball, cube, double_cone };

struct LeakCase {
  double scale;
  Vec3f offset;
};

// Translations go along a direction with no zero component, so every axis is exercised.
Vec3f offset_of(double t) { return {round_f(t), round_f(-0.75 * t), round_f(0.5 * t)}; }

const std::vector<LeakCase>& leak_cases() {
  static const std::vector<LeakCase> cases = {
      {1e-6, offset_of(0)},  {1e-3, offset_of(0)}, {1e-3, offset_of(1)}, {1.0, offset_of(0)},
      {1.0, offset_of(1e3)}, {1e3, offset_of(0)},  {1e3, offset_of(1e5)}, {1e5, offset_of(1e5)},
      {1e6, offset_of(0)}};
  return cases;
}

// A point strictly inside the unit-size mesh, in its own coordinates.
std::array<double, 3> inside_point(Region region, Pcg32& rng) {
  for (;;) {
    const double x = 2.0 * rng.uniform() - 1.0, y = 2.0 * rng.uniform() - 1.0,
                 z = 2.0 * rng.uniform() - 1.0;
    switch (region) {
      case Region::ball:  // the level-3 icosphere contains the ball of radius 0.98
        if (x * x + y * y + z * z <= 0.81) return {x, y, z};
        break;
      case Region::cube:
        return {0.95 * x, 0.95 * y, 0.95 * z};
      case Region::double_cone:  // the cone is r <= 1 - |z| (ring polygon radius ~1)
        if (std::sqrt(x * x + y * y) <= 0.9 * (1.0 - std::fabs(z))) return {x, y, z};
        break;
    }
  }
}

struct LeakCounts {
  uint64_t rays = 0, brute_leaks = 0, bvh_leaks = 0, bvh_farther = 0;
  double max_farther = 0.0;  // largest (t_bvh - t_brute) / t_brute seen
};

// Shoots `rays` rays from inside `unit` transformed by (scale, offset). A third of them go in
// random directions, a third at vertices (for the double cone half of these at an apex), a
// third at points of edges (for the double cone mostly edges from an apex).
LeakCounts count_leaks(const Mesh& unit, Region region, const LeakCase& c, uint32_t rays, uint64_t seed) {
  const Mesh mesh = unit.transformed(c.scale, c.offset);
  const std::vector<scenes::Triangle> tris = mesh.triangles();
  const scenes::SceneImage img = scenes::build_scene_image(mesh_scene(mesh, "leak"), {}, nullptr);
  Pcg32 rng = Pcg32::keyed(seed, uint64_t(c.scale * 1e6) ^ float_bits(c.offset.x));
  LeakCounts n;
  for (uint32_t r = 0; r < rays; ++r) {
    const auto p = inside_point(region, rng);
    const Vec3f o{round_f(p[0] * c.scale + double(c.offset.x)), round_f(p[1] * c.scale + double(c.offset.y)),
                  round_f(p[2] * c.scale + double(c.offset.z))};
    Vec3f d{};
    const uint32_t kind = r % 3;
    if (kind == 0) {
      d = random_unit(rng);
    } else if (kind == 1) {
      const uint32_t vi = (region == Region::double_cone && rng.below(2) == 0)
                              ? rng.below(2)
                              : rng.below(uint32_t(mesh.v.size()));
      d = mesh.v[vi] - o;
    } else {
      const auto& f = mesh.f[rng.below(uint32_t(mesh.f.size()))];
      const uint32_t e = rng.below(3);
      const Vec3f a = mesh.v[f[e]], b = mesh.v[f[(e + 1) % 3]];
      const float s = rng.uniform();
      d = (a + (b - a) * s) - o;
    }
    const TraceRay ray{o, d, 0.0f, INFINITY};
    const ClosestHit bf = brute_force(tris, ray);
    const ClosestHit tr = trace(img, ray);
    ++n.rays;
    if (!bf.hit) ++n.brute_leaks;
    if (!tr.hit) ++n.bvh_leaks;
    if (bf.hit && tr.hit && tr.t > bf.t) {
      const double rel = (double(tr.t) - double(bf.t)) / double(bf.t);
      if (rel > n.max_farther) n.max_farther = rel;
      if (!same_point(o, d, bf.t, tr.t)) ++n.bvh_farther;
    }
  }
  return n;
}

std::string case_name(const char* mesh, const LeakCase& c) {
  std::ostringstream s;
  s << mesh << " scale " << c.scale << " offset (" << c.offset.x << ", " << c.offset.y << ", " << c.offset.z << ")";
  return s.str();
}

void run_mesh(const char* name, const Mesh& unit, Region region, uint32_t rays_per_case) {
  uint64_t total = 0, brute = 0, bvh = 0, farther = 0;
  for (const LeakCase& c : leak_cases()) {
    const LeakCounts n = count_leaks(unit, region, c, rays_per_case, 2024);
    const std::string what = case_name(name, c);
    report_rate(what + " brute-force leaks", n.brute_leaks, n.rays);
    report_rate(what + " BVH leaks", n.bvh_leaks, n.rays);
    std::cout << "[numerics] " << what << " max (t_bvh - t_brute)/t_brute = " << n.max_farther << "\n";
    if (n.bvh_farther) report_rate(what + " BVH hit farther than brute force", n.bvh_farther, n.rays);
    EXPECT_EQ(n.brute_leaks, 0u) << what;
    EXPECT_EQ(n.bvh_leaks, 0u) << what;
    EXPECT_EQ(n.bvh_farther, 0u) << what;
    total += n.rays;
    brute += n.brute_leaks;
    bvh += n.bvh_leaks;
    farther += n.bvh_farther;
  }
  report_rate(std::string(name) + " all cases brute-force leaks", brute, total);
  report_rate(std::string(name) + " all cases BVH leaks", bvh, total);
}

TEST(NumericsLeak, IcosphereHasNoLeaks) {
  run_mesh("icosphere(1280 tris)", icosphere(3), Region::ball, 12000);
}

TEST(NumericsLeak, TwelveTriangleBoxHasNoLeaks) {
  run_mesh("box(12 tris)", box12(), Region::cube, 40000);
}

TEST(NumericsLeak, HighValenceDoubleConeHasNoLeaks) {
  run_mesh("double cone(2000 tris, valence 1000)", double_cone(1000), Region::double_cone, 10000);
}

// Rays from points on the cone's axis exactly at an apex: every apex edge term is an exact
// zero or a rounding-level value, the case where per-triangle rounding would let a ray slip
// between 1000 triangles.
TEST(NumericsLeak, AxisRaysAtHighValenceApex) {
  const Mesh unit = double_cone(1000);
  uint64_t rays = 0, leaks = 0;
  for (const LeakCase& c : leak_cases()) {
    const Mesh mesh = unit.transformed(c.scale, c.offset);
    const std::vector<scenes::Triangle> tris = mesh.triangles();
    const scenes::SceneImage img = scenes::build_scene_image(mesh_scene(mesh, "apex"), {}, nullptr);
    Pcg32 rng = Pcg32::keyed(5, float_bits(round_f(c.scale)));
    for (int i = 0; i < 400; ++i) {
      const double z = 1.8 * rng.uniform() - 0.9;
      const Vec3f o{c.offset.x, c.offset.y, round_f(z * c.scale + double(c.offset.z))};
      for (uint32_t apex = 0; apex < 2; ++apex) {
        const TraceRay ray{o, mesh.v[apex] - o, 0.0f, INFINITY};
        ++rays;
        if (!brute_force(tris, ray).hit) ++leaks;
        if (!trace(img, ray).hit) ++leaks;
      }
    }
  }
  report_rate("double cone apex rays from the axis (brute force + BVH)", leaks, 2 * rays);
  EXPECT_EQ(leaks, 0u);
}

}  // namespace
}  // namespace strata::numerics
