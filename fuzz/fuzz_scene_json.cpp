// Scene descriptions (JSON naming meshes, camera, light): SceneError or a scene.
#include "fuzz_file.h"
#include "scenes/scene_spec.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // A mesh for the descriptions to name (the seed's "quad.obj"), beside the input.
  static const bool mesh = [] {
    const char quad[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    strata::fuzz::input_file(reinterpret_cast<const uint8_t*>(quad), sizeof quad - 1, "quad.obj");
    return true;
  }();
  (void)mesh;
  try {
    strata::scenes::load_scene(strata::fuzz::input_file(data, size, "scene.json").string(), STRATA_SOURCE_DIR);
  } catch (const strata::scenes::SceneError&) {
  }
  return 0;
}
