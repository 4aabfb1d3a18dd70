#include "sim/scene_source.h"

#include <chrono>
#include <iostream>

#include "scenes/scene_cache.h"
#include "scenes/scene_spec.h"

namespace strata::sim {

void add_scene_build_options(CLI::App* cmd, SceneSourceOptions& o) {
  cmd->add_option("--treelet-bytes", o.params.treelet_bytes, "treelet size in bytes (= L1 size)")
      ->capture_default_str();
  cmd->add_option("--max-leaf", o.params.bvh.max_leaf_triangles, "triangles per leaf, at most")
      ->capture_default_str();
  cmd->add_option("--bins", o.params.bvh.bins, "SAH bins per axis")->capture_default_str();
  cmd->add_option("--treelet-policy", o.treelet_policy, "surface-area or breadth-first")
      ->capture_default_str();
  cmd->add_option("--cache-dir", o.cache_dir,
                  "scene image cache (default: $STRATA_CACHE_DIR or ~/.cache/strata-tlm)");
  cmd->add_flag("--no-cache", o.no_cache, "always build the scene image; never read or write the cache");
}

LoadedScene load_scene_and_image(const SceneSourceOptions& o) {
  scenes::SceneImageParams params = o.params;
  params.treelet_policy = scenes::parse_treelet_policy(o.treelet_policy);
  LoadedScene loaded;
  const auto t0 = std::chrono::steady_clock::now();
  loaded.scene = scenes::load_scene(o.scene, STRATA_SOURCE_DIR);
  loaded.load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const std::string& w : loaded.scene.warnings) std::cerr << "warning: " << w << "\n";
  const std::filesystem::path cache =
      o.no_cache ? std::filesystem::path()
                 : (o.cache_dir.empty() ? scenes::default_cache_dir() : std::filesystem::path(o.cache_dir));
  loaded.image = scenes::load_or_build_scene_image(loaded.scene, params, cache, &loaded.build);
  return loaded;
}

}  // namespace strata::sim
