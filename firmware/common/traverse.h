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

// The ray was checked once by traverse(), so the per-box validity test is skipped.
STRATA_INLINE bool child_box_hit(const BvhNode& n, int side, const BoxRay& r, float* t_entry) {
  if (child_is_leaf(n.child[side]) && leaf_count(n.child[side]) == 0) return false;
  return intersect_box_valid_ray(child_min(n, side), child_max(n, side), r, t_entry);
}

}  // namespace detail

// The whole state of a ray's traversal: small enough to live in a 48-byte stream-memory ray,
// so a streaming kernel can suspend it where the ray leaves a treelet and resume it on another
// TM. traverse() below runs the same state machine to the end in one go; both make exactly
// the same decisions, so every kernel computes the same hits and statistics.
enum TraversalPhase : uint32_t {
  kEnterNode = 0,    // test both children's boxes of `node`
  kReturnLeft = 1,   // the left child's subtree of `node` is done
  kReturnRight = 2,  // the right child's subtree of `node` is done
  kAtLeaf = 3,       // test the triangles of leaf `pending`, child `leaf_side` of `node`
  kAscend = 4,       // return to `node` (the parent) from its child `pending`
  kTraversalDone = 5
};

constexpr uint32_t kNoTriangle = 0xFFFFFFFFu;

struct TraversalState {
  uint32_t node;
  uint32_t stack;
  uint32_t phase;      // TraversalPhase
  uint32_t pending;    // kAtLeaf: the leaf reference; kAscend: the child we come from
  uint32_t leaf_side;  // kAtLeaf: which child of `node` the leaf is
  float t_best;        // closest hit so far (starts at the ray's tmax)
  uint32_t hit_triangle;  // byte offset of the closest triangle, or kNoTriangle
};

inline TraversalState start_traversal(uint32_t root, const TraceRay& ray) {
  const BoxRay box_ray = {ray.origin, inverse_direction(ray.dir), ray.tmin, ray.tmax};
  // An invalid ray would be rejected by every box: it is done before it starts.
  const uint32_t phase = box_ray_is_valid(box_ray) ? kEnterNode : kTraversalDone;
  return {root, 0u, phase, 0u, 0u, ray.tmax, kNoTriangle};
}

// Where a traversal may run: Bounds::node_here(index) and leaf_here(leaf_ref) say whether the
// next node or leaf lies in memory the caller holds (its treelet); when not, advance() stops
// with the state pointing at it. EverywhereBounds never stops.
struct EverywhereBounds {
  bool node_here(uint32_t) const { return true; }
  bool leaf_here(uint32_t) const { return true; }
};

// How the box and triangle tests are computed: in general-purpose instructions
// (SoftwareTests, intersect.h), or by the fused pipelines (the firmware's pipeline tester,
// which the hardware computes with the same intersect.h, bit for bit). A Tests policy gets
// the ray once per advance() and the new tmax whenever a closer hit shortens it.
struct SoftwareTests {
  BoxRay box_ray;
  void begin(const TraceRay& ray, float tmax) {
    box_ray = {ray.origin, inverse_direction(ray.dir), ray.tmin, tmax};
  }
  void set_tmax(float tmax) { box_ray.tmax = tmax; }
  bool box(const BvhNode& n, int side, float* t_entry) const {
    return detail::child_box_hit(n, side, box_ray, t_entry);
  }
  bool triangle(const TriangleRecord& tri, const TraceRay& ray, TriangleHit* hit) const {
    TrianglePartial partial;
    if (!triangle_hit_test(load_vec3(tri.v0), load_vec3(tri.v1), load_vec3(tri.v2), ray.origin, ray.dir, &partial))
      return false;
    *hit = triangle_finish(partial);
    return true;
  }
};

