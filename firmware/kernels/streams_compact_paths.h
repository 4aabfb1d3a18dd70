// The compact path state of the streaming kernels (design.path_state = compact, the STRaTA
// default): a path has exactly one ray in flight, and that ray carries everything the path
// needs in one 64-byte stream entry. No path table: the stream memory's whole capacity is rays,
// and every ray in flight is a path in flight. docs/path-state.md justifies each field.
//
//   bytes  closest-hit ray (primary, bounce)     shadow ray
//   0-11   origin                                origin
//   12-23  direction                             the pending bounce's direction (the shadow
//                                                ray's own is light - origin, recomputed)
//   24-27  closest hit t                         geometry factor (a shadow ray's t is 1)
//   28-39  node, bit stack, pending              node, bit stack, pending
//   40-43  closest triangle                      unused (an any-hit ray needs none)
//   44-47  meta: phase, side, type, vertex count, pending-bounce flag
//   48-51  sample index (pixel * spp + s): the pixel, the sample, the random sequences
//   52-57  throughput (packed RGB)               weight = throughput * albedo (packed RGB)
//   58-63  radiance so far (packed RGB)          radiance so far (packed RGB)
//
// The shadow ray is traced before the bounce ray is issued (the bounce starts from the shadow
// ray's origin, offset_ray_origin(p, n) for both), so a path never has two rays in flight.
// Throughput and radiance are kept packed (PackedPathArithmetic): the native twin with the same
// arithmetic computes the same image.
//
// The work handed out is a pixel's samples. With one sample per pixel, a path is a pixel. With
// more, the platform gives per-sample slots (BootBlock::sample_slots) and the samples are the
// work: each path is one sample, a pixel's samples are in flight together, and each writes its
// radiance to its own slot. Once every sample is done, the threads sum each pixel's slots in
// sample order (0 + r0, then + r1, ...), the twin's order, whatever order the samples finished
// in. Without slots, a path runs its pixel's samples one after another and the running sum
// lives in the framebuffer.
#pragma once

#include "firmware/kernels/packed_color.h"
#include "firmware/kernels/streams_kernel.h"

namespace strata::kernels {

// The per-sample slots the platform placed (BootBlock::sample_slots), or null.
struct SampleSlots {
  Pixel* pixels;
};

struct CompactRay {
  StreamRay ray;
  uint32_t sample;
  PackedColor throughput;  // a shadow ray: throughput * albedo at its vertex (its weight)
  PackedColor radiance;
};
static_assert(sizeof(CompactRay) == 64, "a compact ray is one 64-byte stream entry");

// The meta word's path tag (stream_ray.h): the vertex count and the pending-bounce flag.
constexpr uint32_t kCompactVertexMask = 0x7Fu;  // max_path_vertices <= 64
constexpr uint32_t kCompactBounceFlag = 0x80u;

// The packed arithmetic (PackedPathArithmetic) rounds each new weight and each radiance sum:
// keep(x) = unpack(pack(x)). This kernel stores those values packed, so it packs at exactly
// those points and unpacks only what it reads: a colour that passes through a ray unchanged is
// copied as bits, never repacked. The values are the twin's, bit for bit.
template <class Machine>
class CompactPaths {
 public:
  using Ray = CompactRay;

  CompactPaths(StreamPort<Machine>& port, const KernelContext& ctx, const SampleSlots& slots)
      : port_(port), ctx_(ctx), f_(*ctx.frame), pixels_(f_.width * f_.height),
        samples_(pixels_ * f_.samples_per_pixel), slots_(slots.pixels),
        inv_spp_(1.0f / float(f_.samples_per_pixel)), unit_(pack_color({1.0f, 1.0f, 1.0f})),
        black_(pack_color({0.0f, 0.0f, 0.0f})) {}

  StreamPort<Machine>& port() { return port_; }
  uint32_t path_limit() const { return 0xFFFFFFFFu; }  // the stream memory and the pixels bound it

