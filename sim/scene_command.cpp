// `strata-sim scene info <scene>`: loads or builds a scene image and prints its statistics.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "scenes/scene_stats.h"
#include "sim/commands.h"
#include "sim/output_file.h"
#include "sim/scene_source.h"

namespace strata::sim {
namespace {

struct SceneInfoOptions {
  SceneSourceOptions source;
  uint32_t rays = 100000;
  uint64_t seed = 1;
  std::string json_out;
};

nlohmann::json to_json(const scenes::Scene& scene, const scenes::SceneImage& image,
                       const scenes::SceneBuildReport& build, double load_seconds,
                       const scenes::BvhStats& bvh, const scenes::TreeletStats& tl,
                       const scenes::CrossingStats& cross, const SceneInfoOptions& o) {
  const SceneImageHeader& h = image.header();
  nlohmann::json j;
  j["scene"] = o.source.scene;
  j["triangles"] = h.triangle_count;
  j["dropped_degenerate_triangles"] = scene.dropped_degenerate;
  j["bounds"] = {{"min", {h.bounds_min[0], h.bounds_min[1], h.bounds_min[2]}},
                 {"max", {h.bounds_max[0], h.bounds_max[1], h.bounds_max[2]}}};
  j["image_bytes"] = h.image_bytes;
  std::vector<uint32_t> histogram(bvh.leaf_size_histogram.begin(), bvh.leaf_size_histogram.end());
  j["bvh"] = {{"inner_nodes", bvh.inner_nodes},     {"leaves", bvh.leaves},
              {"depth", bvh.depth},                 {"max_depth_bound", o.source.params.bvh.max_depth},
              {"sah_cost", bvh.sah_cost},           {"mean_leaf_triangles", bvh.mean_leaf_triangles},
              {"leaf_size_histogram", histogram},   {"max_leaf_triangles", o.source.params.bvh.max_leaf_triangles},
              {"sah_bins", o.source.params.bvh.bins}};
  j["treelets"] = {{"policy", o.source.treelet_policy},
                   {"treelet_bytes", h.treelet_bytes},
                   {"node_treelets", tl.node_treelets},
                   {"triangle_treelets", tl.triangle_treelets},
                   {"node_fill", tl.node_fill},
                   {"triangle_fill", tl.triangle_fill}};
  j["crossings"] = {{"rays", cross.rays},
                    {"seed", o.seed},
                    {"hit_fraction", cross.rays ? double(cross.hits) / double(cross.rays) : 0.0},
                    {"treelet_crossings_per_ray", cross.crossings_per_ray},
                    {"node_visits_per_ray", cross.node_visits_per_ray},
                    {"leaf_visits_per_ray", cross.leaf_visits_per_ray},
                    {"triangle_tests_per_ray", cross.triangle_tests_per_ray}};
  j["timing_seconds"] = {{"load", load_seconds},
                         {"bvh_build", build.bvh_seconds},
                         {"treelets", build.treelet_seconds},
                         {"layout", build.layout_seconds}};
  j["from_cache"] = build.from_cache;
  j["cache"] = build.cache_note;
  return j;
}

void print_summary(const nlohmann::json& j) {
  const auto& b = j["bvh"];
  const auto& t = j["treelets"];
  const auto& c = j["crossings"];
  const auto& s = j["timing_seconds"];
  std::printf("scene            %s\n", j["scene"].get<std::string>().c_str());
  std::printf("triangles        %llu (%llu degenerate dropped)\n",
              j["triangles"].get<unsigned long long>(), j["dropped_degenerate_triangles"].get<unsigned long long>());
  std::printf("bounds           [%g, %g, %g] .. [%g, %g, %g]\n", j["bounds"]["min"][0].get<double>(),
              j["bounds"]["min"][1].get<double>(), j["bounds"]["min"][2].get<double>(),
              j["bounds"]["max"][0].get<double>(), j["bounds"]["max"][1].get<double>(),
              j["bounds"]["max"][2].get<double>());
  std::printf("image            %.1f MiB\n", j["image_bytes"].get<double>() / (1024.0 * 1024.0));
  std::printf("bvh              %u inner nodes, %u leaves, depth %u (bound %u), SAH cost %.2f\n",
              b["inner_nodes"].get<unsigned>(), b["leaves"].get<unsigned>(), b["depth"].get<unsigned>(),
              b["max_depth_bound"].get<unsigned>(), b["sah_cost"].get<double>());
  std::printf("leaf sizes       mean %.2f triangles; histogram (triangles: leaves)",
              b["mean_leaf_triangles"].get<double>());
  const auto& hist = b["leaf_size_histogram"];
  for (size_t k = 1; k < hist.size(); ++k)
    if (hist[k].get<unsigned>() > 0) std::printf(" %zu:%u", k, hist[k].get<unsigned>());
  std::printf("\n");
  std::printf("treelets         %s, %u B each: %u node treelets (mean fill %.1f%%), %u triangle treelets (mean fill %.1f%%)\n",
              t["policy"].get<std::string>().c_str(), t["treelet_bytes"].get<unsigned>(),
              t["node_treelets"].get<unsigned>(), 100.0 * t["node_fill"].get<double>(),
              t["triangle_treelets"].get<unsigned>(), 100.0 * t["triangle_fill"].get<double>());
  std::printf("random rays      %llu (seed %llu), %.1f%% hit: %.2f treelet crossings/ray, "
              "%.1f node visits/ray, %.1f triangle tests/ray\n",
              c["rays"].get<unsigned long long>(), c["seed"].get<unsigned long long>(),
              100.0 * c["hit_fraction"].get<double>(), c["treelet_crossings_per_ray"].get<double>(),
              c["node_visits_per_ray"].get<double>(), c["triangle_tests_per_ray"].get<double>());
  std::printf("time             load %.2f s, BVH build %.2f s, treelets %.2f s, layout %.2f s (wall clock)\n",
              s["load"].get<double>(), s["bvh_build"].get<double>(), s["treelets"].get<double>(),
              s["layout"].get<double>());
  std::printf("cache            %s\n", j["cache"].get<std::string>().c_str());
}

void run_scene_info(const SceneInfoOptions& o) {
  if (!o.json_out.empty()) require_writable_file(o.json_out, "--json");
  const LoadedScene loaded = load_scene_and_image(o.source);
  const nlohmann::json j =
      to_json(loaded.scene, loaded.image, loaded.build, loaded.load_seconds,
              scenes::bvh_stats(loaded.image), scenes::treelet_stats(loaded.image),
              scenes::measure_crossings(loaded.image, o.rays, o.seed), o);
  print_summary(j);
  if (!o.json_out.empty()) {
    write_file_atomically(o.json_out, j.dump(2) + "\n");
  }
}

}  // namespace

void add_scene_command(CLI::App& app) {
  auto* scene = app.add_subcommand("scene", "Scene pipeline: load, build BVH and treelets, report");
  scene->require_subcommand(1);
  auto* info = scene->add_subcommand("info", "Print triangle, BVH and treelet statistics of a scene");
  auto opts = std::make_shared<SceneInfoOptions>();
  info->add_option("scene", opts->source.scene,
                   "scene.json, mesh (.obj/.gltf/.glb), or cornell|hairball|vegetation[:size=F,seed=N]|sibenik")
      ->required();
  add_scene_build_options(info, opts->source);
  info->add_option("--rays", opts->rays, "random rays for the crossing statistics")->capture_default_str();
  info->add_option("--seed", opts->seed, "seed of the random rays")->capture_default_str();
  info->add_option("--json", opts->json_out, "also write the statistics as JSON to this file");
  info->callback([opts] { run_scene_info(*opts); });
}

}  // namespace strata::sim
