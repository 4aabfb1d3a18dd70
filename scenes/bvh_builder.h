// Binned SAH build of a binary BVH over a scene's triangles (Wald 2007 style binning).
// The result is an intermediate tree whose leaves are nodes; scene_image.h turns it into the
// 64-byte node layout the hardware reads.
#pragma once

#include <cstdint>
#include <vector>

#include "scenes/scene.h"

namespace strata::scenes {

struct BvhBuildParams {
  uint32_t bins = 32;                // SAH bins per axis (at least 16)
  uint32_t max_leaf_triangles = 4;   // leaf size bound, at most kMaxLeafTriangles
  uint32_t max_depth = 32;           // deepest leaf in edges; the bit stack holds 32 levels
  float traversal_cost = 1.0f;       // SAH cost of one box test (two children)...
  float intersection_cost = 1.0f;    // ...relative to one triangle test
};

struct BinaryBvh {
  static constexpr uint32_t kNone = 0xFFFFFFFFu;
  struct Node {
    Bounds bounds;
    uint32_t left = kNone, right = kNone;  // inner nodes only
    uint32_t first = 0, count = 0;         // leaves only: range in `primitives`
    uint32_t parent = kNone;
    uint32_t depth = 0;
    bool is_leaf() const { return left == kNone; }
  };
  std::vector<Node> nodes;            // nodes[0] is the root; a parent precedes its children
  std::vector<uint32_t> primitives;   // triangle indices, grouped by leaf

  uint32_t max_depth() const;
};

// Throws SceneError on invalid parameters or an empty triangle list.
//
// Depth bound: a subtree of n triangles needs at least ceil(log2(ceil(n / max_leaf))) more
// levels. Whenever an SAH split would leave a child that cannot fit under max_depth, the
// node is split at the object median instead, which halves the need; so every leaf ends at
// depth <= max_depth, whatever the input (the test builds a geometric series of triangles
// whose plain SAH tree is hundreds of levels deep).
BinaryBvh build_bvh(const std::vector<Triangle>& triangles, const BvhBuildParams& params);

}  // namespace strata::scenes
