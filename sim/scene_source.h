// The scene options every strata-sim command shares (scene spec, BVH and treelet
// parameters, cache), and loading a scene plus its built or cached memory image.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "scenes/scene.h"
#include "scenes/scene_image.h"

namespace strata::sim {

struct SceneSourceOptions {
  std::string scene;
  scenes::SceneImageParams params;
  std::string treelet_policy = "surface-area";
  std::string cache_dir;  // empty: the default cache directory
  bool no_cache = false;
};

// Adds --treelet-bytes, --max-leaf, --bins, --treelet-policy, --cache-dir and --no-cache.
// The scene itself is added by each command (positional or --scene).
void add_scene_build_options(CLI::App* cmd, SceneSourceOptions& o);

struct LoadedScene {
  scenes::Scene scene;
  scenes::SceneImage image;
  scenes::SceneBuildReport build;
  double load_seconds = 0;
};

// Loads the scene (warnings go to stderr) and builds or loads its image.
LoadedScene load_scene_and_image(const SceneSourceOptions& o);

}  // namespace strata::sim
