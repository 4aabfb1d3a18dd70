// The chip designs the simulator knows: what each one is, the mechanisms it has, the kernel it
// runs and the global registers that kernel reports its progress in. `design.name` selects one;
// the config's mechanism flags (design.streams, design.pipelines) must agree with it, so a
// combination no design has (streams off, pipelines on) is an error naming the field instead of
// a frame silently run on another kernel.
//
// Adding a design touches three places (docs/chip-model.md, "Adding a design"): a row in
// kDesigns (design.cpp), its kernel (firmware/kernels/<kernel>_main.cpp, and <kernel>_compact
// for a streaming design's compact path state), and its config file (sim/configs/).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/chip/chip_config.h"

namespace strata::chip {

struct Design {
  const char* name;     // design.name
  const char* summary;  // one line, for the docs and for errors
  bool streams;         // ray stream memory and treelet scheduling (else TRaX-style, L2 only)
  bool pipelines;       // fused box and triangle pipelines (else general-purpose XUs only)
  // firmware/kernels/<kernel>_main.cpp. A streaming design runs <kernel>_compact under
  // design.path_state=compact, whose rays carry their path's state.
  const char* kernel;
  // The global register the kernel counts finished work in (firmware/abi/frame_abi.h): pixels
  // handed out for a kernel that finishes a pixel before taking the next, pixels or samples done
  // for a streaming one.
  uint32_t done_register;
};

// Every design, in the order the docs list them.
const std::vector<Design>& designs();

// The design called `name`; throws ConfigError naming design.name and the designs there are.
const Design& design_named(const std::string& name);

// The design the config selects, checked: an unknown design.name, or a mechanism flag that
// contradicts the design, throws ConfigError naming the field.
const Design& checked_design(const DesignConfig& config);

// A DesignConfig of the design called `name` with its flags filled in (for tests and tools).
DesignConfig design_config(const std::string& name, PathStatePlacement path_state = PathStatePlacement::kCompact);

// The kernel the config runs: the design's, or its compact twin under design.path_state=compact.
std::string kernel_of(const DesignConfig& config);

}  // namespace strata::chip