  static uint32_t type(const Ray& r) { return ray_type(r.ray); }
  static TraversalState state(const Ray& r) {
    TraversalState s = state_of(r.ray);
    if (type(r) == kShadowRay) {  // its t and hit slots carry path state: an any-hit ray's are fixed
      s.t_best = 1.0f;
      s.hit_triangle = kNoTriangle;
    }
    return s;
  }
  static void suspend(Ray& r, const TraversalState& s) {
    const float t_slot = r.ray.t_best;
    const uint32_t hit_slot = r.ray.hit_triangle;
    store_state(r.ray, s);
    if (type(r) == kShadowRay) {
      r.ray.t_best = t_slot;
      r.ray.hit_triangle = hit_slot;
    }
  }
  TraceRay trace_ray(const Ray& r) const {
    if (type(r) != kShadowRay) return trace_ray_of(r.ray);
    const Vec3f origin = load_vec3(r.ray.origin);
    return {origin, shadow_direction(ctx_.scene, origin), 0.0f, 1.0f};
  }

  // Out of line: a path starts once, and inlined into the kernel's loop its two ways of
  // handing out work made GCC spill the traversal state there (+9% loads on a Cornell frame).
  __attribute__((noinline)) bool start_pixel(uint32_t) {
    if (slots_) {
      const uint32_t sample = port_.machine.atomic_increment(kSampleCounterRegister);
      if (sample >= samples_) return false;
      start_sample(sample / f_.samples_per_pixel, sample);
      return true;
    }
    const uint32_t pixel = port_.machine.atomic_increment(kPixelCounterRegister);
    if (pixel >= pixels_) return false;
    start_sample(pixel, pixel * f_.samples_per_pixel);
    return true;
  }

  // The work items the kernel waits for (kPixelsDoneRegister counts them done).
  uint32_t work_items() const { return slots_ ? samples_ : pixels_; }

  // After every path is done: each pixel's samples summed from their slots in sample order,
  // the pixels shared out among the threads. Once per thread, out of line.
  __attribute__((noinline)) void resolve() {
    if (!slots_) return;
    const uint32_t spp = f_.samples_per_pixel;
    for (;;) {
      const uint32_t pixel = port_.machine.atomic_increment(kResolveCounterRegister);
      if (pixel >= pixels_) return;
      const Pixel* slot = slots_ + pixel * spp;
      Vec3f sum{0.0f, 0.0f, 0.0f};
      for (uint32_t s = 0; s < spp; ++s) sum = sum + load_vec3(slot[s].rgb);
      const Vec3f avg = sum * inv_spp_;
      ctx_.framebuffer[pixel] = {{avg.x, avg.y, avg.z}};
    }
  }

  void complete(const Ray& r, const TraversalState& s, const TraceRay& ray) {
    const uint32_t type = ray_type(r.ray);
    const uint32_t vertex = ray_tag(r.ray) & kCompactVertexMask;
    if (type == kShadowRay) {
      complete_shadow(r, s);
      return;
    }
    PathState path{unpack_color(r.throughput), {0.0f, 0.0f, 0.0f}, r.sample, vertex};
    const ClosestHit hit = finish_traversal(ctx_.scene, s, ray);
    if (!hit.hit) {
      path.radiance = unpack_color(r.radiance);
      shade_miss<PackedPathArithmetic>(ctx_.scene, &path);
      finish_sample(path.sample, path.radiance);
      return;
    }
    ++ctx_.counters->hits[type];
    // Exact here, packed below: the weight is rounded once, where it is stored.
    const HitShading sh =
        shade_hit<ExactPathArithmetic>(ctx_.scene, f_, ray, hit, ctx_.scene.triangle(hit.triangle_offset), &path);
    const PackedColor weight = pack_color(sh.weight);
    if (sh.has_shadow_ray)
      emit_shadow(sh, path, weight, r.radiance);
    else if (sh.has_bounce_ray)
      emit_closest(sh.bounce_ray, kBounceRay, path.sample, path.vertex, weight, r.radiance);
    else
      finish_sample(path.sample, unpack_color(r.radiance));
  }

