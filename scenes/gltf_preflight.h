// Checks a glTF or GLB file's JSON before tinygltf parses it, for the cases where tinygltf's
// own message would mislead: a glTF 1.0 file ("asset" object not found), a required
// compression extension (an accessor error about bufferViews), and a buffer URI that names a
// folder or a special file (std::bad_alloc, or a read that never ends).
#pragma once

#include <filesystem>
#include <string>

namespace strata::scenes {

// Throws SceneError "<file>: ..." for those cases; returns quietly otherwise (tinygltf then
// reports whatever else is wrong).
void gltf_preflight(const std::filesystem::path& file, bool binary);

}  // namespace strata::scenes
