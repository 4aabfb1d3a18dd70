// trace_rays against the small procedural Cornell box: the same hits as calling
// trace_closest directly, and as a brute-force loop over every triangle of the scene.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

#include <glm/geometric.hpp>

#include "firmware/common/traverse.h"
#include "scenes/procedural/procedural.h"
#include "scenes/scene_image.h"
#include "sim/ray_file.h"

namespace strata::sim {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

// The closest hit over all triangles in scene order, by the same rule as the traversal:
// tmin < t < tmax, strictly closer wins.
HitRecord brute_force(const scenes::Scene& scene, const RayRecord& r) {
  HitRecord best{kInf, kMissPrimitive, 0.0f, 0.0f};
  if (!ray_is_valid(r)) return best;
  const Vec3f o{r.origin[0], r.origin[1], r.origin[2]};
  const Vec3f d{r.dir[0], r.dir[1], r.dir[2]};
  float tmax = r.tmax;
  for (size_t i = 0; i < scene.triangles.size(); ++i) {
    const scenes::Triangle& tri = scene.triangles[i];
    TrianglePartial p;
    if (!triangle_hit_test({tri.v0.x, tri.v0.y, tri.v0.z}, {tri.v1.x, tri.v1.y, tri.v1.z},
                           {tri.v2.x, tri.v2.y, tri.v2.z}, o, d, &p))
      continue;
    const TriangleHit h = triangle_finish(p);
    if (h.t > r.tmin && h.t < tmax) {
      best = {h.t, uint32_t(i), h.b1, h.b2};
      tmax = h.t;
    }
  }
  return best;
}

class TraceRays : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = std::make_unique<scenes::Scene>(scenes::make_cornell({0.3, 1}));
    image_ = std::make_unique<scenes::SceneImage>(
        scenes::build_scene_image(*scene_, scenes::SceneImageParams{}, nullptr));
  }
  static void TearDownTestSuite() {
    image_.reset();
    scene_.reset();
  }

  // Random rays, then for each of the first hits two rays that cut the interval at the hit:
  // tmax = t (must not report that hit) and tmin = t (must find something farther).
  static std::vector<RayRecord> test_rays(uint32_t count) {
    std::vector<RayRecord> rays = generate_random_rays(scene_->bounds(), count, 7);
    const std::vector<HitRecord> first = trace_rays(*image_, rays, nullptr);
    for (size_t i = 0; i < first.size() && i < 2000; ++i) {
      if (first[i].primitive == kMissPrimitive) continue;
      RayRecord before = rays[i], beyond = rays[i];
      before.tmax = first[i].t;
      beyond.tmin = first[i].t;
      rays.push_back(before);
      rays.push_back(beyond);
    }
    return rays;
  }

  static std::unique_ptr<scenes::Scene> scene_;
  static std::unique_ptr<scenes::SceneImage> image_;
};
std::unique_ptr<scenes::Scene> TraceRays::scene_;
std::unique_ptr<scenes::SceneImage> TraceRays::image_;

