// The STRaTA streaming kernels (ARCHITECTURE.md, "Ray stream memory" and "Treelets"). Rays
// live in the stream memory, one LIFO buffer per treelet. A TM is assigned a treelet; its TPs
// pop rays from that buffer and traverse them until the ray needs another treelet (a child or
// parent in another node treelet, or a leaf's triangle treelet), where it is pushed. A ray
// that finishes its traversal is shaded and replaced by its path's next ray (shadow, bounce,
// or the first ray of a new path), pushed to the root treelet: one ray in, one ray out, so the
// rays in flight stay at the capacity filled at the start.
//
// The path computations are path_shading.h's and the traversal is traverse.h's state
// machine, so the image and the ray statistics equal the native twin's bit for bit. A pixel's
// samples run one after another in one path slot, so its sum has the twin's order.
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

// One path in flight: what its rays do not carry.
struct PathRecord {
  PathState path;
  Vec3f shadow_radiance;  // added if the pending shadow ray is not occluded
  Vec3f bounce_origin, bounce_dir;
  Vec3f sum;  // this pixel's finished samples
  uint32_t pixel, sample, has_bounce, pad;
};
static_assert(sizeof(PathRecord) == kPathRecordBytes, "PathRecord is the size the platform reserves (frame_abi.h)");

struct StreamsContext {
  KernelContext kernel;
  PathRecord* paths;
  uint32_t path_slots;
};

inline uint32_t log2_u32(uint32_t v) {
  uint32_t s = 0;
  while ((1u << s) < v) ++s;
  return s;
}

template <class Machine, class Pipeline>
class StreamsKernel {
 public:
  StreamsKernel(Machine& m, Pipeline& p, const StreamsContext& c)
      : m_(m), pipe_(p), ctx_(c.kernel), paths_(c.paths), path_slots_(c.path_slots), f_(*c.kernel.frame) {
    const SceneImageHeader& h = ctx_.scene.header();
    root_ = h.root_node;
    bounds_.node_shift = log2_u32(h.treelet_bytes / uint32_t(sizeof(BvhNode)));
    bounds_.treelet_shift = log2_u32(h.treelet_bytes);
    bounds_.node_treelets = h.node_treelet_count;
    root_treelet_ = root_ >> bounds_.node_shift;
    pixels_ = f_.width * f_.height;
    inv_spp_ = 1.0f / float(f_.samples_per_pixel);
  }

  void run() {
    // Fill: as many paths as the stream memory holds, less one ray per thread: a thread that
    // popped a ray holds a slot for its replacement, so the fill can never fail or deadlock.
    const uint32_t capacity = m_.stream_capacity();
    const uint32_t threads = m_.thread_count();
    uint32_t slots = capacity > threads ? capacity - threads : 1u;
    if (slots > path_slots_) slots = path_slots_;
    for (;;) {
      const uint32_t slot = m_.atomic_increment(kFillSlotRegister);
      if (slot >= slots || !start_pixel(slot)) break;
    }
    for (;;) {
      const uint32_t treelet = m_.stream_assign();
      if (treelet == kNoStreamTreelet) {
        if (m_.global_read(kPixelsDoneRegister) >= pixels_) break;
        continue;  // rays are still in other threads' hands
      }
      StreamRay r;
      if (!m_.stream_pop(&r)) continue;  // another TP took the last one: ask again
      // The TM's assignment may have moved on since this TP asked (another TP emptied the
      // buffer and took a new one), so the ray itself says which treelet it is in.
      process(r, bounds_.next_treelet(state_of(r)));
    }
  }

 private:
  void process(StreamRay& r, uint32_t treelet) {
    const bool triangles = treelet >= bounds_.node_treelets;
    pipe_.enter_treelet(triangles);
    bounds_.treelet = treelet;
    TraversalState s = state_of(r);
    const TraceRay ray = trace_ray_of(r);
    CountingObserver obs;
    if (ray_type(r) == kShadowRay)
      advance<true>(ctx_.scene, s, ray, obs, bounds_, pipe_.tests());
    else
      advance<false>(ctx_.scene, s, ray, obs, bounds_, pipe_.tests());
    ctx_.counters->node_visits += obs.nodes;
    ctx_.counters->triangle_tests += obs.triangles;
    if (s.phase != kTraversalDone) {
      store_state(r, s);
      push(r, bounds_.next_treelet(s));
      return;
    }
    complete(r, s, ray);
  }

