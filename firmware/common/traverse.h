// Closest-hit traversal of the scene image with a 32-bit bit stack and parent pointers
// (ARCHITECTURE.md, "Traversal"). No stack memory: the state is the current node, where we
// came from, and one word with a bit per level (least significant bit = top).
//   push:  stack = (stack << 1) | (left child taken first ? 1 : 0)
//   pop:   stack >>= 1
// After a child's subtree is done, the top bit says which child was taken first. If that is
// the side just finished, the other child is visited when its box is still hit closer than
// the current closest hit; otherwise both are done: pop and go up to the parent. When only
// one child's box was hit, the bit names the other child, so its return pops at once.
//
// Freestanding and templated on two policies so the firmware, the native twin and host
// tools share it without virtual calls:
//   Memory:   const BvhNode& node(uint32_t index) const;
//             const TriangleRecord& triangle(uint32_t byte_offset) const;
//   Observer: void node_visited(uint32_t index); void leaf_visited(uint32_t leaf_ref);
//             void triangle_tested();   (for statistics; NullObserver ignores them)
// trace_closest finds the closest hit; trace_any stops at the first (occlusion queries).
#pragma once

#include <stdint.h>

#include "firmware/common/intersect.h"
#include "firmware/common/scene_layout.h"

namespace strata {

struct TraceRay {
  Vec3f origin;
  Vec3f dir;
  float tmin, tmax;
};

struct ClosestHit {
  bool hit;
  float t, b1, b2;
  uint32_t primitive, material;
  uint32_t triangle_offset;  // byte offset of the hit TriangleRecord in the triangle section
};

struct NullObserver {
  void node_visited(uint32_t) {}
  void leaf_visited(uint32_t) {}
  void triangle_tested() {}
};

namespace detail {

// Returns true when an any-hit (occlusion) query may stop.
template <bool kAnyHit, class Memory, class Observer>
inline bool test_leaf(const Memory& mem, uint32_t ref, const TraceRay& ray, ClosestHit* best,
                      BoxRay* box_ray, Observer& obs) {
  obs.leaf_visited(ref);
  const uint32_t count = leaf_count(ref);
  const uint32_t offset = leaf_byte_offset(ref);
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t tri_offset = offset + i * uint32_t(sizeof(TriangleRecord));
    const TriangleRecord& tri = mem.triangle(tri_offset);
    obs.triangle_tested();
    TrianglePartial partial;
    if (!triangle_hit_test(load_vec3(tri.v0), load_vec3(tri.v1), load_vec3(tri.v2), ray.origin,
                           ray.dir, &partial))
      continue;
    const TriangleHit h = triangle_finish(partial);
    // Strictly closer wins, so among equal distances the first one found is kept.
    if (h.t > ray.tmin && h.t < box_ray->tmax) {
      *best = {true, h.t, h.b1, h.b2, tri.primitive, tri.material, tri_offset};
      box_ray->tmax = h.t;
      if (kAnyHit) return true;
    }
  }
  return false;
}

// The ray was checked once by traverse(), so the per-box validity test is skipped.
STRATA_INLINE bool child_box_hit(const BvhNode& n, int side, const BoxRay& r, float* t_entry) {
  if (child_is_leaf(n.child[side]) && leaf_count(n.child[side]) == 0) return false;
  return intersect_box_valid_ray(n.child_min[side], n.child_max[side], r, t_entry);
}

template <bool kAnyHit, class Memory, class Observer>
inline ClosestHit traverse(const Memory& mem, uint32_t root, const TraceRay& ray, Observer& obs) {
  ClosestHit best = {false, ray.tmax, 0.0f, 0.0f, 0u, 0u, 0u};
  BoxRay box_ray = {ray.origin, inverse_direction(ray.dir), ray.tmin, ray.tmax};
  if (!box_ray_is_valid(box_ray)) return best;  // intersect_box would reject every box
  uint32_t node = root;
  uint32_t stack = 0;
  int returning_from = -1;  // -1: entering node; 0 or 1: that child's subtree is done

  for (;;) {
    const BvhNode& n = mem.node(node);
    obs.node_visited(node);
    int go = -1;  // child to visit next, or -1 to leave this node
    if (returning_from < 0) {
      float t0 = 0.0f, t1 = 0.0f;
      const bool hit0 = detail::child_box_hit(n, 0, box_ray, &t0);
      const bool hit1 = detail::child_box_hit(n, 1, box_ray, &t1);
      if (hit0 || hit1) {
        go = (hit0 && (!hit1 || t0 <= t1)) ? 0 : 1;
        // With one child hit, the bit names the other side, as if it had gone first: the
        // return then pops at once instead of re-testing a box that already missed.
        const int first = (hit0 && hit1) ? go : 1 - go;
        stack = (stack << 1) | (first == 0 ? 1u : 0u);
      }
    } else {
      const int first = (stack & 1u) ? 0 : 1;
      float t_other = 0.0f;
      if (first == returning_from &&
          detail::child_box_hit(n, 1 - returning_from, box_ray, &t_other))
        go = 1 - returning_from;  // the bit keeps naming the first side, so we pop later
      else
        stack >>= 1;
    }

    if (go >= 0) {
      const uint32_t ref = n.child[go];
      if (child_is_leaf(ref)) {
        if (detail::test_leaf<kAnyHit>(mem, ref, ray, &best, &box_ray, obs)) break;
        returning_from = go;
      } else {
        node = ref;
        returning_from = -1;
      }
      continue;
    }
    // Leave this node: go up to the parent, or finish at the root.
    if (n.parent == kNoParent) break;
    const uint32_t child = node;
    node = n.parent;
    returning_from = mem.node(node).child[0] == child ? 0 : 1;
  }
  return best;
}

}  // namespace detail

// The closest hit in (tmin, tmax); among equally close hits, the first found.
template <class Memory, class Observer>
inline ClosestHit trace_closest(const Memory& mem, uint32_t root, const TraceRay& ray,
                                Observer& obs) {
  return detail::traverse<false>(mem, root, ray, obs);
}

// Any hit in (tmin, tmax): stops at the first one (shadow rays). Its hit record is that
// first hit, not the closest.
template <class Memory, class Observer>
inline ClosestHit trace_any(const Memory& mem, uint32_t root, const TraceRay& ray, Observer& obs) {
  return detail::traverse<true>(mem, root, ray, obs);
}

}  // namespace strata
