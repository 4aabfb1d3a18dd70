// `strata-sim trace`: batch closest-hit ray queries against a scene.
//   trace --scene S --rays rays.bin --out hits.bin        trace a ray file, write a hit file
//   trace --scene S --generate N [--seed K] --out rays.bin   write N random rays instead
// The file formats are in sim/ray_file.h and the README ("Batch ray queries").
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "scenes/scene_spec.h"
#include "sim/commands.h"
#include "sim/output_file.h"
#include "sim/ray_file.h"
#include "sim/scene_source.h"

namespace strata::sim {
namespace {

struct TraceOptions {
  SceneSourceOptions source;  // --scene, BVH/treelet parameters, --cache-dir, --no-cache
  std::string rays_in;
  uint32_t generate = 0;
  uint64_t seed = 1;
  std::string out;
};

double per(uint64_t total, uint64_t n) { return n ? double(total) / double(n) : 0.0; }

// Rays --generate writes at most: 2^27 rays are a 4 GB file, and the rays are built in memory.
constexpr uint32_t kMaxGeneratedRays = 1u << 27;

void run_generate(const TraceOptions& o) {
  if (o.generate > kMaxGeneratedRays)
    throw std::invalid_argument("--generate: at most " + std::to_string(kMaxGeneratedRays) + " rays, got " +
                                std::to_string(o.generate));
  require_writable_file(o.out, "--out");
  require_not_input(o.out, "--out", o.source.scene, "--scene");
  // Only the bounds are needed: no BVH build.
  const scenes::Scene scene = scenes::load_scene(o.source.scene, STRATA_SOURCE_DIR);
  for (const std::string& w : scene.warnings) std::cerr << "warning: " << w << "\n";
  const scenes::Bounds b = scene.bounds();
  write_ray_file(o.out, generate_random_rays(b, o.generate, o.seed));
  std::printf("wrote %u random rays (seed %llu, origins in [%g, %g, %g] .. [%g, %g, %g]) to %s\n",
              o.generate, static_cast<unsigned long long>(o.seed), double(b.min.x),
              double(b.min.y), double(b.min.z), double(b.max.x), double(b.max.y),
              double(b.max.z), o.out.c_str());
}

void run_trace(const TraceOptions& o) {
  // Before anything is read: the hits must not replace the rays (or the scene) they come from.
  require_not_input(o.out, "--out", o.rays_in, "--rays");
  require_not_input(o.out, "--out", o.source.scene, "--scene");
  // The ray file first: a bad file should fail before a long scene build.
  const std::vector<RayRecord> rays = read_ray_file(o.rays_in);
  require_writable_file(o.out, "--out");

  const LoadedScene loaded = load_scene_and_image(o.source);
  const scenes::SceneImage& image = loaded.image;

  TraceStats s;
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<HitRecord> hits = trace_rays(image, rays, &s);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  write_hit_file(o.out, hits);

  if (s.invalid > 0)
    std::cerr << "warning: " << o.rays_in << ": " << s.invalid << " invalid ray"
              << (s.invalid == 1 ? "" : "s") << " (first: ray " << s.first_invalid
              << ") reported as misses; a ray needs finite origin and direction, a non-zero "
                 "direction, finite 0 <= tmin <= tmax (tmax may be +inf)\n";
  std::printf("scene            %s (%u triangles)\n", o.source.scene.c_str(), image.header().triangle_count);
  std::printf("cache            %s\n", loaded.build.cache_note.c_str());
  std::printf("rays             %llu from %s\n", static_cast<unsigned long long>(s.rays), o.rays_in.c_str());
  std::printf("hits             %llu (%.1f%%)\n", static_cast<unsigned long long>(s.hits),
              100.0 * per(s.hits, s.rays));
  std::printf("misses           %llu (%llu invalid rays among them)\n",
              static_cast<unsigned long long>(s.misses), static_cast<unsigned long long>(s.invalid));
  std::printf("speed            %.2f MRays/s (%.3f s wall clock for traversal, 1 thread)\n",
              seconds > 0 ? double(s.rays) / seconds * 1e-6 : 0.0, seconds);
  std::printf("per ray          %.1f node visits, %.1f triangle tests\n", per(s.node_visits, s.rays),
              per(s.triangle_tests, s.rays));
  std::printf("hit file         %s\n", o.out.c_str());
}

}  // namespace

void add_trace_command(CLI::App& app) {
  auto* trace = app.add_subcommand(
      "trace", "Closest-hit queries for a file of rays; or, with --generate, write random rays");
  auto opts = std::make_shared<TraceOptions>();
  trace->add_option("--scene", opts->source.scene,
                    "scene.json, mesh (.obj/.gltf/.glb), or cornell|hairball|vegetation[:size=F,seed=N]|sibenik")
      ->required();
  auto* rays = trace->add_option("--rays", opts->rays_in, "ray file to trace (format: README, \"Batch ray queries\")");
  auto* gen = trace->add_option("--generate", opts->generate,
                                "instead of tracing, write this many random rays (origins in the scene bounds, "
                                "uniform directions, tmin 0, tmax inf) to --out");
  rays->excludes(gen);
  trace->add_option("--seed", opts->seed, "seed of the random rays")->capture_default_str()->needs(gen);
  trace->add_option("--out", opts->out, "hit file to write (ray file with --generate)")->required();
  add_scene_build_options(trace, opts->source);
  trace->callback([opts, rays, gen] {
    if (gen->count() > 0)
      run_generate(*opts);
    else if (rays->count() > 0)
      run_trace(*opts);
    else
      throw CLI::RequiredError("--rays or --generate");
  });
}

}  // namespace strata::sim
