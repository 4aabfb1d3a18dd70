// The shipped design configs' folder, and a config load's error, for the config tests.
#pragma once

#include <string>
#include <vector>

#include "model/chip/chip_config.h"

namespace strata::chip::test {

inline std::string config_dir() { return std::string(STRATA_SOURCE_DIR) + "/sim/configs/"; }

// The ConfigError loading `file` with `overrides` throws, or "" when it loads.
inline std::string error_of(const std::string& file, const std::vector<std::string>& overrides) {
  try {
    load_chip_config(file, overrides);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace strata::chip::test
