// glTF 2.0 loader (.gltf with embedded or external buffers, and binary .glb).
#pragma once

#include "scenes/scene.h"

#include <filesystem>

namespace strata::scenes {

// Appends the triangles of the file's default scene (else scene 0, else every root node)
// to scene.triangles in world space: node transforms (matrix or translation/rotation/scale)
// are composed down the hierarchy, and a mesh used by several nodes is instanced once per
// node. Every primitive of mode TRIANGLES (or no mode) is loaded, indexed or not;
// TRIANGLE_STRIP and TRIANGLE_FAN are converted to triangles; points and lines are
// skipped with a warning. Each glTF material becomes a scene material whose albedo is
// pbrMetallicRoughness.baseColorFactor.rgb; primitives without one use a grey default.
// Textures are never decoded.
//
// Throws SceneError (message starts with the file) for a missing file, an unsupported
// extension, anything tinygltf rejects, and any index or accessor that points outside
// its array or buffer (checked before reading, so corrupt files cannot cause
// out-of-bounds reads). Finishes with validate_triangles on the appended triangles.
void load_gltf(Scene& scene, const std::filesystem::path& file);

}  // namespace strata::scenes
