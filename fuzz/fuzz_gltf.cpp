// The glTF and GLB loader: the first byte picks the container, the rest is the file.
#include "fuzz_file.h"
#include "scenes/load_gltf.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  strata::scenes::Scene scene;
  try {
    strata::scenes::load_gltf(scene, strata::fuzz::input_file(data + 1, size - 1, (data[0] & 1) ? "in.glb" : "in.gltf"));
  } catch (const strata::scenes::SceneError&) {
  }
  return 0;
}
