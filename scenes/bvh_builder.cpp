#include "scenes/bvh_builder.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "firmware/common/scene_layout.h"

namespace strata::scenes {
namespace {

// Per-triangle data the build touches, kept in flat arrays for cache-friendly passes.
struct PrimitiveInfo {
  std::vector<Bounds> bounds;
  std::vector<glm::vec3> centroid;
};

PrimitiveInfo primitive_info(const std::vector<Triangle>& tris) {
  PrimitiveInfo info;
  info.bounds.resize(tris.size());
  info.centroid.resize(tris.size());
  for (size_t i = 0; i < tris.size(); ++i) {
    Bounds b;
    b.extend(tris[i].v0);
    b.extend(tris[i].v1);
    b.extend(tris[i].v2);
    info.bounds[i] = b;
    info.centroid[i] = b.center();
  }
  return info;
}

uint32_t levels_needed(uint64_t count, uint32_t max_leaf) {
  uint64_t leaves = (count + max_leaf - 1) / max_leaf;
  uint32_t levels = 0;
  while ((uint64_t{1} << levels) < leaves) ++levels;
  return levels;
}

struct Split {
  int axis = -1;
  uint32_t bin = 0;  // primitives in bins [0, bin] go left
  float cost = 0.0f;
};

struct Bin {
  Bounds bounds;
  uint32_t count = 0;
};

class Builder {
 public:
  Builder(const std::vector<Triangle>& tris, const BvhBuildParams& p)
      : params_(p), info_(primitive_info(tris)), bins_(p.bins), right_area_(p.bins) {}

  BinaryBvh build() {
    const uint32_t n = uint32_t(info_.bounds.size());
    bvh_.primitives.resize(n);
    for (uint32_t i = 0; i < n; ++i) bvh_.primitives[i] = i;
    bvh_.nodes.reserve(2 * (n / std::max(1u, params_.max_leaf_triangles / 2) + 1));
    bvh_.nodes.push_back({});
    struct Task {
      uint32_t node, begin, end;
    };
    std::vector<Task> stack{{0, 0, n}};
    while (!stack.empty()) {
      const Task task = stack.back();
      stack.pop_back();
      uint32_t mid = 0;
      if (!split_node(task.node, task.begin, task.end, &mid)) continue;
      const uint32_t depth = bvh_.nodes[task.node].depth + 1;
      const uint32_t left = uint32_t(bvh_.nodes.size());
      bvh_.nodes.push_back({});
      bvh_.nodes.push_back({});
      bvh_.nodes[task.node].left = left;
      bvh_.nodes[task.node].right = left + 1;
      for (uint32_t c = left; c <= left + 1; ++c) {
        bvh_.nodes[c].parent = task.node;
        bvh_.nodes[c].depth = depth;
      }
      // Right first so the left subtree is built (and numbered) first: depth-first order.
      stack.push_back({left + 1, mid, task.end});
      stack.push_back({left, task.begin, mid});
    }
    return std::move(bvh_);
  }

 private:
  // Fills the node's bounds and decides leaf or split; returns false for a leaf.
  bool split_node(uint32_t node_index, uint32_t begin, uint32_t end, uint32_t* mid) {
    Bounds bounds, centroids;
    for (uint32_t i = begin; i < end; ++i) {
      const uint32_t p = bvh_.primitives[i];
      bounds.extend(info_.bounds[p]);
      centroids.extend(info_.centroid[p]);
    }
    BinaryBvh::Node& node = bvh_.nodes[node_index];
    node.bounds = bounds;
    const uint32_t count = end - begin;
    const uint32_t child_depth = node.depth + 1;
    const uint32_t depth_left = params_.max_depth - std::min(params_.max_depth, child_depth);
    const bool may_be_leaf = count <= params_.max_leaf_triangles;

    const Split split = best_sah_split(begin, end, centroids);
    const float leaf_cost = params_.intersection_cost * float(count);
    if (may_be_leaf && (split.axis < 0 || leaf_cost <= split.cost)) {
      make_leaf(node_index, begin, count);
      return false;
    }
    if (split.axis >= 0) {
      *mid = partition_by_bin(begin, end, split, centroids);
      const uint32_t n_left = *mid - begin, n_right = end - *mid;
      if (levels_needed(n_left, params_.max_leaf_triangles) <= depth_left &&
          levels_needed(n_right, params_.max_leaf_triangles) <= depth_left)
        return true;
    }
    // SAH found no split (all centroids equal) or its split would break the depth bound.
    *mid = median_split(begin, end, centroids);
    return true;
  }

  void make_leaf(uint32_t node_index, uint32_t begin, uint32_t count) {
    bvh_.nodes[node_index].first = begin;
    bvh_.nodes[node_index].count = count;
  }

  uint32_t bin_of(const glm::vec3& c, int axis, const Bounds& centroids, float scale) const {
    const float x = (c[axis] - centroids.min[axis]) * scale;
    const uint32_t last = params_.bins - 1;
    return x <= 0.0f ? 0u : std::min(last, uint32_t(x));
  }