// Runs the traversal until it is done or needs memory outside `bounds`. Always inlined: its
// state must stay in registers; called out of line (GCC for RV32 decides so once the caller is
// large, as the streaming kernels' process() is), it keeps the state in memory, and the
// pipelined kernel ran 25% more instructions, nearly all loads and stores.
template <bool kAnyHit, class Memory, class Observer, class Bounds, class Tests = SoftwareTests>
STRATA_INLINE void advance(const Memory& mem, TraversalState& s, const TraceRay& ray, Observer& obs,
                    const Bounds& bounds, Tests tests = Tests()) {
  tests.begin(ray, s.t_best);
  while (s.phase != kTraversalDone) {
    if (s.phase == kAtLeaf) {
      const uint32_t ref = s.pending;
      obs.leaf_visited(ref);
      const uint32_t count = leaf_count(ref);
      const uint32_t offset = leaf_byte_offset(ref);
      bool stop = false;
      for (uint32_t i = 0; i < count && !stop; ++i) {
        const uint32_t tri_offset = offset + i * uint32_t(sizeof(TriangleRecord));
        const TriangleRecord& tri = mem.triangle(tri_offset);
        obs.triangle_tested();
        TriangleHit h;
        if (!tests.triangle(tri, ray, &h)) continue;
        // Strictly closer wins, so among equal distances the first one found is kept.
        if (h.t > ray.tmin && h.t < s.t_best) {
          s.t_best = h.t;
          s.hit_triangle = tri_offset;
          tests.set_tmax(h.t);
          stop = kAnyHit;
        }
      }
      if (stop) {
        s.phase = kTraversalDone;
        break;
      }
      s.phase = s.leaf_side == 0 ? kReturnLeft : kReturnRight;
      if (!bounds.node_here(s.node)) return;
      continue;
    }

    const BvhNode& n = mem.node(s.node);
    obs.node_visited(s.node);
    int returning_from = -1;
    if (s.phase == kAscend) returning_from = n.child[0] == s.pending ? 0 : 1;
    else if (s.phase != kEnterNode) returning_from = s.phase == kReturnLeft ? 0 : 1;

    int go = -1;  // child to visit next, or -1 to leave this node
    if (returning_from < 0) {
      float t0 = 0.0f, t1 = 0.0f;
      const bool hit0 = tests.box(n, 0, &t0);
      const bool hit1 = tests.box(n, 1, &t1);
      if (hit0 || hit1) {
        go = (hit0 && (!hit1 || t0 <= t1)) ? 0 : 1;
        // With one child hit, the bit names the other side, as if it had gone first: the
        // return then pops at once instead of re-testing a box that already missed.
        const int first = (hit0 && hit1) ? go : 1 - go;
        s.stack = (s.stack << 1) | (first == 0 ? 1u : 0u);
      }
    } else {
      const int first = (s.stack & 1u) ? 0 : 1;
      float t_other = 0.0f;
      if (first == returning_from && tests.box(n, 1 - returning_from, &t_other))
        go = 1 - returning_from;  // the bit keeps naming the first side, so we pop later
      else
        s.stack >>= 1;
    }

    if (go >= 0) {
      const uint32_t ref = n.child[go];
      if (child_is_leaf(ref)) {
        s.phase = kAtLeaf;
        s.pending = ref;
        s.leaf_side = uint32_t(go);
        if (!bounds.leaf_here(ref)) return;
      } else {
        s.node = ref;
        s.phase = kEnterNode;
        if (!bounds.node_here(ref)) return;
      }
      continue;
    }
    // Leave this node: go up to the parent, or finish at the root.
    if (n.parent == kNoParent) {
      s.phase = kTraversalDone;
      break;
    }
    s.pending = s.node;
    s.node = n.parent;
    s.phase = kAscend;
    if (!bounds.node_here(s.node)) return;
  }
}

// The hit record of a finished traversal. The barycentrics come from testing the hit
// triangle once more: the test is deterministic, so they are the values found during the
// traversal, and the state need not carry them.
template <class Memory>
inline ClosestHit finish_traversal(const Memory& mem, const TraversalState& s, const TraceRay& ray) {
  if (s.hit_triangle == kNoTriangle) return {false, ray.tmax, 0.0f, 0.0f, 0u, 0u, 0u};
  const TriangleRecord& tri = mem.triangle(s.hit_triangle);
  TrianglePartial partial = {0.0f, 0.0f, 0.0f, 0.0f, 1.0f};
  triangle_hit_test(load_vec3(tri.v0), load_vec3(tri.v1), load_vec3(tri.v2), ray.origin, ray.dir, &partial);
  const TriangleHit h = triangle_finish(partial);
  return {true, s.t_best, h.b1, h.b2, tri.primitive, tri.material, s.hit_triangle};
}

namespace detail {

template <bool kAnyHit, class Memory, class Observer>
inline ClosestHit traverse(const Memory& mem, uint32_t root, const TraceRay& ray, Observer& obs) {
  TraversalState s = start_traversal(root, ray);
  advance<kAnyHit>(mem, s, ray, obs, EverywhereBounds{});
  return finish_traversal(mem, s, ray);
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
