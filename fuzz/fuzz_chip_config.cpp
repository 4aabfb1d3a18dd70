// A chip config file and --set overrides: the input up to the first newline-after-a-NUL is the
// file, each further line one override. ConfigError or a finalized config, nothing else.
#include "fuzz_file.h"
#include "model/chip/chip_config.h"

#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const size_t split = text.find('\0');
  const std::string file = text.substr(0, split);
  std::vector<std::string> overrides;
  if (split != std::string::npos) {
    size_t at = split + 1;
    while (at <= text.size()) {
      const size_t end = std::min(text.find('\n', at), text.size());
      overrides.push_back(text.substr(at, end - at));
      at = end + 1;
    }
  }
  try {
    strata::chip::load_chip_config(
        strata::fuzz::input_file(reinterpret_cast<const uint8_t*>(file.data()), file.size(), "config.json"), overrides);
  } catch (const strata::chip::ConfigError&) {
  }
  return 0;
}

// libsystemc, which the library links, calls sc_main; libFuzzer owns main, so this never runs.
extern "C" int sc_main(int, char**) { return 0; }
