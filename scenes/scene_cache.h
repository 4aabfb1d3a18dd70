// On-disk cache of built scene images, keyed by scene content and build parameters, so a
// second run of a big scene skips the BVH build. A cached file is used only after it passes
// every check of SceneImage (size, magic, version, checksum, structure) and its key matches;
// a truncated, corrupt or stale file is reported and rebuilt, never trusted.
#pragma once

#include <filesystem>

#include "scenes/scene_image.h"

namespace strata::scenes {

// The cache directory: $STRATA_CACHE_DIR, else $XDG_CACHE_HOME/strata-tlm, else
// ~/.cache/strata-tlm, else a folder in the system temp directory.
std::filesystem::path default_cache_dir();

std::filesystem::path cache_file_for(const std::filesystem::path& dir, uint64_t key);

// Loads the image from `cache_dir` or builds it (and stores it there). An empty
// `cache_dir` disables the cache. `report` says which happened and why.
SceneImage load_or_build_scene_image(const Scene& scene, const SceneImageParams& params,
                                     const std::filesystem::path& cache_dir,
                                     SceneBuildReport* report);

// Reads an image file and validates it (throws SceneError naming the file).
SceneImage read_scene_image(const std::filesystem::path& file);
void write_scene_image(const SceneImage& image, const std::filesystem::path& file);

}  // namespace strata::scenes
