// The fused pipelines' timing as the model charges it: the TM config's defaults
// (model/tm/tm_config.h), overridden by the shipped design config that uses the pipelines
// (sim/configs/strata-pipelines.json, keys tm.pipelines.<name>.*) where it sets them. The RTL
// timing tests compare what they measure with this, so the RTL and the model cannot drift.
#pragma once

#include <fstream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "model/tm/tm_config.h"

namespace strata::rtl_test {

inline tm::FusedPipelineConfig configured_pipeline(const std::string& name) {
  const tm::TmConfig defaults;
  tm::FusedPipelineConfig c = name == "box" ? defaults.pipelines.box : defaults.pipelines.triangle;
  const std::string path = std::string(STRATA_SOURCE_DIR) + "/sim/configs/strata-pipelines.json";
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  const nlohmann::json j = nlohmann::json::parse(in);
  const nlohmann::json::json_pointer p("/tm/pipelines/" + name);
  if (j.contains(p)) {
    const nlohmann::json& s = j.at(p);
    auto take = [&](const char* key, uint32_t& field) {
      if (s.contains(key)) field = s.at(key).get<uint32_t>();
    };
    take("multipliers", c.multipliers);
    take("adders", c.adders);
    take("initiation_interval", c.initiation_interval);
    take("latency", c.latency);
    take("issue_width", c.issue_width);
  }
  return c;
}

}  // namespace strata::rtl_test
