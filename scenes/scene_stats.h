// Statistics of a built scene image: BVH shape, SAH cost, treelet fill, and how often
// incoherent rays cross from one treelet to another (the cost streaming pays per ray).
#pragma once

#include <array>
#include <cstdint>

#include "scenes/scene_image.h"

namespace strata::scenes {

struct BvhStats {
  uint32_t inner_nodes = 0;
  uint32_t leaves = 0;        // non-empty leaves
  uint32_t depth = 0;         // deepest leaf, edges from the root
  double sah_cost = 0;        // traversal cost 1 per node, intersection cost 1 per triangle
  double mean_leaf_triangles = 0;
  std::array<uint32_t, kMaxLeafTriangles + 1> leaf_size_histogram{};  // [k] = leaves with k
};

struct TreeletStats {
  uint32_t node_treelets = 0, triangle_treelets = 0;
  double node_fill = 0, triangle_fill = 0;  // mean used bytes / treelet bytes
};

struct CrossingStats {
  uint64_t rays = 0, hits = 0;
  double crossings_per_ray = 0;       // treelet changes, node and triangle treelets alike
  double node_visits_per_ray = 0;     // node reads (a node is read again after its leaves)
  double leaf_visits_per_ray = 0;
  double triangle_tests_per_ray = 0;
};

BvhStats bvh_stats(const SceneImage& image);
TreeletStats treelet_stats(const SceneImage& image);

// Incoherent rays: origins uniform in the scene bounds, directions uniform on the sphere,
// from a fixed seed; traced closest-hit with the bit-stack traversal.
CrossingStats measure_crossings(const SceneImage& image, uint32_t rays, uint64_t seed);

}  // namespace strata::scenes
