// The batch-query ray file reader: RayFileError or rays, nothing else.
#include "fuzz_file.h"
#include "sim/ray_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const auto rays = strata::sim::read_ray_file(strata::fuzz::input_file(data, size, "rays.bin"));
    for (const auto& r : rays) (void)strata::sim::ray_is_valid(r);
  } catch (const strata::sim::RayFileError&) {
  }
  return 0;
}

// libsystemc, which the library links, calls sc_main; libFuzzer owns main, so this never runs.
extern "C" int sc_main(int, char**) { return 0; }