 private:
  void complete_shadow(const Ray& r, const TraversalState& s) {
    PackedColor radiance = r.radiance;
    if (s.hit_triangle != kNoTriangle) {
      ++ctx_.counters->hits[kShadowRay];
    } else {
      const Vec3f light = shadow_contribution(ctx_.scene, unpack_color(r.throughput), r.ray.t_best);
      radiance = pack_color(unpack_color(r.radiance) + light);
    }
    const uint32_t tag = ray_tag(r.ray);
    if (tag & kCompactBounceFlag) {
      // The bounce starts where the shadow ray did, with the weight as its throughput.
      const TraceRay bounce{load_vec3(r.ray.origin), load_vec3(r.ray.dir), 0.0f, __builtin_inff()};
      emit_closest(bounce, kBounceRay, r.sample, tag & kCompactVertexMask, r.throughput, radiance);
    } else {
      finish_sample(r.sample, unpack_color(radiance));
    }
  }

  void emit_closest(const TraceRay& ray, uint32_t type, uint32_t sample, uint32_t vertex, PackedColor throughput,
                    PackedColor radiance) {
    ++ctx_.counters->rays[type];
    CompactRay c;
    c.ray = make_stream_ray(ray, type, vertex, port_.root_node);
    c.sample = sample;
    c.throughput = throughput;
    c.radiance = radiance;
    port_.push(c, port_.root_treelet);
  }

  // The shadow ray, holding the bounce that follows it (if any) in the slots it does not need.
  void emit_shadow(const HitShading& sh, const PathState& path, PackedColor weight, PackedColor radiance) {
    ++ctx_.counters->rays[kShadowRay];
    CompactRay c;
    const uint32_t tag = path.vertex | (sh.has_bounce_ray ? kCompactBounceFlag : 0u);
    c.ray = make_stream_ray(sh.shadow_ray, kShadowRay, tag, port_.root_node);
    const Vec3f bounce_dir = sh.has_bounce_ray ? sh.bounce_ray.dir : Vec3f{0.0f, 0.0f, 0.0f};
    c.ray.dir[0] = bounce_dir.x;
    c.ray.dir[1] = bounce_dir.y;
    c.ray.dir[2] = bounce_dir.z;
    c.ray.t_best = sh.geometry;
    c.ray.hit_triangle = 0;
    c.sample = path.sample;
    c.throughput = weight;
    c.radiance = radiance;
    port_.push(c, port_.root_treelet);
  }

  void start_sample(uint32_t pixel, uint32_t sample_index) {
    emit_closest(camera_ray(f_, pixel, sample_index), kPrimaryRay, sample_index, 0u, unit_, black_);
  }

  // With slots, the sample's radiance waits in its own slot for resolve(). Without, the pixel's
  // running sum lives in the framebuffer between its samples: only this path writes the pixel,
  // so the sum has the twin's order (0 + r0, then + r1, ...).
  void finish_sample(uint32_t sample, Vec3f radiance) {
    ++ctx_.counters->paths;
    if (slots_) {
      slots_[sample] = {{radiance.x, radiance.y, radiance.z}};
      port_.machine.atomic_increment(kPixelsDoneRegister);  // a work item: this sample
      start_pixel(0);
      return;
    }
    const uint32_t pixel = sample / f_.samples_per_pixel;
    const uint32_t s = sample - pixel * f_.samples_per_pixel;
    Pixel& out = ctx_.framebuffer[pixel];
    const Vec3f before = s == 0 ? Vec3f{0.0f, 0.0f, 0.0f} : load_vec3(out.rgb);
    const Vec3f sum = before + radiance;
    if (s + 1 < f_.samples_per_pixel) {
      out = {{sum.x, sum.y, sum.z}};
      start_sample(pixel, sample + 1);
      return;
    }
    const Vec3f avg = sum * inv_spp_;
    out = {{avg.x, avg.y, avg.z}};
    port_.machine.atomic_increment(kPixelsDoneRegister);
    start_pixel(0);
  }

  StreamPort<Machine>& port_;
  KernelContext ctx_;
  const FrameParams& f_;
  uint32_t pixels_;
  uint32_t samples_;  // pixels * spp: the work when the samples run together
  Pixel* slots_;      // one per sample, or null: a pixel's samples run one after another
  float inv_spp_;
  PackedColor unit_, black_;  // a new path's throughput and radiance
};

}  // namespace strata::kernels