TEST_F(TraceRays, SameHitsAsTraceClosestDirectly) {
  const auto rays = test_rays(20000);
  TraceStats stats;
  const auto hits = trace_rays(*image_, rays, &stats);
  ASSERT_EQ(hits.size(), rays.size());
  uint64_t expected_hits = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const RayRecord& r = rays[i];
    NullObserver obs;
    const ClosestHit h = trace_closest(*image_, image_->header().root_node,
                                       TraceRay{{r.origin[0], r.origin[1], r.origin[2]},
                                                {r.dir[0], r.dir[1], r.dir[2]}, r.tmin, r.tmax},
                                       obs);
    if (!h.hit) {
      EXPECT_EQ(hits[i].primitive, kMissPrimitive) << "ray " << i;
      EXPECT_EQ(hits[i].t, kInf) << "ray " << i;
      EXPECT_EQ(hits[i].b1, 0.0f);
      EXPECT_EQ(hits[i].b2, 0.0f);
      continue;
    }
    ++expected_hits;
    EXPECT_EQ(hits[i].primitive, h.primitive) << "ray " << i;
    EXPECT_EQ(bits(hits[i].t), bits(h.t)) << "ray " << i;
    EXPECT_EQ(bits(hits[i].b1), bits(h.b1)) << "ray " << i;
    EXPECT_EQ(bits(hits[i].b2), bits(h.b2)) << "ray " << i;
  }
  EXPECT_EQ(stats.rays, rays.size());
  EXPECT_EQ(stats.hits, expected_hits);
  EXPECT_EQ(stats.misses, rays.size() - expected_hits);
  EXPECT_EQ(stats.invalid, 0u);
  // Rays start inside the box (open only at the front), so most hit.
  EXPECT_GT(stats.hits, rays.size() / 2);
  EXPECT_GE(stats.node_visits, rays.size());  // every ray reads the root at least
  EXPECT_GT(stats.triangle_tests, 0u);
}

TEST_F(TraceRays, SameHitsAsBruteForce) {
  const auto rays = test_rays(20000);
  const auto hits = trace_rays(*image_, rays, nullptr);
  uint64_t ties = 0, hit_count = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const HitRecord want = brute_force(*scene_, rays[i]);
    const HitRecord& got = hits[i];
    ASSERT_EQ(got.primitive == kMissPrimitive, want.primitive == kMissPrimitive) << "ray " << i;
    if (want.primitive == kMissPrimitive) continue;
    ++hit_count;
    ASSERT_LT(got.primitive, scene_->triangles.size());
    EXPECT_EQ(bits(got.t), bits(want.t)) << "ray " << i;
    if (got.primitive == want.primitive) {
      EXPECT_EQ(bits(got.b1), bits(want.b1)) << "ray " << i;
      EXPECT_EQ(bits(got.b2), bits(want.b2)) << "ray " << i;
    } else {
      // Equally close triangles (a shared edge): the other one must really be hit at that t.
      ++ties;
      RayRecord only = rays[i];
      scenes::Scene one;
      one.triangles = {scene_->triangles[got.primitive]};
      const HitRecord alone = brute_force(one, only);
      EXPECT_EQ(bits(alone.t), bits(got.t)) << "ray " << i;
    }
  }
  EXPECT_GT(hit_count, rays.size() / 2);
  EXPECT_LT(ties, hit_count / 100 + 1);
  // The tmax = t / tmin = t rays cover the interval rule, so brute force matters there too.
  for (size_t i = 20000; i < rays.size(); i += 2)
    EXPECT_TRUE(hits[i].primitive == kMissPrimitive || hits[i].t < rays[i].tmax) << "ray " << i;
}

// A ray straight at the centroid of triangle k reports primitive k: the ids index the scene.
TEST_F(TraceRays, PrimitiveIdsIndexTheSceneTriangles) {
  std::vector<RayRecord> rays;
  std::vector<uint32_t> target;
  for (uint32_t k = 0; k < scene_->triangles.size(); k += 7) {
    const scenes::Triangle& t = scene_->triangles[k];
    const glm::vec3 c = (t.v0 + t.v1 + t.v2) / 3.0f;
    const glm::vec3 n = glm::normalize(glm::cross(t.v1 - t.v0, t.v2 - t.v0));
    // 1e-4 off the surface: the lamp panel hangs 1e-3 under the ceiling.
    const glm::vec3 o = c + n * 1e-4f;
    rays.push_back({{o.x, o.y, o.z}, {-n.x, -n.y, -n.z}, 0.0f, 2e-4f});
    target.push_back(k);
  }
  const auto hits = trace_rays(*image_, rays, nullptr);
  for (size_t i = 0; i < rays.size(); ++i) {
    EXPECT_EQ(hits[i].primitive, target[i]) << "ray " << i;
    EXPECT_NEAR(hits[i].t, 1e-4f, 1e-5f);
    EXPECT_NEAR(hits[i].b1, 1.0f / 3.0f, 1e-3f);
    EXPECT_NEAR(hits[i].b2, 1.0f / 3.0f, 1e-3f);
  }
}

