#include "scenes/treelets.h"

#include <algorithm>
#include <deque>
#include <queue>
#include <set>
#include <utility>

#include "scenes/scene.h"

namespace strata::scenes {

TreeletPolicy parse_treelet_policy(const std::string& name) {
  if (name == "surface-area") return TreeletPolicy::surface_area;
  if (name == "breadth-first") return TreeletPolicy::breadth_first;
  throw SceneError("treelet policy: unknown '" + name +
                   "' (expected surface-area or breadth-first)");
}

const char* to_string(TreeletPolicy policy) {
  return policy == TreeletPolicy::surface_area ? "surface-area" : "breadth-first";
}

namespace {

// Inner nodes in each node's subtree (leaves are not nodes in the image layout).
std::vector<uint32_t> inner_subtree_sizes(const BinaryBvh& bvh) {
  std::vector<uint32_t> size(bvh.nodes.size(), 0);
  // Children always have larger indices than their parent, so one reverse pass suffices.
  for (size_t i = bvh.nodes.size(); i-- > 0;) {
    const BinaryBvh::Node& n = bvh.nodes[i];
    if (n.is_leaf()) continue;
    size[i] = 1 + size[n.left] + size[n.right];
  }
  return size;
}

void append_subtree(const BinaryBvh& bvh, uint32_t root, std::vector<uint32_t>* out) {
  std::vector<uint32_t> stack{root};
  while (!stack.empty()) {
    const uint32_t i = stack.back();
    stack.pop_back();
    const BinaryBvh::Node& n = bvh.nodes[i];
    if (n.is_leaf()) continue;
    out->push_back(i);
    stack.push_back(n.right);
    stack.push_back(n.left);
  }
}

// Greedy fill from `root`; frontier nodes left over are appended to `overflow`.
std::vector<uint32_t> grow_treelet(const BinaryBvh& bvh, uint32_t root, uint32_t capacity,
                                   TreeletPolicy policy, std::vector<uint32_t>* overflow) {
  std::vector<uint32_t> members;
  auto larger_area_first = [&](uint32_t a, uint32_t b) {
    const float sa = bvh.nodes[a].bounds.surface_area(), sb = bvh.nodes[b].bounds.surface_area();
    return sa < sb || (sa == sb && a > b);  // max-heap on area; ties: lower index first
  };
  std::priority_queue<uint32_t, std::vector<uint32_t>, decltype(larger_area_first)> by_area(
      larger_area_first);
  std::deque<uint32_t> fifo;
  auto push = [&](uint32_t i) {
    if (bvh.nodes[i].is_leaf()) return;
    if (policy == TreeletPolicy::surface_area) by_area.push(i); else fifo.push_back(i);
  };
  auto empty = [&] { return policy == TreeletPolicy::surface_area ? by_area.empty() : fifo.empty(); };
  auto pop = [&] {
    uint32_t i;
    if (policy == TreeletPolicy::surface_area) { i = by_area.top(); by_area.pop(); }
    else { i = fifo.front(); fifo.pop_front(); }
    return i;
  };
  push(root);
  while (!empty() && members.size() < capacity) {
    const uint32_t i = pop();
    members.push_back(i);
    push(bvh.nodes[i].left);
    push(bvh.nodes[i].right);
  }
  while (!empty()) overflow->push_back(pop());
  return members;
}

}  // namespace

TreeletPartition partition_treelets(const BinaryBvh& bvh, uint32_t nodes_per_treelet,
                                    TreeletPolicy policy) {
  TreeletPartition result;
  if (bvh.nodes.empty() || bvh.nodes[0].is_leaf()) return result;
  const std::vector<uint32_t> size = inner_subtree_sizes(bvh);

  std::vector<uint32_t> small_roots;  // whole subtrees that fit one treelet
  std::deque<uint32_t> big_roots{0};
  while (!big_roots.empty()) {
    const uint32_t root = big_roots.front();
    big_roots.pop_front();
    if (size[root] <= nodes_per_treelet) {
      small_roots.push_back(root);
      continue;
    }
    std::vector<uint32_t> overflow;
    result.treelets.push_back(grow_treelet(bvh, root, nodes_per_treelet, policy, &overflow));
    for (uint32_t r : overflow) big_roots.push_back(r);
  }

  // Best-fit decreasing packing of the whole subtrees: each goes into the open treelet with
  // the least free space that still holds it. Sizes sort stably, so the layout is
  // deterministic.
  std::stable_sort(small_roots.begin(), small_roots.end(),
                   [&](uint32_t a, uint32_t b) { return size[a] > size[b]; });
  std::set<std::pair<uint32_t, size_t>> open;  // (free nodes, treelet index)
  for (uint32_t root : small_roots) {
    auto fit = open.lower_bound({size[root], 0});
    size_t treelet;
    uint32_t free_nodes;
    if (fit == open.end()) {
      treelet = result.treelets.size();
      result.treelets.emplace_back();
      free_nodes = nodes_per_treelet;
    } else {
      treelet = fit->second;
      free_nodes = fit->first;
      open.erase(fit);
    }
    append_subtree(bvh, root, &result.treelets[treelet]);
    free_nodes -= size[root];
    if (free_nodes > 0) open.insert({free_nodes, treelet});
  }
  return result;
}

}  // namespace strata::scenes
