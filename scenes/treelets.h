// Grouping of BVH inner nodes into node treelets of at most one L1 cache of bytes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scenes/bvh_builder.h"

namespace strata::scenes {

enum class TreeletPolicy {
  // Greedy fill by surface area (after Aila and Karras 2010): grow the treelet from its
  // root by always adding the frontier node with the largest box, i.e. the node most rays
  // that enter the treelet will visit. What is left on the frontier roots new treelets.
  surface_area,
  // Breadth-first fill: add frontier nodes level by level.
  breadth_first,
};

TreeletPolicy parse_treelet_policy(const std::string& name);  // "surface-area" | "breadth-first"
const char* to_string(TreeletPolicy policy);

// Each treelet lists inner-node indices of the binary BVH in their memory order.
// Subtrees that fit in one treelet whole are never split; when the greedy fill leaves such
// subtrees on its frontier, they are packed together (first fit, biggest first) so small
// subtrees near the leaves do not each waste a whole aligned treelet.
struct TreeletPartition {
  std::vector<std::vector<uint32_t>> treelets;
};

TreeletPartition partition_treelets(const BinaryBvh& bvh, uint32_t nodes_per_treelet,
                                    TreeletPolicy policy);

}  // namespace strata::scenes
