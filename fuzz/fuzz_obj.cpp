// The OBJ loader on arbitrary text: SceneError or a valid scene, nothing else.
#include "fuzz_file.h"
#include "scenes/load_obj.h"
#include "scenes/validate.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  strata::scenes::Scene scene;
  try {
    strata::scenes::load_obj(scene, strata::fuzz::input_file(data, size, "input.obj"));
  } catch (const strata::scenes::SceneError&) {
  }
  return 0;
}
