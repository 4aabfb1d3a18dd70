#include "scenes/scene_stats.h"

#include <cmath>
#include <limits>

#include "firmware/common/traverse.h"
#include "scenes/procedural/random.h"

namespace strata::scenes {
namespace {

double box_area(const float mn[3], const float mx[3]) {
  const double x = double(mx[0]) - mn[0], y = double(mx[1]) - mn[1], z = double(mx[2]) - mn[2];
  return 2.0 * (x * y + y * z + z * x);
}

// Walks all real nodes from the root (padding slots are not reachable).
template <class Visit>
void for_each_node(const SceneImage& image, Visit visit) {
  std::vector<uint32_t> stack{image.header().root_node};
  while (!stack.empty()) {
    const uint32_t i = stack.back();
    stack.pop_back();
    const BvhNode& n = image.node(i);
    visit(n);
    for (uint32_t ref : n.child)
      if (!child_is_leaf(ref)) stack.push_back(ref);
  }
}

// Counts treelet changes along one ray's traversal.
struct CrossingObserver {
  const SceneImage& image;
  uint32_t current = std::numeric_limits<uint32_t>::max();
  uint64_t crossings = 0, node_visits = 0, leaf_visits = 0, triangle_tests = 0;

  void enter(uint32_t treelet) {
    if (treelet != current && current != std::numeric_limits<uint32_t>::max()) ++crossings;
    current = treelet;
  }
  void node_visited(uint32_t index) {
    ++node_visits;
    enter(image.node(index).treelet);
  }
  void leaf_visited(uint32_t ref) {
    ++leaf_visits;
    enter(image.treelet_of_triangle(leaf_byte_offset(ref)));
  }
  void triangle_tested() { ++triangle_tests; }
};

}  // namespace

BvhStats bvh_stats(const SceneImage& image) {
  const SceneImageHeader& h = image.header();
  BvhStats s;
  s.depth = h.bvh_depth;
  const double root_area = std::max(box_area(h.bounds_min, h.bounds_max), 1e-30);
  uint64_t leaf_triangles = 0;
  // SAH: every inner node costs 1 per ray reaching it and every leaf 1 per triangle, each
  // weighted by the area of its box relative to the root's (the root is always reached).
  // Child boxes live in the parent, so each term is added where the parent is visited.
  s.sah_cost = 1.0;
  for_each_node(image, [&](const BvhNode& n) {
    ++s.inner_nodes;
    for (int side = 0; side < 2; ++side) {
      const uint32_t ref = n.child[side];
      const double rel = box_area(child_min(n, side), child_max(n, side)) / root_area;
      if (!child_is_leaf(ref)) {
        s.sah_cost += rel;
        continue;
      }
      const uint32_t count = leaf_count(ref);
      if (count == 0) continue;
      ++s.leaves;
      ++s.leaf_size_histogram[count];
      leaf_triangles += count;
      s.sah_cost += rel * count;
    }
  });
  s.mean_leaf_triangles = s.leaves ? double(leaf_triangles) / s.leaves : 0.0;
  return s;
}

TreeletStats treelet_stats(const SceneImage& image) {
  const SceneImageHeader& h = image.header();
  TreeletStats s;
  double node_used = 0, tri_used = 0;
  for (uint32_t i = 0; i < h.treelet_count; ++i) {
    const TreeletRecord& t = image.treelet(i);
    if (t.kind == kNodeTreelet) {
      ++s.node_treelets;
      node_used += t.used_bytes;
    } else {
      ++s.triangle_treelets;
      tri_used += t.used_bytes;
    }
  }
  if (s.node_treelets) s.node_fill = node_used / (double(s.node_treelets) * h.treelet_bytes);
  if (s.triangle_treelets) s.triangle_fill = tri_used / (double(s.triangle_treelets) * h.treelet_bytes);
  return s;
}

CrossingStats measure_crossings(const SceneImage& image, uint32_t rays, uint64_t seed) {
  const SceneImageHeader& h = image.header();
  Pcg32 rng = Pcg32::keyed(seed, 0x7265656c6574ull);
  CrossingStats s;
  uint64_t crossings = 0, nodes = 0, leaves = 0, tests = 0;
  for (uint32_t r = 0; r < rays; ++r) {
    Vec3f o{rng.uniform(h.bounds_min[0], h.bounds_max[0]), rng.uniform(h.bounds_min[1], h.bounds_max[1]),
            rng.uniform(h.bounds_min[2], h.bounds_max[2])};
    const float z = rng.uniform(-1.0f, 1.0f);
    const float phi = rng.uniform(0.0f, 6.28318530718f);
    const float rxy = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const TraceRay ray{o, {rxy * std::cos(phi), rxy * std::sin(phi), z}, 0.0f, INFINITY};
    CrossingObserver obs{image};
    const ClosestHit hit = trace_closest(image, h.root_node, ray, obs);
    s.hits += hit.hit ? 1 : 0;
    crossings += obs.crossings;
    nodes += obs.node_visits;
    leaves += obs.leaf_visits;
    tests += obs.triangle_tests;
  }
  s.rays = rays;
  if (rays) {
    s.crossings_per_ray = double(crossings) / rays;
    s.node_visits_per_ray = double(nodes) / rays;
    s.leaf_visits_per_ray = double(leaves) / rays;
    s.triangle_tests_per_ray = double(tests) / rays;
  }
  return s;
}

}  // namespace strata::scenes
