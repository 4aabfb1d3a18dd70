// BVH invariants on the built scene image: every triangle reachable exactly once, child
// boxes nested in their parent's, consistent parent pointers, depth within the bit-stack
// bound, and closest-hit traversal equal to brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numeric>

#include "firmware/common/traverse.h"
#include "scenes/procedural/procedural.h"
#include "scenes/procedural/random.h"
#include "scenes/scene_image.h"
#include "scene_image_fixtures.h"

namespace strata::scenes {
namespace {

struct Walk {
  std::vector<uint32_t> primitives;
  uint32_t max_depth = 0;
  uint32_t nodes = 0;
};

bool box_inside(const float imin[3], const float imax[3], const float omin[3], const float omax[3]) {
  for (int a = 0; a < 3; ++a)
    if (imin[a] < omin[a] || imax[a] > omax[a]) return false;
  return true;
}

// Walks the image from the root, checking structure as it goes.
Walk walk_and_check(const SceneImage& img) {
  Walk w;
  struct Item { uint32_t node, depth; };
  std::vector<Item> stack{{img.header().root_node, 0}};
  EXPECT_EQ(img.node(img.header().root_node).parent, kNoParent);
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    ++w.nodes;
    const BvhNode& n = img.node(it.node);
    EXPECT_EQ(n.treelet, it.node / (img.header().treelet_bytes / sizeof(BvhNode)));
    for (int side = 0; side < 2; ++side) {
      const uint32_t ref = n.child[side];
      if (child_is_leaf(ref)) {
        w.max_depth = std::max(w.max_depth, it.depth + 1);
        for (uint32_t i = 0; i < leaf_count(ref); ++i) {
          const TriangleRecord& t = img.triangle(leaf_byte_offset(ref) + i * 48);
          w.primitives.push_back(t.primitive);
          for (const float* v : {t.v0, t.v1, t.v2})
            EXPECT_TRUE(box_inside(v, v, child_min(n, side), child_max(n, side)));
        }
        continue;
      }
      const BvhNode& c = img.node(ref);
      EXPECT_EQ(c.parent, it.node) << "parent pointer of node " << ref;
      for (int cs = 0; cs < 2; ++cs) {
        if (child_is_leaf(c.child[cs]) && leaf_count(c.child[cs]) == 0) continue;
        EXPECT_TRUE(box_inside(child_min(c, cs), child_max(c, cs), child_min(n, side), child_max(n, side)))
            << "child box of node " << ref << " escapes its parent's box";
      }
      stack.push_back({ref, it.depth + 1});
    }
  }
  return w;
}

void expect_all_reachable_once(const Walk& w, size_t triangles) {
  std::vector<uint32_t> p = w.primitives;
  std::sort(p.begin(), p.end());
  std::vector<uint32_t> expected(triangles);
  std::iota(expected.begin(), expected.end(), 0u);
  EXPECT_EQ(p, expected);
}

ClosestHit brute_force(const Scene& s, const TraceRay& ray) {
  ClosestHit best{false, ray.tmax, 0, 0, 0, 0, 0};
  for (uint32_t i = 0; i < s.triangles.size(); ++i) {
    const Triangle& t = s.triangles[i];
    TrianglePartial p;
    if (!triangle_hit_test({t.v0.x, t.v0.y, t.v0.z}, {t.v1.x, t.v1.y, t.v1.z}, {t.v2.x, t.v2.y, t.v2.z},
                           ray.origin, ray.dir, &p))
      continue;
    const TriangleHit h = triangle_finish(p);
    if (h.t > ray.tmin && h.t < best.t) best = {true, h.t, h.b1, h.b2, i, t.material, 0};
  }
  return best;
}

TraceRay random_ray(Pcg32& rng, const SceneImageHeader& h) {
  const Vec3f o{rng.uniform(h.bounds_min[0], h.bounds_max[0]), rng.uniform(h.bounds_min[1], h.bounds_max[1]),
                rng.uniform(h.bounds_min[2], h.bounds_max[2])};
  const Vec3f d{rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f)};
  return {o, d, 0.0f, INFINITY};
}

TEST(Bvh, InvariantsHoldOnCornell) {
  const Scene s = make_cornell({0.2, 1});
  const SceneImage img = build_scene_image(s, {}, nullptr);
  const Walk w = walk_and_check(img);
  expect_all_reachable_once(w, s.triangles.size());
  EXPECT_EQ(w.max_depth, img.header().bvh_depth);
  EXPECT_LE(w.max_depth, kMaxBvhDepth);
  EXPECT_EQ(w.nodes, img.header().node_count);
}