  Split best_sah_split(uint32_t begin, uint32_t end, const Bounds& centroids) {
    Split best;
    best.cost = INFINITY;
    const uint32_t nb = params_.bins;
    Bounds node_bounds;
    for (int axis = 0; axis < 3; ++axis) {
      const float extent = centroids.max[axis] - centroids.min[axis];
      if (!(extent > 0.0f)) continue;
      const float scale = float(nb) / extent;
      std::fill(bins_.begin(), bins_.end(), Bin{});
      for (uint32_t i = begin; i < end; ++i) {
        const uint32_t p = bvh_.primitives[i];
        Bin& b = bins_[bin_of(info_.centroid[p], axis, centroids, scale)];
        b.bounds.extend(info_.bounds[p]);
        ++b.count;
      }
      // Sweep from the right to get the area of every right side, then from the left.
      Bounds acc;
      for (uint32_t i = nb - 1; i > 0; --i) {
        acc.extend(bins_[i].bounds);
        right_area_[i] = acc.surface_area();
      }
      node_bounds = acc;
      node_bounds.extend(bins_[0].bounds);
      const float inv_area = 1.0f / std::max(node_bounds.surface_area(), 1e-30f);
      Bounds left;
      uint32_t n_left = 0;
      for (uint32_t i = 0; i + 1 < nb; ++i) {
        left.extend(bins_[i].bounds);
        n_left += bins_[i].count;
        const uint32_t n_right = (end - begin) - n_left;
        if (n_left == 0 || n_right == 0) continue;
        const float cost =
            params_.traversal_cost + params_.intersection_cost * inv_area *
                                         (left.surface_area() * float(n_left) +
                                          right_area_[i + 1] * float(n_right));
        if (cost < best.cost) best = {axis, i, cost};
      }
    }
    return best;
  }

  uint32_t partition_by_bin(uint32_t begin, uint32_t end, const Split& s, const Bounds& c) {
    const float scale = float(params_.bins) / (c.max[s.axis] - c.min[s.axis]);
    auto* first = bvh_.primitives.data() + begin;
    auto* last = bvh_.primitives.data() + end;
    auto* m = std::partition(first, last, [&](uint32_t p) {
      return bin_of(info_.centroid[p], s.axis, c, scale) <= s.bin;
    });
    return uint32_t(m - bvh_.primitives.data());
  }

  // Object median along the widest centroid axis, ties broken by triangle index so the
  // result does not depend on the partition order.
  uint32_t median_split(uint32_t begin, uint32_t end, const Bounds& c) {
    const glm::vec3 e = c.extent();
    const int axis = (e.x >= e.y && e.x >= e.z) ? 0 : (e.y >= e.z ? 1 : 2);
    const uint32_t mid = begin + (end - begin) / 2;
    auto* base = bvh_.primitives.data();
    std::nth_element(base + begin, base + mid, base + end, [&](uint32_t a, uint32_t b) {
      const float ca = info_.centroid[a][axis], cb = info_.centroid[b][axis];
      return ca < cb || (ca == cb && a < b);
    });
    return mid;
  }

  BvhBuildParams params_;
  PrimitiveInfo info_;
  BinaryBvh bvh_;
  std::vector<Bin> bins_;
  std::vector<float> right_area_;
};

void check_params(const BvhBuildParams& p) {
  if (p.bins < 16) throw SceneError("bvh.bins: need at least 16 SAH bins, got " + std::to_string(p.bins));
  if (p.max_leaf_triangles < 1 || p.max_leaf_triangles > kMaxLeafTriangles)
    throw SceneError("bvh.max_leaf_triangles: must be 1.." + std::to_string(kMaxLeafTriangles) +
                     ", got " + std::to_string(p.max_leaf_triangles));
  if (p.max_depth < 1 || p.max_depth > kMaxBvhDepth)
    throw SceneError("bvh.max_depth: must be 1.." + std::to_string(kMaxBvhDepth) + ", got " +
                     std::to_string(p.max_depth));
  if (!(p.traversal_cost > 0.0f) || !(p.intersection_cost > 0.0f))
    throw SceneError("bvh costs: traversal_cost and intersection_cost must be positive");
}

}  // namespace

uint32_t BinaryBvh::max_depth() const {
  uint32_t d = 0;
  for (const Node& n : nodes) d = std::max(d, n.depth);
  return d;
}

BinaryBvh build_bvh(const std::vector<Triangle>& triangles, const BvhBuildParams& params) {
  check_params(params);
  if (triangles.empty()) throw SceneError("bvh: the scene has no triangles");
  const uint64_t capacity = uint64_t(params.max_leaf_triangles) << params.max_depth;
  if (triangles.size() > capacity)
    throw SceneError("bvh: " + std::to_string(triangles.size()) +
                     " triangles do not fit under max_depth with this leaf size");
  return Builder(triangles, params).build();
}

}  // namespace strata::scenes