// A flat mesh: `trace --generate` draws origins inside the scene's bounds, which have no
// thickness across the plane, so every origin lies exactly in it and no ray can hit anything
// at t > 0 (tmin = 0 is open). Before the sign of t was decided conservatively, 38% of such
// rays reported a hit at t of about 1e-11 to 1e-8. Each axis, at the origin and translated
// by 1e5.
TEST(TracePlanarMesh, OriginsInThePlaneHitNothing) {
  for (int axis = 0; axis < 3; ++axis) {
    for (float offset : {0.0f, 1e5f}) {
      scenes::Scene scene;
      scene.materials.resize(1);
      auto at = [&](float u, float v) {
        glm::vec3 p;
        p[axis] = offset;
        p[(axis + 1) % 3] = offset + u;
        p[(axis + 2) % 3] = offset - 0.75f * v;
        return p;
      };
      for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) {
          const float u0 = 0.125f * float(i), u1 = u0 + 0.125f, w0 = 0.125f * float(j), w1 = w0 + 0.125f;
          scene.triangles.push_back({at(u0, w0), at(u1, w0), at(u1, w1), 0});
          scene.triangles.push_back({at(u0, w0), at(u1, w1), at(u0, w1), 0});
        }
      const scenes::SceneImage image = scenes::build_scene_image(scene, scenes::SceneImageParams{}, nullptr);
      const std::vector<RayRecord> rays = generate_random_rays(scene.bounds(), 20000, 11);
      TraceStats stats;
      trace_rays(image, rays, &stats);
      EXPECT_EQ(stats.rays, 20000u);
      EXPECT_EQ(stats.hits, 0u) << "axis " << axis << " offset " << offset;
    }
  }
}

TEST_F(TraceRays, InvalidRaysAreCountedMisses) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<RayRecord> rays = generate_random_rays(scene_->bounds(), 10, 3);
  rays[2].origin[1] = nan;
  rays[4].dir[0] = rays[4].dir[1] = rays[4].dir[2] = 0.0f;
  rays[5].tmin = -1.0f;
  rays[7].tmin = 5.0f;
  rays[7].tmax = 4.0f;
  rays[9].tmax = nan;
  TraceStats stats;
  const auto hits = trace_rays(*image_, rays, &stats);
  EXPECT_EQ(stats.invalid, 5u);
  EXPECT_EQ(stats.first_invalid, 2u);
  EXPECT_EQ(stats.hits + stats.misses, 10u);
  for (size_t i : {2u, 4u, 5u, 7u, 9u}) {
    EXPECT_EQ(hits[i].primitive, kMissPrimitive) << "ray " << i;
    EXPECT_EQ(hits[i].t, kInf);
  }
  // The valid rays get exactly the hits they get when traced alone.
  uint64_t valid_hits = 0;
  for (size_t i : {0u, 1u, 3u, 6u, 8u}) {
    const auto alone = trace_rays(*image_, {rays[i]}, nullptr);
    EXPECT_EQ(hits[i].primitive, alone[0].primitive) << "ray " << i;
    EXPECT_EQ(bits(hits[i].t), bits(alone[0].t)) << "ray " << i;
    valid_hits += alone[0].primitive != kMissPrimitive;
  }
  EXPECT_EQ(stats.hits, valid_hits);
  EXPECT_GT(valid_hits, 0u);

  TraceStats none;
  trace_rays(*image_, {}, &none);
  EXPECT_EQ(none.rays, 0u);
  EXPECT_EQ(none.first_invalid, UINT64_MAX);
}

}  // namespace
}  // namespace strata::sim
