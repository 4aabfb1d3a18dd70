// `strata-sim render <scene>`: renders a frame with the baseline firmware kernel, either as
// the native twin (compiled for the host) or as RISC-V firmware on one functional ISS hart,
// and writes EXR, PNG preview and statistics JSON named after the engine.
#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "sim/commands.h"
#include "sim/image_output.h"
#include "sim/iss_render.h"
#include "sim/native_render.h"
#include "sim/output_file.h"
#include "sim/ray_file.h"
#include "sim/resolution.h"
#include "sim/scene_source.h"

namespace strata::sim {
namespace {

struct RenderOptions {
  SceneSourceOptions source;
  std::string resolution = "512x512";
  RenderSettings settings;
  float exposure = 1.0f;
  std::string out_dir = "out/render";
  std::string dump_rays;  // ray file of every traced ray, for replay in other tracers
  std::string engine = "native";
  std::string path_arithmetic = "exact";  // native: exact, or packed (the compact path state's twin)
  std::string firmware;  // kernel ELF for --engine iss; default: the one this tree built
  uint64_t max_instructions = UINT64_MAX;
};

const char* engine_description(const std::string& engine) {
  return engine == "iss" ? "functional, untimed: a firmware kernel (baseline unless --firmware) on one RV32IMF ISS hart"
                         : "functional, untimed: the baseline kernel on one host thread";
}

nlohmann::json stats_json(const RenderOptions& o, const RenderResult& r, const IssRunStats* iss) {
  using kernels::kBounceRay;
  using kernels::kPrimaryRay;
  using kernels::kShadowRay;
  const auto& c = r.counters;
  const double rays = double(r.total_rays());
  nlohmann::json j;
  j["mode"] = o.engine == "iss" ? "iss-functional" : "native-twin";
  j["mode_description"] = engine_description(o.engine);
  j["scene"] = o.source.scene;
  j["width"] = o.settings.width;
  j["height"] = o.settings.height;
  j["samples_per_pixel"] = o.settings.samples_per_pixel;
  j["max_path_vertices"] = o.settings.max_path_vertices;
  j["seed"] = o.settings.seed;
  j["path_arithmetic"] = o.path_arithmetic;
  j["paths"] = c.paths;
  const char* names[] = {"primary", "bounce", "shadow"};
  for (uint32_t t : {kPrimaryRay, kBounceRay, kShadowRay})
    j["rays"][names[t]] = {{"traced", c.rays[t]}, {t == kShadowRay ? "occluded" : "hit", c.hits[t]}};
  j["rays"]["total"] = r.total_rays();
  j["node_visits_per_ray"] = rays > 0 ? double(c.node_visits) / rays : 0.0;
  j["triangle_tests_per_ray"] = rays > 0 ? double(c.triangle_tests) / rays : 0.0;
  j["wall_seconds"] = r.seconds;
  j["mrays_per_second"] = r.seconds > 0 ? rays / r.seconds * 1e-6 : 0.0;
  if (iss) {
    j["firmware"] = o.firmware;
    j["instructions"] = iss->instructions;
    j["mips"] = iss->mips();
    for (unsigned k = 0; k < iss::kClassCount; ++k)
      if (iss->counters.by_class[k])
        j["instruction_mix"][iss::class_name(iss::InstrClass(k))] = iss->counters.by_class[k];
    j["register_file"] = {{"int_reads", iss->counters.int_reads}, {"int_writes", iss->counters.int_writes},
                          {"fp_reads", iss->counters.fp_reads}, {"fp_writes", iss->counters.fp_writes}};
  }
  return j;
}

void print_summary(const nlohmann::json& j, const std::string& dir, const std::string& engine) {
  std::printf("mode           %s (%s)\n", j["mode"].get<std::string>().c_str(),
              j["mode_description"].get<std::string>().c_str());
  std::printf("frame          %ux%u, %u spp, at most %u path vertices, seed %u\n",
              j["width"].get<unsigned>(), j["height"].get<unsigned>(),
              j["samples_per_pixel"].get<unsigned>(), j["max_path_vertices"].get<unsigned>(),
              j["seed"].get<unsigned>());
  const auto& r = j["rays"];
  auto pct = [](uint64_t a, uint64_t b) { return b ? 100.0 * double(a) / double(b) : 0.0; };
  const uint64_t p = r["primary"]["traced"], ph = r["primary"]["hit"];
  const uint64_t b = r["bounce"]["traced"], bh = r["bounce"]["hit"];
  const uint64_t s = r["shadow"]["traced"], so = r["shadow"]["occluded"];
  std::printf("rays           %llu primary (%.1f%% hit), %llu bounce (%.1f%% hit), %llu shadow (%.1f%% occluded)\n",
              (unsigned long long)p, pct(ph, p), (unsigned long long)b, pct(bh, b),
              (unsigned long long)s, pct(so, s));
  std::printf("per ray        %.1f node visits, %.2f triangle tests\n",
              j["node_visits_per_ray"].get<double>(), j["triangle_tests_per_ray"].get<double>());
  std::printf("speed          %.2f MRays/s (wall clock, %.2f s, kernel only, 1 thread)\n",
              j["mrays_per_second"].get<double>(), j["wall_seconds"].get<double>());
  if (j.contains("instructions"))
    std::printf("iss            %llu instructions retired, %.0f MIPS (wall clock)\n",
                j["instructions"].get<unsigned long long>(), j["mips"].get<double>());
  std::printf("wrote          %s/%s.exr, %s.png, %s-stats.json\n", dir.c_str(), engine.c_str(),
              engine.c_str(), engine.c_str());
}

void run_render(RenderOptions o) {
  if (o.engine != "native" && o.engine != "iss")
    throw std::invalid_argument("engine: '" + o.engine + "' is not native or iss");
  if (o.engine == "iss" && !o.dump_rays.empty())
    throw std::invalid_argument("dump-rays: only the native engine records rays");
  if (o.path_arithmetic != "exact" && o.path_arithmetic != "packed")
    throw std::invalid_argument("path-arithmetic: '" + o.path_arithmetic + "' is not exact or packed");
  if (o.engine == "iss" && o.path_arithmetic != "exact")
    throw std::invalid_argument("path-arithmetic: the iss engine runs a firmware, whose kernel fixes its arithmetic");
  o.settings.path_arithmetic = o.path_arithmetic == "packed" ? PathArithmetic::kPacked : PathArithmetic::kExact;
  parse_resolution(o.resolution, &o.settings.width, &o.settings.height);
  check_render_settings(o.settings);
  if (!(o.exposure > 0.0f)) throw std::invalid_argument("exposure: must be positive");
  require_writable_dir(o.out_dir, "--out");
  if (!o.dump_rays.empty()) require_writable_file(o.dump_rays, "--dump-rays");
  const LoadedScene loaded = load_scene_and_image(o.source);
  std::vector<TraceRay> rays;
  IssRunStats iss_stats;
  RenderResult r;
  if (o.engine == "iss") {
    if (o.firmware.empty()) o.firmware = default_kernel_elf("baseline");
    r = render_on_iss(loaded.image, o.settings, o.firmware, o.max_instructions, &iss_stats);
  } else {
    r = render_native(loaded.image, o.settings, o.dump_rays.empty() ? nullptr : &rays);
  }
  const std::filesystem::path dir(o.out_dir);
  write_exr(dir / (o.engine + ".exr"), o.settings.width, o.settings.height, r.image);
  write_png_preview(dir / (o.engine + ".png"), o.settings.width, o.settings.height, r.image, o.exposure);
  const nlohmann::json j = stats_json(o, r, o.engine == "iss" ? &iss_stats : nullptr);
  const std::filesystem::path stats_file = dir / (o.engine + "-stats.json");
  write_file_atomically(stats_file, j.dump(2) + "\n");
  print_summary(j, dir.string(), o.engine);
  if (!o.dump_rays.empty()) {
    std::vector<RayRecord> records(rays.size());
    for (size_t i = 0; i < rays.size(); ++i) {
      const TraceRay& t = rays[i];
      records[i] = {{t.origin.x, t.origin.y, t.origin.z}, {t.dir.x, t.dir.y, t.dir.z}, t.tmin, t.tmax};
    }
    write_ray_file(o.dump_rays, records);
    std::printf("wrote          %zu rays to %s\n", records.size(), o.dump_rays.c_str());
  }
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("render", "Render a frame with the native twin or the firmware on the ISS");
  auto opts = std::make_shared<RenderOptions>();
  cmd->add_option("scene", opts->source.scene,
                  "scene.json, mesh (.obj/.gltf/.glb), or cornell|hairball|vegetation[:size=F,seed=N]|sibenik")
      ->required();
  cmd->add_option("--res", opts->resolution, "image size WxH")->capture_default_str();
  cmd->add_option("--spp", opts->settings.samples_per_pixel, "samples (paths) per pixel")->capture_default_str();
  cmd->add_option("--max-path-vertices", opts->settings.max_path_vertices,
                  "closest-hit segments per path (5 = primary + 4 bounces)")->capture_default_str();
  cmd->add_option("--seed", opts->settings.seed, "random seed of the frame")->capture_default_str();
  cmd->add_option("--exposure", opts->exposure, "PNG preview exposure multiplier")->capture_default_str();
  cmd->add_option("--out", opts->out_dir, "output folder")->capture_default_str();
  cmd->add_option("--engine", opts->engine,
                  "native: the kernel compiled for the host (native twin); iss: the RISC-V firmware on one ISS hart")
      ->capture_default_str();
  cmd->add_option("--path-arithmetic", opts->path_arithmetic,
                  "native: how paths keep throughput and radiance, exact floats or packed (the twin of "
                  "design.path_state=compact)")
      ->capture_default_str();
  cmd->add_option("--firmware", opts->firmware, "kernel ELF for --engine iss (default: the baseline kernel built here)");
  cmd->add_option("--max-instructions", opts->max_instructions, "stop the ISS after this many instructions");
  cmd->add_option("--dump-rays", opts->dump_rays,
                  "write every traced ray (primary, bounce, shadow) to this ray file");
  add_scene_build_options(cmd, opts->source);
  cmd->callback([opts] { run_render(*opts); });
}

}  // namespace strata::sim
