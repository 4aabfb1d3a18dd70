// The 48-byte ray the stream memory holds (ARCHITECTURE.md, "Ray stream memory"): origin and
// direction (24 B), the traversal state (20 B) and the bit stack (4 B). Its meta word keeps 24
// bits for the path: the record-per-path kernels (streams_record_paths.h) put the path's slot
// in the path table there; the compact kernel (streams_compact_paths.h) its vertex count and a
// flag, and carries the rest of the path's state in 16 more bytes (CompactRay).
#pragma once

#include <stdint.h>

#include "firmware/common/traverse.h"
#include "firmware/abi/frame_abi.h"

namespace strata::kernels {

struct StreamRay {
  float origin[3];
  float dir[3];
  float t_best;           // closest hit so far; starts at the ray's tmax (tmin is always 0)
  uint32_t node;
  uint32_t stack;         // the traversal bit stack
  uint32_t pending;       // leaf reference, or the child a return comes from
  uint32_t hit_triangle;
  uint32_t meta;          // path tag (bits 8..31), ray type (6..7), phase (1..5), leaf side (0)
};
static_assert(sizeof(StreamRay) == 48, "a stream ray is 48 bytes");

inline uint32_t ray_tag(const StreamRay& r) { return r.meta >> 8; }
inline uint32_t ray_type(const StreamRay& r) { return (r.meta >> 6) & 3u; }

inline StreamRay make_stream_ray(const TraceRay& ray, uint32_t type, uint32_t tag, uint32_t root) {
  const TraversalState s = start_traversal(root, ray);
  StreamRay r;
  r.origin[0] = ray.origin.x; r.origin[1] = ray.origin.y; r.origin[2] = ray.origin.z;
  r.dir[0] = ray.dir.x; r.dir[1] = ray.dir.y; r.dir[2] = ray.dir.z;
  r.t_best = s.t_best;
  r.node = s.node;
  r.stack = s.stack;
  r.pending = s.pending;
  r.hit_triangle = s.hit_triangle;
  r.meta = (tag << 8) | (type << 6) | (s.phase << 1) | s.leaf_side;
  return r;
}

inline TraceRay trace_ray_of(const StreamRay& r) {
  // Shadow rays end at the light (t = 1); the others run to infinity.
  const float tmax = ray_type(r) == kShadowRay ? 1.0f : __builtin_inff();
  return {load_vec3(r.origin), load_vec3(r.dir), 0.0f, tmax};
}

inline TraversalState state_of(const StreamRay& r) {
  return {r.node, r.stack, (r.meta >> 1) & 31u, r.pending, r.meta & 1u, r.t_best, r.hit_triangle};
}

inline void store_state(StreamRay& r, const TraversalState& s) {
  r.t_best = s.t_best;
  r.node = s.node;
  r.stack = s.stack;
  r.pending = s.pending;
  r.hit_triangle = s.hit_triangle;
  r.meta = (r.meta & ~63u) | (s.phase << 1) | s.leaf_side;
}

// A TM's treelet: the traversal may run while its next node or leaf lies inside it.
struct TreeletBounds {
  uint32_t treelet;
  uint32_t node_shift;      // log2(nodes per treelet)
  uint32_t treelet_shift;   // log2(treelet bytes)
  uint32_t node_treelets;   // triangle treelets are numbered after the node treelets

  bool node_here(uint32_t node) const { return (node >> node_shift) == treelet; }
  bool leaf_here(uint32_t ref) const {
    return node_treelets + (leaf_byte_offset(ref) >> treelet_shift) == treelet;
  }
  // Where a suspended traversal must continue.
  uint32_t next_treelet(const TraversalState& s) const {
    return s.phase == kAtLeaf ? node_treelets + (leaf_byte_offset(s.pending) >> treelet_shift)
                              : s.node >> node_shift;
  }
};

}  // namespace strata::kernels
