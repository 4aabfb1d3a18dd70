// What computes a chip run's fused tests when tm.pipeline_impl=rtl: the factory strata-sim puts
// in the frame's inputs (chip::FrameInputs::pipeline_backend), making one verilated-RTL backend
// per TM that uses it (rtl/cosim/rtl_fused_backend.h). Its only place in sim/, so the model
// never depends on the RTL.
#pragma once

#include <cstdint>
#include <string>

#include "model/chip/chip_config.h"
#include "model/chip/fused_backend_factory.h"

namespace strata::sim {

// The RTL's own VCD, beside the chip's (--vcd): one file per TM, `<vcd_base>.rtl_tm<k>.vcd`,
// recording the fused tests issued in chip cycles [start, end].
struct RtlVcdOptions {
  std::string base;  // empty: no VCD
  uint64_t start = 0, end = ~uint64_t{0};
};

// The VCD file of TM `tm`'s RTL pipelines.
std::string rtl_vcd_path(const std::string& base, uint32_t tm);

// Throws chip::ConfigError naming tm.pipeline_impl when this strata-sim was built without the
// RTL (-DSTRATA_RTL=OFF).
chip::FusedBackendFactory rtl_pipeline_backend(const chip::ChipConfig& config, const RtlVcdOptions& vcd);

}  // namespace strata::sim
