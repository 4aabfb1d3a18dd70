// `strata-sim arithmetic-error <scene>`: how far the compact path state's packed arithmetic
// moves the image, against the frame's own Monte Carlo noise (docs/path-state.md). Renders the
// native twin three times: exact floats with the frame's seed, packed with the same seed, and
// exact floats with the next seed. The packed frame traces the same rays as the exact one, so
// their difference is the rounding alone; the two exact frames differ by the noise alone.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>

#include "sim/commands.h"
#include "sim/native_render.h"
#include "sim/resolution.h"
#include "sim/scene_source.h"

namespace strata::sim {
namespace {

struct ArithmeticErrorOptions {
  SceneSourceOptions source;
  std::string resolution = "256x256";
  RenderSettings settings;
};

struct Difference {
  double rms = 0, max_abs = 0, max_rel = 0;  // over every channel of every pixel
  double mean_value = 0;                      // of the reference frame's channels
};

Difference difference(const std::vector<kernels::Pixel>& a, const std::vector<kernels::Pixel>& ref) {
  Difference d;
  double sum2 = 0, sum = 0;
  for (size_t i = 0; i < a.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double x = a[i].rgb[c], r = ref[i].rgb[c];
      const double e = std::fabs(x - r);
      sum2 += e * e;
      sum += r;
      d.max_abs = std::max(d.max_abs, e);
      if (r > 0) d.max_rel = std::max(d.max_rel, e / r);
    }
  const double n = 3.0 * double(a.size());
  d.rms = std::sqrt(sum2 / n);
  d.mean_value = sum / n;
  return d;
}

void run_arithmetic_error(ArithmeticErrorOptions o) {
  parse_resolution(o.resolution, &o.settings.width, &o.settings.height);
  check_render_settings(o.settings);
  const LoadedScene loaded = load_scene_and_image(o.source);
  RenderSettings exact = o.settings, packed = o.settings, other_seed = o.settings;
  exact.path_arithmetic = other_seed.path_arithmetic = PathArithmetic::kExact;
  packed.path_arithmetic = PathArithmetic::kPacked;
  other_seed.seed = o.settings.seed + 1;
  const RenderResult e = render_native(loaded.image, exact);
  const RenderResult p = render_native(loaded.image, packed);
  const RenderResult s = render_native(loaded.image, other_seed);
  const bool same_rays = std::memcmp(&e.counters, &p.counters, sizeof e.counters) == 0;
  const Difference rounding = difference(p.image, e.image);
  const Difference noise_pair = difference(s.image, e.image);
  // Two independent frames differ by sqrt(2) times one frame's noise.
  const double noise = noise_pair.rms / std::sqrt(2.0);
  std::printf("scene          %s, %ux%u, %u spp, %u path vertices, seed %u (native twin, untimed)\n",
              o.source.scene.c_str(), o.settings.width, o.settings.height, o.settings.samples_per_pixel,
              o.settings.max_path_vertices, o.settings.seed);
  std::printf("rays           packed and exact frames trace %s rays (rays, hits, node visits, paths)\n",
              same_rays ? "the same" : "DIFFERENT");
  std::printf("pixel values   mean %.6g (radiance, linear; over all channels of the exact frame)\n",
              rounding.mean_value);
  std::printf("rounding       packed - exact: RMS %.3g, max |diff| %.3g, max relative %.3g\n", rounding.rms,
              rounding.max_abs, rounding.max_rel);
  std::printf("noise          RMS of one frame's Monte Carlo noise %.3g (seeds %u and %u differ by RMS %.3g)\n",
              noise, o.settings.seed, other_seed.seed, noise_pair.rms);
  std::printf("ratio          rounding / noise = %.3g (RMS over RMS)\n", noise > 0 ? rounding.rms / noise : 0.0);
  if (!same_rays) throw std::runtime_error("the packed arithmetic changed the rays traced: a kernel bug");
}

}  // namespace

void add_arithmetic_error_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "arithmetic-error", "Measure the compact path state's packed arithmetic against the image's Monte Carlo noise");
  auto opts = std::make_shared<ArithmeticErrorOptions>();
  cmd->add_option("scene", opts->source.scene,
                  "scene.json, mesh (.obj/.gltf/.glb), or cornell|hairball|vegetation[:size=F,seed=N]|sibenik")
      ->required();
  cmd->add_option("--res", opts->resolution, "image size WxH")->capture_default_str();
  cmd->add_option("--spp", opts->settings.samples_per_pixel, "samples (paths) per pixel")->capture_default_str();
  cmd->add_option("--max-path-vertices", opts->settings.max_path_vertices,
                  "closest-hit segments per path (5 = primary + 4 bounces)")->capture_default_str();
  cmd->add_option("--seed", opts->settings.seed, "random seed of the frame (the noise frame uses seed + 1)")
      ->capture_default_str();
  add_scene_build_options(cmd, opts->source);
  cmd->callback([opts] { run_arithmetic_error(*opts); });
}

}  // namespace strata::sim
