// The path tracer's physics, shared by every kernel (baseline, streams, pipelines) so they
// compute the same image: pinhole camera rays, Lambertian surfaces lit by one point light
// with a shadow ray at every path vertex, cosine-weighted bounces, at most
// max_path_vertices closest-hit segments per path (5 = primary + 4 bounces: at most 10 rays
// per sample, the paper's 10.5 M segments for 1024x1024).
#pragma once

#include <stdint.h>

#include "firmware/common/ray_offset.h"
#include "firmware/common/traverse.h"
#include "firmware/abi/frame_abi.h"
#include "firmware/kernels/packed_color.h"
#include "firmware/kernels/sampling.h"
#include "firmware/kernels/scene_view.h"

namespace strata::kernels {

constexpr float kInvPi = 0.318309886183790671538f;

// Everything a path carries between its rays.
struct PathState {
  Vec3f throughput;  // product of albedos so far (cosine sampling cancels cos/pdf)
  Vec3f radiance;    // this sample's contribution so far
  uint32_t sample;   // pixel * samples_per_pixel + s: names the path's random sequences
  uint32_t vertex;   // closest-hit segments traced so far
};

// How a path keeps its throughput and radiance between rays. Every kernel applies the policy at
// the same points (each new throughput, each radiance sum), so a kernel that stores them packed
// and the native twin with the same policy compute the same image bit for bit.
struct ExactPathArithmetic {  // float, as computed
  static Vec3f keep(Vec3f v) { return v; }
};
struct PackedPathArithmetic {  // 48-bit shared-exponent RGB (packed_color.h): the compact path state
  static Vec3f keep(Vec3f v) { return quantize_color(v); }
};

inline Vec3f mul(Vec3f a, Vec3f b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }

// Sample `sample_index` = pixel * samples_per_pixel + s, jittered inside its pixel by the
// path's vertex-0 random sequence.
inline TraceRay camera_ray(const FrameParams& f, uint32_t pixel, uint32_t sample_index) {
  PathRng rng(f.seed, sample_index, 0u);
  const float px = float(pixel % f.width) + rng.uniform();
  const float py = float(f.height - 1u - pixel / f.width) + rng.uniform();  // row 0 is the top
  const Vec3f ll = load_vec3(f.camera_lower_left);
  const Vec3f dir = (ll + load_vec3(f.camera_du) * px) + load_vec3(f.camera_dv) * py;
  return {load_vec3(f.camera_origin), dir, 0.0f, __builtin_inff()};
}

inline PathState start_path(uint32_t sample_index) {
  return {{1.0f, 1.0f, 1.0f}, {0.0f, 0.0f, 0.0f}, sample_index, 0u};
}

// What happens after a closest-hit segment found a surface.
struct HitShading {
  bool has_shadow_ray;
  TraceRay shadow_ray;
  Vec3f weight;    // throughput * albedo, kept by the path arithmetic: the next throughput
  float geometry;  // the shadow ray adds shadow_contribution(scene, weight, geometry) if unoccluded
  bool has_bounce_ray;
  TraceRay bounce_ray;
};

// What an unoccluded shadow ray adds: Lambert, albedo / pi * I * cos(theta) / d^2, with the
// albedo and the path's throughput in `weight` and the rest in `geometry`.
inline Vec3f shadow_contribution(const SceneView& scene, Vec3f weight, float geometry) {
  return mul(weight, load_vec3(scene.header().light_intensity)) * geometry;
}

// A shadow ray's unnormalised direction: the light sits at t = 1, so (0, 1) is exactly "before
// it". A function of the origin alone, so a ray that carries its origin need not carry it.
inline Vec3f shadow_direction(const SceneView& scene, Vec3f origin) {
  return load_vec3(scene.header().light_position) - origin;
}

template <class Arithmetic>
inline void add_radiance(PathState* path, Vec3f contribution) {
  path->radiance = Arithmetic::keep(path->radiance + contribution);
}

template <class Arithmetic>
inline HitShading shade_hit(const SceneView& scene, const FrameParams& f, const TraceRay& ray,
                            const ClosestHit& hit, const TriangleRecord& tri, PathState* path) {
  HitShading out{};
  const SceneImageHeader& h = scene.header();
  const Vec3f v0 = load_vec3(tri.v0);
  const Vec3f e1 = load_vec3(tri.v1) - v0;
  const Vec3f e2 = load_vec3(tri.v2) - v0;
  // The hit point from the barycentrics is accurate to the triangle, whatever t's error.
  const Vec3f p = (v0 + e1 * hit.b1) + e2 * hit.b2;
  Vec3f n = normalize(cross(e1, e2));
  if (dot(n, ray.dir) > 0.0f) n = n * -1.0f;  // face the side the ray came from
  const MaterialRecord& m = scene.material(tri.material);
  out.weight = Arithmetic::keep(mul(path->throughput, load_vec3(m.albedo)));

  const Vec3f to_light = load_vec3(h.light_position) - p;
  const float cos_light = dot(n, to_light);
  if (cos_light > 0.0f) {
    const Vec3f origin = offset_ray_origin(p, n);
    const float dist2 = dot(to_light, to_light);
    // cos(theta) / d^2 / pi, with cos(theta) = cos_light / d.
    out.geometry = cos_light / (dist2 * sqrt_f(dist2)) * kInvPi;
    out.has_shadow_ray = true;
    out.shadow_ray = {origin, shadow_direction(scene, origin), 0.0f, 1.0f};
  }
  path->vertex += 1;
  if (path->vertex < f.max_path_vertices) {
    out.has_bounce_ray = true;
    PathRng rng(f.seed, path->sample, path->vertex);
    const Vec3f dir = sample_cosine_hemisphere(n, rng);
    out.bounce_ray = {offset_ray_origin(p, n), dir, 0.0f, __builtin_inff()};
    path->throughput = out.weight;
  }
  return out;
}

template <class Arithmetic>
inline void shade_miss(const SceneView& scene, PathState* path) {
  add_radiance<Arithmetic>(path, mul(path->throughput, load_vec3(scene.header().background)));
  path->vertex += 1;
}

}  // namespace strata::kernels
