// The TRaX baseline kernel: each thread takes pixels by atomic increment of a global
// register and traces each path to completion with the bit-stack traversal in
// general-purpose instructions. Built natively, it is the native twin (the golden model).
//
// `Machine` supplies the STRaTA intrinsics the kernel needs (here only the global-register
// atomic increment; natively a plain counter, on RISC-V the custom instruction) and a hook
// `ray_issued(ray, type)` that sees every ray before it is traced (a no-op on RISC-V; the
// host uses it to record the rays for replay in other tracers).
#pragma once

#include "firmware/kernels/path_shading.h"

namespace strata::kernels {

struct KernelContext {
  SceneView scene;
  const FrameParams* frame;
  Pixel* framebuffer;
  RayCounters* counters;  // this thread's record
};

// Counts in 32-bit fields of a per-sample object; trace_sample adds them to the thread's
// counters once, so the hot loop does no 64-bit memory arithmetic.
struct CountingObserver {
  uint32_t nodes = 0, triangles = 0;
  void node_visited(uint32_t) { ++nodes; }
  void leaf_visited(uint32_t) {}
  void triangle_tested() { ++triangles; }
};

// One sample of one pixel, traced to the end of its path.
template <class Arithmetic, class Machine>
inline Vec3f trace_sample(Machine& machine, const KernelContext& ctx, uint32_t pixel,
                          uint32_t sample_index) {
  const FrameParams& f = *ctx.frame;
  const uint32_t root = ctx.scene.header().root_node;
  CountingObserver obs;
  PathState path = start_path(sample_index);
  TraceRay ray = camera_ray(f, pixel, sample_index);
  uint32_t type = kPrimaryRay;
  for (;;) {
    ++ctx.counters->rays[type];
    machine.ray_issued(ray, type);
    const ClosestHit hit = trace_closest(ctx.scene, root, ray, obs);
    if (!hit.hit) {
      shade_miss<Arithmetic>(ctx.scene, &path);
      break;
    }
    ++ctx.counters->hits[type];
    const HitShading s =
        shade_hit<Arithmetic>(ctx.scene, f, ray, hit, ctx.scene.triangle(hit.triangle_offset), &path);
    if (s.has_shadow_ray) {
      ++ctx.counters->rays[kShadowRay];
      machine.ray_issued(s.shadow_ray, kShadowRay);
      if (trace_any(ctx.scene, root, s.shadow_ray, obs).hit)
        ++ctx.counters->hits[kShadowRay];
      else
        add_radiance<Arithmetic>(&path, shadow_contribution(ctx.scene, s.weight, s.geometry));
    }
    if (!s.has_bounce_ray) break;
    ray = s.bounce_ray;
    type = kBounceRay;
  }
  ctx.counters->node_visits += obs.nodes;
  ctx.counters->triangle_tests += obs.triangles;
  ++ctx.counters->paths;
  return path.radiance;
}

// The per-thread kernel: pixels are handed out one at a time; all samples of a pixel are
// traced by the thread that took it, so the pixel's sum has a fixed order. The thread counts
// rays in its own local memory (its stack) and writes the totals out once at the end, as
// hardware event counters would, so statistics add no traffic to the caches.
// Arithmetic: how a path keeps throughput and radiance (path_shading.h). The TRaX firmware keeps
// them exact; the native twin of a design with the compact path state keeps them packed.
template <class Arithmetic = ExactPathArithmetic, class Machine>
inline void baseline_kernel(Machine& machine, const KernelContext& shared) {
  RayCounters counters = {};
  KernelContext ctx = shared;
  ctx.counters = &counters;
  const FrameParams& f = *ctx.frame;
  const uint32_t pixels = f.width * f.height;
  const float inv_spp = 1.0f / float(f.samples_per_pixel);
  for (;;) {
    const uint32_t pixel = machine.atomic_increment(kPixelCounterRegister);
    if (pixel >= pixels) break;
    Vec3f sum{0.0f, 0.0f, 0.0f};
    for (uint32_t s = 0; s < f.samples_per_pixel; ++s)
      sum = sum + trace_sample<Arithmetic>(machine, ctx, pixel, pixel * f.samples_per_pixel + s);
    const Vec3f avg = sum * inv_spp;
    ctx.framebuffer[pixel] = {{avg.x, avg.y, avg.z}};
  }
  *shared.counters = counters;
}

}  // namespace strata::kernels