TEST(Bvh, InvariantsHoldOnSmallHairballWithEveryLeafSize) {
  const Scene s = make_hairball({0.01, 3});
  for (uint32_t leaf : {1u, 4u, 15u}) {
    SceneImageParams p;
    p.bvh.max_leaf_triangles = leaf;
    const SceneImage img = build_scene_image(s, p, nullptr);
    const Walk w = walk_and_check(img);
    expect_all_reachable_once(w, s.triangles.size());
    EXPECT_LE(w.max_depth, kMaxBvhDepth);
  }
}

TEST(Bvh, SingleTriangleSceneGetsOneRootNode) {
  const Scene s = testing::geometric_series_scene(1);
  const SceneImage img = build_scene_image(s, {}, nullptr);
  EXPECT_EQ(img.header().node_count, 1u);
  EXPECT_EQ(img.header().bvh_depth, 1u);
  expect_all_reachable_once(walk_and_check(img), 1);
}

// A plain SAH build of this series is one level per triangle (59 levels); the builder
// must cap the depth so the 32-bit bit stack stays exact, and traversal must find every one.
TEST(Bvh, DepthStaysWithinBitStackOnExponentiallyShrinkingTriangles) {
  const int count = 60;  // 2^-60 squared is still a normal float
  const Scene s = testing::geometric_series_scene(count);
  for (uint32_t depth_bound : {32u, 8u}) {
    SceneImageParams p;
    p.bvh.max_leaf_triangles = 1;
    p.bvh.max_depth = depth_bound;
    const SceneImage img = build_scene_image(s, p, nullptr);
    const Walk w = walk_and_check(img);
    expect_all_reachable_once(w, count);
    EXPECT_LE(w.max_depth, depth_bound);
    for (int i = 0; i < count; ++i) {
      const float x = std::ldexp(1.0f, -i);
      const TraceRay ray{{x, 0.0f, 1.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, INFINITY};
      NullObserver obs;
      const ClosestHit hit = trace_closest(img, img.header().root_node, ray, obs);
      ASSERT_TRUE(hit.hit) << "triangle " << i << " missed with depth bound " << depth_bound;
      EXPECT_EQ(hit.primitive, uint32_t(i));
      EXPECT_NEAR(hit.t, 1.0f, 1e-6f);
    }
  }
}

int count_agreeing_hits(const Scene& s, int rays) {
  const SceneImage img = build_scene_image(s, {}, nullptr);
  Pcg32 rng = Pcg32::keyed(11, 0);
  int hits = 0;
  for (int r = 0; r < rays; ++r) {
    const TraceRay ray = random_ray(rng, img.header());
    NullObserver obs;
    const ClosestHit a = trace_closest(img, img.header().root_node, ray, obs);
    const ClosestHit b = brute_force(s, ray);
    EXPECT_EQ(a.hit, b.hit) << "ray " << r;
    if (!a.hit || !b.hit) continue;
    ++hits;
    EXPECT_EQ(a.t, b.t) << "ray " << r;
  }
  return hits;
}

TEST(Bvh, TraversalMatchesBruteForceOnRandomRays) {
  // Inside the (open-fronted) Cornell box most rays hit; the sparse hairball tests misses.
  EXPECT_GT(count_agreeing_hits(make_cornell({0.3, 1}), 3000), 2000);
  EXPECT_GT(count_agreeing_hits(make_hairball({0.005, 7}), 3000), 50);
}

TEST(Bvh, RejectsBadParameters) {
  const Scene s = make_cornell({0.1, 1});
  SceneImageParams p;
  p.bvh.bins = 8;
  EXPECT_THROW(build_scene_image(s, p, nullptr), SceneError);
  p = {};
  p.bvh.max_leaf_triangles = 16;
  EXPECT_THROW(build_scene_image(s, p, nullptr), SceneError);
  p = {};
  p.bvh.max_depth = 33;
  EXPECT_THROW(build_scene_image(s, p, nullptr), SceneError);
  Scene empty;
  empty.name = "empty";
  EXPECT_THROW(build_scene_image(empty, {}, nullptr), SceneError);
}

}  // namespace
}  // namespace strata::scenes