  void push(const StreamRay& r, uint32_t treelet) {
    while (!m_.stream_push(&r, treelet)) {
    }  // full: the TP stalls and retries; the ray is never dropped
  }

  void emit(const TraceRay& ray, uint32_t type, uint32_t slot) {
    ++ctx_.counters->rays[type];
    push(make_stream_ray(ray, type, slot, root_), root_treelet_);
  }

  bool start_pixel(uint32_t slot) {
    const uint32_t pixel = m_.atomic_increment(kPixelCounterRegister);
    if (pixel >= pixels_) return false;
    PathRecord& rec = paths_[slot];
    rec.pixel = pixel;
    rec.sample = 0;
    rec.sum = {0.0f, 0.0f, 0.0f};
    start_sample(rec, slot);
    return true;
  }

  void start_sample(PathRecord& rec, uint32_t slot) {
    rec.path = start_path(f_, rec.pixel * f_.samples_per_pixel + rec.sample);
    rec.has_bounce = 0;
    const TraceRay ray = camera_ray(f_, rec.pixel, rec.path.rng);
    emit(ray, kPrimaryRay, slot);
  }

  void finish_sample(PathRecord& rec, uint32_t slot) {
    rec.sum = rec.sum + rec.path.radiance;
    ++ctx_.counters->paths;
    if (++rec.sample < f_.samples_per_pixel) {
      start_sample(rec, slot);
      return;
    }
    const Vec3f avg = rec.sum * inv_spp_;
    ctx_.framebuffer[rec.pixel] = {{avg.x, avg.y, avg.z}};
    m_.atomic_increment(kPixelsDoneRegister);
    start_pixel(slot);
  }

  void continue_path(PathRecord& rec, uint32_t slot) {
    if (!rec.has_bounce) {
      finish_sample(rec, slot);
      return;
    }
    rec.has_bounce = 0;
    emit({rec.bounce_origin, rec.bounce_dir, 0.0f, __builtin_inff()}, kBounceRay, slot);
  }

  void complete(const StreamRay& r, const TraversalState& s, const TraceRay& ray) {
    const uint32_t slot = ray_slot(r);
    const uint32_t type = ray_type(r);
    PathRecord& rec = paths_[slot];
    if (type == kShadowRay) {
      if (s.hit_triangle != kNoTriangle)
        ++ctx_.counters->hits[kShadowRay];
      else
        rec.path.radiance = rec.path.radiance + rec.shadow_radiance;
      continue_path(rec, slot);
      return;
    }
    const ClosestHit hit = finish_traversal(ctx_.scene, s, ray);
    if (!hit.hit) {
      shade_miss(ctx_.scene, &rec.path);
      finish_sample(rec, slot);
      return;
    }
    ++ctx_.counters->hits[type];
    const HitShading sh = shade_hit(ctx_.scene, f_, ray, hit, ctx_.scene.triangle(hit.triangle_offset), &rec.path);
    rec.has_bounce = sh.has_bounce_ray ? 1u : 0u;
    if (sh.has_bounce_ray) {
      rec.bounce_origin = sh.bounce_ray.origin;
      rec.bounce_dir = sh.bounce_ray.dir;
    }
    if (sh.has_shadow_ray) {
      rec.shadow_radiance = sh.shadow_radiance;
      emit(sh.shadow_ray, kShadowRay, slot);
    } else {
      continue_path(rec, slot);
    }
  }

  Machine& m_;
  Pipeline& pipe_;
  KernelContext ctx_;
  PathRecord* paths_;
  uint32_t path_slots_;
  const FrameParams& f_;
  TreeletBounds bounds_{};
  uint32_t root_ = 0, root_treelet_ = 0, pixels_ = 0;
  float inv_spp_ = 1.0f;
};

// Box and triangle tests in general-purpose instructions (the "streams only" design).
struct GeneralPurposeTests {
  void enter_treelet(bool) {}
  SoftwareTests tests() const { return SoftwareTests(); }
};

// Runs a streaming kernel with per-thread counters kept in local memory and written once.
template <class Machine, class Pipeline>
inline void streams_kernel(Machine& machine, Pipeline& pipeline, const StreamsContext& shared) {
  RayCounters counters = {};
  StreamsContext ctx = shared;
  ctx.kernel.counters = &counters;
  StreamsKernel<Machine, Pipeline>(machine, pipeline, ctx).run();
  *shared.kernel.counters = counters;
}

}  // namespace strata::kernels
