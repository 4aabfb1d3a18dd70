#include "sim/native_render.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "firmware/kernels/baseline_kernel.h"

namespace strata::sim {
namespace {

// The native stand-in for the chip: its global registers, and an optional ray recorder.
struct NativeMachine {
  uint32_t globals[32] = {};
  std::vector<TraceRay>* ray_log = nullptr;
  uint32_t atomic_increment(uint32_t reg) { return globals[reg]++; }
  void ray_issued(const TraceRay& ray, uint32_t) {
    if (ray_log) ray_log->push_back(ray);
  }
};

struct D3 {
  double x, y, z;
};
D3 operator-(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator*(D3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
D3 cross(D3 a, D3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
D3 normalize(D3 a) { return a * (1.0 / std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z)); }
D3 load(const float* p) { return {p[0], p[1], p[2]}; }
void store(float* dst, D3 v) {
  dst[0] = float(v.x);
  dst[1] = float(v.y);
  dst[2] = float(v.z);
}

}  // namespace

uint64_t RenderResult::total_rays() const {
  return counters.rays[kernels::kPrimaryRay] + counters.rays[kernels::kBounceRay] +
         counters.rays[kernels::kShadowRay];
}

void check_render_settings(const RenderSettings& s) {
  if (s.width == 0 || s.height == 0 || s.width > 16384 || s.height > 16384)
    throw std::invalid_argument("resolution: width and height must be 1..16384, got " +
                                std::to_string(s.width) + "x" + std::to_string(s.height));
  if (s.samples_per_pixel == 0 || s.samples_per_pixel > 65536)
    throw std::invalid_argument("spp: must be 1..65536");
  if (uint64_t(s.width) * s.height * s.samples_per_pixel > 0xFFFFFFFFull)
    throw std::invalid_argument("resolution x spp: more than 2^32 samples in one frame");
  if (s.max_path_vertices == 0 || s.max_path_vertices > 64)
    throw std::invalid_argument("max-path-vertices: must be 1..64");
}

kernels::FrameParams make_frame_params(const SceneImageHeader& h, const RenderSettings& s) {
  kernels::FrameParams f{};
  f.width = s.width;
  f.height = s.height;
  f.samples_per_pixel = s.samples_per_pixel;
  f.max_path_vertices = s.max_path_vertices;
  f.seed = s.seed;
  const D3 eye = load(h.camera_eye);
  const D3 forward = normalize(load(h.camera_target) - eye);
  const D3 right = normalize(cross(forward, load(h.camera_up)));
  const D3 up = cross(right, forward);
  const double half_h = std::tan(h.camera_vfov_degrees * 0.5 * 3.14159265358979323846 / 180.0);
  const double half_w = half_h * double(s.width) / double(s.height);
  store(f.camera_origin, eye);
  store(f.camera_lower_left, (forward - right * half_w) - up * half_h);
  store(f.camera_du, right * (2.0 * half_w / s.width));
  store(f.camera_dv, up * (2.0 * half_h / s.height));
  return f;
}

RenderResult render_native(const scenes::SceneImage& image, const RenderSettings& settings,
                           std::vector<TraceRay>* ray_log) {
  check_render_settings(settings);
  const kernels::FrameParams frame = make_frame_params(image.header(), settings);
  RenderResult result;
  result.image.assign(size_t(settings.width) * settings.height, kernels::Pixel{});
  NativeMachine machine;
  machine.ray_log = ray_log;
  const kernels::KernelContext ctx{kernels::SceneView(image.bytes()), &frame, result.image.data(),
                                   &result.counters};
  const auto t0 = std::chrono::steady_clock::now();
  if (settings.path_arithmetic == PathArithmetic::kPacked)
    kernels::baseline_kernel<kernels::PackedPathArithmetic>(machine, ctx);
  else
    kernels::baseline_kernel<kernels::ExactPathArithmetic>(machine, ctx);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace strata::sim
