// Scene description files: a small JSON document naming geometry files and setting the
// camera, the point light and the background. Format (also in scenes/README.md):
//
//   {
//     "geometry": ["relative/or/absolute/path.obj", "other.glb"],        // required
//     "camera": {"eye": [x,y,z], "target": [x,y,z], "up": [x,y,z],
//                "vfov_degrees": 45},                                      // optional
//     "light": {"position": [x,y,z], "intensity": [r,g,b] or a number},   // optional
//     "background": [r,g,b]                                                // optional
//   }
//
// - "geometry" is a non-empty array of file names; relative names are relative to the
//   JSON file's directory. .obj goes to load_obj, .gltf/.glb to load_gltf (extension
//   case-insensitive); anything else is an error. Files are loaded in order.
// - Every other field, and every field inside "camera" and "light", is optional and
//   defaults to the values in scene.h.
// - Vectors are arrays of exactly 3 finite numbers. vfov_degrees is in (0, 180).
//   Light intensity and background are >= 0. The camera's eye and target must differ
//   and up must not be parallel to the viewing direction.
// - Unknown keys are errors (a typo must not silently fall back to a default).
#pragma once

#include "scenes/scene.h"

#include <filesystem>

namespace strata::scenes {

// Loads the description and all its geometry. Scene::name is the JSON path. Throws
// SceneError for a missing or malformed file, an unknown key, a wrong type or value
// (message "<file>: <field>: <problem>", e.g. "scene.json: camera.eye: expected an array
// of 3 numbers"), any geometry loading error, and a scene without triangles.
Scene load_scene_description(const std::filesystem::path& json_file);

}  // namespace strata::scenes
