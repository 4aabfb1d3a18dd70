// The record-per-path state of the streaming kernels (design.path_state = on-chip or dram): a
// 48-byte ray carries its path's slot, and a 96-byte PathRecord per path in flight keeps what
// the ray does not carry. The platform places the table on chip (in the stream memory, which
// then holds fewer rays) or in DRAM (reached through the caches). A pixel's samples run one
// after another in one slot, so its sum has the twin's order. Floats are kept exact.
#pragma once

#include "firmware/kernels/streams_kernel.h"

namespace strata::kernels {

// One path in flight: what its rays do not carry.
struct PathRecord {
  PathState path;
  Vec3f shadow_radiance;  // added if the pending shadow ray is not occluded
  Vec3f bounce_origin, bounce_dir;
  Vec3f sum;  // this pixel's finished samples
  uint32_t pixel, sample, has_bounce, pad;
};
static_assert(sizeof(PathRecord) == kPathRecordBytes, "PathRecord is the size the platform reserves (frame_abi.h)");

// The path table the platform placed (BootBlock::path_table, path_slots).
struct PathTable {
  PathRecord* records;
  uint32_t slots;
};

template <class Machine>
class RecordPaths {
 public:
  using Ray = StreamRay;
  using Arithmetic = ExactPathArithmetic;

  RecordPaths(StreamPort<Machine>& port, const KernelContext& ctx, const PathTable& table)
      : port_(port), ctx_(ctx), f_(*ctx.frame), paths_(table.records), slots_(table.slots),
        pixels_(f_.width * f_.height), inv_spp_(1.0f / float(f_.samples_per_pixel)) {}

  StreamPort<Machine>& port() { return port_; }
  uint32_t path_limit() const { return slots_; }

  static TraversalState state(const Ray& r) { return state_of(r); }
  static uint32_t type(const Ray& r) { return ray_type(r); }
  static void suspend(Ray& r, const TraversalState& s) { store_state(r, s); }
  TraceRay trace_ray(const Ray& r) const { return trace_ray_of(r); }

  // A path record sums its pixel's samples itself: they run one after another, so every pixel
  // is written by its path when its last sample finishes, and there is nothing to resolve.
  uint32_t work_items() const { return pixels_; }
  void resolve() {}

  bool start_pixel(uint32_t slot) {
    const uint32_t pixel = port_.machine.atomic_increment(kPixelCounterRegister);
    if (pixel >= pixels_) return false;
    PathRecord& rec = paths_[slot];
    rec.pixel = pixel;
    rec.sample = 0;
    rec.sum = {0.0f, 0.0f, 0.0f};
    start_sample(rec, slot);
    return true;
  }

  void complete(const Ray& r, const TraversalState& s, const TraceRay& ray) {
    const uint32_t slot = ray_tag(r);
    const uint32_t type = ray_type(r);
    PathRecord& rec = paths_[slot];
    if (type == kShadowRay) {
      if (s.hit_triangle != kNoTriangle)
        ++ctx_.counters->hits[kShadowRay];
      else
        add_radiance<Arithmetic>(&rec.path, rec.shadow_radiance);
      continue_path(rec, slot);
      return;
    }
    const ClosestHit hit = finish_traversal(ctx_.scene, s, ray);
    if (!hit.hit) {
      shade_miss<Arithmetic>(ctx_.scene, &rec.path);
      finish_sample(rec, slot);
      return;
    }
    ++ctx_.counters->hits[type];
    const HitShading sh =
        shade_hit<Arithmetic>(ctx_.scene, f_, ray, hit, ctx_.scene.triangle(hit.triangle_offset), &rec.path);
    rec.has_bounce = sh.has_bounce_ray ? 1u : 0u;
    if (sh.has_bounce_ray) {
      rec.bounce_origin = sh.bounce_ray.origin;
      rec.bounce_dir = sh.bounce_ray.dir;
    }
    if (sh.has_shadow_ray) {
      rec.shadow_radiance = shadow_contribution(ctx_.scene, sh.weight, sh.geometry);
      emit(sh.shadow_ray, kShadowRay, slot);
    } else {
      continue_path(rec, slot);
    }
  }

 private:
  void emit(const TraceRay& ray, uint32_t type, uint32_t slot) {
    ++ctx_.counters->rays[type];
    port_.push(make_stream_ray(ray, type, slot, port_.root_node), port_.root_treelet);
  }

  void start_sample(PathRecord& rec, uint32_t slot) {
    const uint32_t sample_index = rec.pixel * f_.samples_per_pixel + rec.sample;
    rec.path = start_path(sample_index);
    rec.has_bounce = 0;
    emit(camera_ray(f_, rec.pixel, sample_index), kPrimaryRay, slot);
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
    port_.machine.atomic_increment(kPixelsDoneRegister);
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

  StreamPort<Machine>& port_;
  KernelContext ctx_;
  const FrameParams& f_;
  PathRecord* paths_;
  uint32_t slots_;
  uint32_t pixels_;
  float inv_spp_;
};

}  // namespace strata::kernels
