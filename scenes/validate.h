// Checks every loader runs on the triangles it has just appended, so that the BVH builder
// and the intersection pipeline only ever see finite, non-degenerate geometry.
//
// The degenerate-triangle rule (also in scenes/README.md):
//   A triangle is dropped if and only if cross(v1 - v0, v2 - v0), evaluated in float, is
//   exactly the zero vector. That covers repeated vertices and exactly collinear vertices.
//   Such triangles can never be hit, and their zero normal would turn into NaN when shading.
//   Needle-like or very thin triangles whose cross product is tiny but nonzero are KEPT:
//   real meshes contain them, and the intersection code must handle them, not the loader.
//   Dropped triangles are counted in Scene::dropped_degenerate and reported with one
//   warning line per call in Scene::warnings.
#pragma once

#include "scenes/scene.h"

#include <cstddef>
#include <filesystem>
#include <string>

namespace strata::scenes {

// Validates scene.triangles[first, end), which came from `source` (a file name used in
// messages). Throws SceneError if any coordinate is NaN or infinite (a loader cannot guess
// what the author meant); removes zero-area triangles as described above, keeping order.
void validate_triangles(Scene& scene, size_t first, const std::string& source);

// The common last step of every file loader. Loaders build a file's content into a fresh
// `part` (material indices relative to part.materials) so that a file which fails halfway
// leaves the caller's scene untouched. This validates all of part's triangles, then
// appends its triangles (material indices shifted), materials, warnings and drop count.
void append_validated(Scene& scene, Scene&& part, const std::string& source);

// Before opening an input file: throws SceneError "<file>: file not found", or "<file>: not a
// regular file" for a folder, FIFO or device (opening a FIFO would block; issue 39 reported
// both as "file not found", which sent the user looking for a file that was there).
void require_regular_file(const std::filesystem::path& file);

// Throws SceneError("<source>: scene has no triangles") when there is nothing to render.
void require_triangles(const Scene& scene, const std::string& source);

}  // namespace strata::scenes
