// Wavefront OBJ loader (geometry + the diffuse colour of its .mtl materials).
#pragma once

#include "scenes/scene.h"

#include <filesystem>

namespace strata::scenes {

// Appends the file's faces to scene.triangles, in world space exactly as written (OBJ has
// no transforms), and its .mtl materials to scene.materials (Kd becomes the albedo).
// Polygons are triangulated. Faces without a material, and all faces when a `mtllib` file
// is missing, use a grey default material (a warning names the missing file).
//
// Throws SceneError (message starts with the file) for: a missing or unreadable file, a
// parse failure, or a face that references a vertex that does not exist (the usual sign
// of a truncated file). Problems the parser tolerates (faces with fewer than 3 vertices,
// unknown usemtl names, a last line without newline) become Scene::warnings.
// Finishes with validate_triangles on the appended triangles.
void load_obj(Scene& scene, const std::filesystem::path& file);

}  // namespace strata::scenes
