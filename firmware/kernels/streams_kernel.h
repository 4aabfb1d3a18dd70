// The STRaTA streaming kernels (ARCHITECTURE.md, "Ray stream memory" and "Treelets"). Rays
// live in the stream memory, one LIFO buffer per treelet. A TM is assigned a treelet; its TPs
// pop rays from that buffer and traverse them until the ray needs another treelet (a child or
// parent in another node treelet, or a leaf's triangle treelet), where it is pushed. A ray
// that finishes its traversal is handed to its path, which replaces it with the path's next
// ray (shadow, bounce, or the first ray of a new sample or pixel), pushed to the root treelet:
// one ray in, one ray out, so the rays in flight stay at the capacity filled at the start.
//
// Where a path's state lives between its rays is the Paths policy (design.path_state):
//   - CompactPaths (streams_compact_paths.h): in the ray itself, a 64-byte stream entry;
//   - RecordPaths (streams_record_paths.h): a 96-byte record per path in a table the platform
//     places on chip (in the stream memory) or in DRAM; the ray is 48 bytes.
// The traversal is traverse.h's state machine and the path computations path_shading.h's, so
// the image and the ray statistics equal the native twin's bit for bit.
//
// Policies: Machine supplies the stream, global-register and id intrinsics; Pipeline supplies
// the box/triangle tests (general-purpose, or the fused pipelines) and configures the TM's
// pipeline mode for the kind of treelet a TP works on.
#pragma once

#include "firmware/abi/strata_isa.h"
#include "firmware/kernels/baseline_kernel.h"
#include "firmware/kernels/stream_ray.h"

namespace strata::kernels {

constexpr uint32_t kNoStreamTreelet = STRATA_NO_TREELET;

inline uint32_t log2_u32(uint32_t v) {
  uint32_t s = 0;
  while ((1u << s) < v) ++s;
  return s;
}

// How a path pushes a ray: to a treelet's buffer, retrying while the memory is full.
template <class Machine>
struct StreamPort {
  Machine& machine;
  uint32_t root_node;
  uint32_t root_treelet;

  template <class Ray>
  void push(const Ray& r, uint32_t treelet) {
    while (!machine.stream_push(&r, treelet)) {
    }  // full: the TP stalls and retries; the ray is never dropped
  }
};

template <class Machine, class Pipeline, class Paths>
class StreamsKernel {
 public:
  using Ray = typename Paths::Ray;

  StreamsKernel(Machine& m, Pipeline& p, Paths& paths, const KernelContext& ctx)
      : m_(m), pipe_(p), paths_(paths), ctx_(ctx) {
    const SceneImageHeader& h = ctx_.scene.header();
    bounds_.node_shift = log2_u32(h.treelet_bytes / uint32_t(sizeof(BvhNode)));
    bounds_.treelet_shift = log2_u32(h.treelet_bytes);
    bounds_.node_treelets = h.node_treelet_count;
    work_items_ = paths_.work_items();
  }

  void run() {
    // Fill: as many paths as the stream memory holds, less one ray per thread: a thread that
    // popped a ray holds a slot for its replacement, so the fill can never fail or deadlock.
    const uint32_t capacity = m_.stream_capacity();
    const uint32_t threads = m_.thread_count();
    uint32_t slots = capacity > threads ? capacity - threads : 1u;
    if (slots > paths_.path_limit()) slots = paths_.path_limit();
    for (;;) {
      const uint32_t slot = m_.atomic_increment(kFillSlotRegister);
      if (slot >= slots || !paths_.start_pixel(slot)) break;
    }
    for (;;) {
      const uint32_t treelet = m_.stream_assign();
      if (treelet == kNoStreamTreelet) {
        if (m_.global_read(kPixelsDoneRegister) >= work_items_) break;
        continue;  // rays are still in other threads' hands
      }
      Ray r;
      if (!m_.stream_pop(&r)) continue;  // another TP took the last one: ask again
      // The TM's assignment may have moved on since this TP asked (another TP emptied the
      // buffer and took a new one), so the ray itself says which treelet it is in.
      process(r, bounds_.next_treelet(Paths::state(r)));
    }
    paths_.resolve();
  }

 private:
  STRATA_INLINE void process(Ray& r, uint32_t treelet) {
    const bool triangles = treelet >= bounds_.node_treelets;
    pipe_.enter_treelet(triangles);
    bounds_.treelet = treelet;
    TraversalState s = Paths::state(r);
    const TraceRay ray = paths_.trace_ray(r);
    CountingObserver obs;
    if (Paths::type(r) == kShadowRay)
      advance<true>(ctx_.scene, s, ray, obs, bounds_, pipe_.tests());
    else
      advance<false>(ctx_.scene, s, ray, obs, bounds_, pipe_.tests());
    ctx_.counters->node_visits += obs.nodes;
    ctx_.counters->triangle_tests += obs.triangles;
    if (s.phase != kTraversalDone) {
      Paths::suspend(r, s);
      paths_.port().push(r, bounds_.next_treelet(s));
      return;
    }
    complete(r, s.hit_triangle, s.t_best);
  }

  // Out of line, and given scalars, not the state and the ray: a ray completes once but steps
  // through treelets many times. With the path's shading inlined into process(), or with the
  // state and the ray passed by reference, GCC for RV32 keeps both in memory on every step:
  // the pipelined kernel ran 15-30% more instructions, nearly all loads and stores.
  __attribute__((noinline)) void complete(const Ray& r, uint32_t hit_triangle, float t_best) {
    TraversalState s{};
    s.phase = kTraversalDone;
    s.hit_triangle = hit_triangle;
    s.t_best = t_best;
    paths_.complete(r, s, paths_.trace_ray(r));
  }

  Machine& m_;
  Pipeline& pipe_;
  Paths& paths_;
  KernelContext ctx_;
  TreeletBounds bounds_{};
  // Every path is finished when kPixelsDoneRegister reaches the frame's work items: its pixels,
  // or its samples when a pixel's samples are in flight together.
  uint32_t work_items_ = 0;
};

// Box and triangle tests in general-purpose instructions (the "streams only" design).
struct GeneralPurposeTests {
  void enter_treelet(bool) {}
  SoftwareTests tests() const { return SoftwareTests(); }
};

// Runs a streaming kernel with per-thread counters kept in local memory and written once.
// PathsOf<Machine> is the path-state policy; `extra` is what it needs beyond the kernel context
// (the record kernels' path table).
template <template <class> class PathsOf, class Machine, class Pipeline, class... Extra>
inline void run_streams_kernel(Machine& machine, Pipeline& pipeline, const KernelContext& shared,
                               const Extra&... extra) {
  RayCounters counters = {};
  KernelContext ctx = shared;
  ctx.counters = &counters;
  const uint32_t root = ctx.scene.header().root_node;
  const uint32_t node_shift = log2_u32(ctx.scene.header().treelet_bytes / uint32_t(sizeof(BvhNode)));
  StreamPort<Machine> port{machine, root, root >> node_shift};
  PathsOf<Machine> paths(port, ctx, extra...);
  StreamsKernel<Machine, Pipeline, PathsOf<Machine>>(machine, pipeline, paths, ctx).run();
  *shared.counters = counters;
}

}  // namespace strata::kernels
