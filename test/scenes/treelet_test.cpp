// Treelet invariants: size, alignment, node/triangle separation, and that the treelet of
// any node or triangle follows from its address alone.
#include <gtest/gtest.h>

#include <set>

#include "scenes/procedural/procedural.h"
#include "scenes/scene_image.h"
#include "scenes/scene_stats.h"

namespace strata::scenes {
namespace {

void check_treelets(const SceneImage& img) {
  const SceneImageHeader& h = img.header();
  const uint32_t T = h.treelet_bytes;
  const uint32_t per = T / sizeof(BvhNode);
  ASSERT_EQ(h.treelet_offset % T, 0u);
  ASSERT_GT(h.node_treelet_count, 0u);
  ASSERT_GT(h.treelet_count, h.node_treelet_count);
  uint64_t nodes = 0, triangles = 0;
  for (uint32_t i = 0; i < h.treelet_count; ++i) {
    const TreeletRecord& t = img.treelet(i);
    EXPECT_LE(t.used_bytes, T);
    EXPECT_GT(t.count, 0u) << "empty treelet " << i;
    const uint64_t start = h.treelet_offset + uint64_t(i) * T;
    EXPECT_EQ(start % T, 0u);
    if (i < h.node_treelet_count) {
      ASSERT_EQ(t.kind, kNodeTreelet);
      EXPECT_EQ(t.first, i * per);
      EXPECT_EQ(t.used_bytes, t.count * sizeof(BvhNode));
      for (uint32_t j = 0; j < t.count; ++j) {
        const BvhNode& n = img.node(t.first + j);
        EXPECT_EQ(n.treelet, i);
        EXPECT_NE(n.child[0], 0u) << "hole inside treelet " << i;
      }
      // The rest of the treelet is zero padding.
      for (uint32_t j = t.count; j < per; ++j) EXPECT_EQ(img.node(t.first + j).child[0], 0u);
      nodes += t.count;
    } else {
      ASSERT_EQ(t.kind, kTriangleTreelet) << "node and triangle treelets interleave";
      EXPECT_EQ(t.first, (i - h.node_treelet_count) * T);
      EXPECT_EQ(t.used_bytes, t.count * sizeof(TriangleRecord));
      triangles += t.count;
    }
  }
  EXPECT_EQ(nodes, h.node_count);
  EXPECT_EQ(triangles, h.triangle_count);
  // Every leaf lies inside one triangle treelet; its treelet follows from its offset.
  for (uint32_t i = 0; i < h.node_slots; ++i) {
    const BvhNode& n = img.node(i);
    if (n.child[0] == 0) continue;
    for (uint32_t ref : n.child) {
      if (!child_is_leaf(ref) || leaf_count(ref) == 0) continue;
      const uint32_t first = leaf_byte_offset(ref);
      const uint32_t last = first + leaf_count(ref) * uint32_t(sizeof(TriangleRecord)) - 1;
      EXPECT_EQ(first / T, last / T) << "leaf straddles triangle treelets";
      const uint32_t treelet = img.treelet_of_triangle(first);
      const TreeletRecord& t = img.treelet(treelet);
      EXPECT_GE(first, t.first);
      EXPECT_LE(last, t.first + t.used_bytes - 1);
    }
  }
}

class TreeletPolicies : public ::testing::TestWithParam<TreeletPolicy> {};

TEST_P(TreeletPolicies, InvariantsHoldAtSeveralTreeletSizes) {
  const Scene s = make_hairball({0.01, 5});
  for (uint32_t bytes : {1024u, 4096u, 32768u}) {
    SceneImageParams p;
    p.treelet_bytes = bytes;
    p.treelet_policy = GetParam();
    const SceneImage img = build_scene_image(s, p, nullptr);
    SCOPED_TRACE(bytes);
    check_treelets(img);
  }
}

TEST_P(TreeletPolicies, SmallSubtreesArePackedNotGivenATreeletEach) {
  const Scene s = make_hairball({0.01, 5});
  SceneImageParams p;
  p.treelet_bytes = 4096;
  p.treelet_policy = GetParam();
  const SceneImage img = build_scene_image(s, p, nullptr);
  const TreeletStats st = treelet_stats(img);
  EXPECT_GT(st.node_fill, 0.85);
  EXPECT_GT(st.triangle_fill, 0.9);
}

INSTANTIATE_TEST_SUITE_P(Treelets, TreeletPolicies,
                         ::testing::Values(TreeletPolicy::surface_area, TreeletPolicy::breadth_first));

TEST(Treelets, CrossingsAreCountedAndFewerWithBiggerTreelets) {
  const Scene s = make_hairball({0.02, 9});
  SceneImageParams small, big;
  small.treelet_bytes = 1024;
  big.treelet_bytes = 65536;
  const CrossingStats a = measure_crossings(build_scene_image(s, small, nullptr), 2000, 3);
  const CrossingStats b = measure_crossings(build_scene_image(s, big, nullptr), 2000, 3);
  EXPECT_GT(a.crossings_per_ray, 2.0);
  EXPECT_LT(b.crossings_per_ray, a.crossings_per_ray);
  EXPECT_EQ(a.hits, b.hits);  // layout never changes what a ray hits
}

TEST(Treelets, PolicyNamesParseAndBadOnesAreRejected) {
  EXPECT_EQ(parse_treelet_policy("surface-area"), TreeletPolicy::surface_area);
  EXPECT_EQ(parse_treelet_policy("breadth-first"), TreeletPolicy::breadth_first);
  EXPECT_THROW(parse_treelet_policy("random"), SceneError);
  SceneImageParams p;
  p.treelet_bytes = 3000;
  EXPECT_THROW(build_scene_image(make_cornell({0.1, 1}), p, nullptr), SceneError);
}

}  // namespace
}  // namespace strata::scenes
