#include "model/chip/design.h"

#include <string>

#include "firmware/abi/frame_abi.h"

namespace strata::chip {
namespace {

const std::vector<Design> kDesigns = {
    {"trax-baseline", "TRaX: general-purpose XUs, every ray traced to the end by its thread, an L2 only", false,
     false, "baseline", kernels::kPixelCounterRegister},
    {"strata-streams", "STRaTA with the ray stream memory and treelet scheduling, general-purpose XUs", true, false,
     "streams", kernels::kPixelsDoneRegister},
    {"strata-streams-pipelines", "STRaTA with the ray stream memory and the fused box and triangle pipelines", true,
     true, "streams_pipelines", kernels::kPixelsDoneRegister},
};

std::string design_list() {
  std::string s;
  for (const Design& d : kDesigns) s += (s.empty() ? "" : ", ") + std::string(d.name);
  return s;
}

const char* yes_no(bool b) { return b ? "true" : "false"; }

}  // namespace

const std::vector<Design>& designs() { return kDesigns; }

const Design& design_named(const std::string& name) {
  for (const Design& d : kDesigns)
    if (name == d.name) return d;
  throw ConfigError("design.name: unknown design \"" + name + "\" (the designs are " + design_list() + ")");
}

const Design& checked_design(const DesignConfig& config) {
  const Design& d = design_named(config.name);
  // The flags name the mechanisms in the config file and the statistics; they must say what
  // the design has, or a frame would run a kernel other than the one the config describes.
  if (config.streams == d.streams && config.pipelines == d.pipelines) return d;
  const bool streams_differ = config.streams != d.streams;
  const std::string field = streams_differ ? "design.streams" : "design.pipelines";
  const bool value = streams_differ ? config.streams : config.pipelines;
  const std::string mechanism = streams_differ ? "ray stream memory" : "fused pipelines";
  const std::string asked = std::string("design.streams=") + yes_no(config.streams) +
                            " and design.pipelines=" + yes_no(config.pipelines);
  std::string hint = " (no design has " + asked + "; the designs are " + design_list() + ")";
  for (const Design& o : kDesigns)
    if (o.streams == config.streams && o.pipelines == config.pipelines)
      hint = std::string(" (the design with ") + asked + " is " + o.name + ")";
  throw ConfigError(field + ": " + yes_no(value) + " contradicts design.name=" + d.name + ", which has " +
                    (value ? "no " : "the ") + mechanism + hint);
}

DesignConfig design_config(const std::string& name, PathStatePlacement path_state) {
  const Design& d = design_named(name);
  DesignConfig c;
  c.name = d.name;
  c.streams = d.streams;
  c.pipelines = d.pipelines;
  c.path_state = path_state;
  return c;
}

std::string kernel_of(const DesignConfig& config) {
  const Design& d = checked_design(config);
  const bool compact = d.streams && config.path_state == PathStatePlacement::kCompact;
  return std::string(d.kernel) + (compact ? "_compact" : "");
}

}  // namespace strata::chip
