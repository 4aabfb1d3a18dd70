// Turns what a user types as <scene> into a Scene:
//   path/to/scene.json            a scene description (scenes/README.md)
//   path/to/mesh.obj|.gltf|.glb   bare geometry, with a camera framing its bounds
//   cornell | hairball | vegetation [:size=F][,seed=N]   procedural scenes
//   sibenik                       scenes/data/sibenik.json (needs ../shared)
#pragma once

#include <filesystem>
#include <string>

#include "scenes/scene.h"

namespace strata::scenes {

// `source_dir` is the repository root, where scenes/data/ lives.
Scene load_scene(const std::string& spec, const std::filesystem::path& source_dir);

// A camera and light that show a whole bounding box (used for bare geometry files). Throws
// SceneError naming `source` when the bounds are too large for them to be finite.
void frame_bounds(Scene& scene, const std::string& source);

}  // namespace strata::scenes
