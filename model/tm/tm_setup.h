// What a TM needs to know of the chip around it: the chip's size, its TPs' stacks, the L1s'
// geometry, whether the design has the stream memory, how a frame is timed, and which TMs
// compute their fused tests with the RTL. The chip fills it from its config
// (model/chip/chip.cpp); the TM never sees the chip's config, so it depends on nothing above it.
#pragma once

#include <cstdint>
#include <vector>

#include "model/sampling/timing_config.h"
#include "model/tm/tm_config.h"
#include "tlm/clock.h"

namespace strata::tm {

struct TmSetup {
  uint32_t tms = 1;
  uint32_t tps_per_tm = 1;
  uint32_t tp_stack_bytes = 2048;  // each TP's local memory, for its stack
  uint32_t l1d_line_bytes = 64, l1d_size_bytes = 32 * 1024;
  uint32_t l1i_line_bytes = 64;
  bool streams = false;  // the design has the ray stream memory (stream ops are legal)
  uint32_t global_register_latency_cycles = 4;
  TmConfig tm;
  sampling::TimingConfig timing;
  transport::Clock clock;
  std::vector<bool> rtl_pipelines;  // per TM: tm.pipeline_impl=rtl computes its fused tests

  uint32_t threads() const { return tms * tps_per_tm; }
};

}  // namespace strata::tm
