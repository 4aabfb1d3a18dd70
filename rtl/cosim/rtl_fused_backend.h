// The fused-pipeline backend of a chip run with tm.pipeline_impl=rtl (model/iss/
// fused_pipeline_backend.h): each box and triangle test a TM issues goes as one TLM-2.0
// transaction (FusedOpExtension) to a zero-time transactor in front of the verilated pipelines
// (zero_time_transactor.h), and the RTL's values come back to the hart. The chip's timing
// stays the XU crossbar's; the backend compares the latency the RTL showed with the one the
// TM config charges and counts what differs (FusedBackendCounts).
//
// The box pipeline's t_entry is t_near on a miss too; the ISA returns +inf on a miss, and a
// triangle miss keeps the previous partial (pipeline_reference.h): both substitutions are the
// issuer's, made here, as the ISS makes them around intersect.h.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include "model/iss/fused_pipeline_backend.h"
#include "rtl/cosim/zero_time_transactor.h"

namespace strata::rtl {

// The triangle pipeline's exact-fallback (slow) path is this many cycles longer than its
// ordinary latency (EXACT_TAP - FAST_TAP, rtl/pipelines/triangle_pipeline.sv).
inline constexpr uint32_t kTriangleSlowPathExtraCycles = 2;

struct RtlBackendConfig {
  // What the chip charges (tm.pipelines.box.latency, tm.pipelines.triangle.latency).
  uint32_t box_latency = 8, triangle_latency = 31;
  // Optional VCD of the pipelines' internal signals (empty: none), recording the tests the
  // chip issues in chip cycles [vcd_start, vcd_end]; chip cycle c is at c * ps_per_cycle ps
  // of the trace's time axis, and the RTL's half cycles follow it 1 ps apart
  // (zero_time_transactor.h keeps the times increasing).
  std::string vcd_path;
  uint64_t vcd_start = 0, vcd_end = ~uint64_t{0};
  uint64_t ps_per_cycle = 1000;
  // The chip cycle of the test being issued (for the VCD window and time axis).
  std::function<uint64_t()> cycle;
};

class RtlFusedBackend : public sc_core::sc_module, public iss::FusedPipelineBackend {
 public:
  tlm_utils::simple_initiator_socket<RtlFusedBackend> socket{"socket"};

  RtlFusedBackend(sc_core::sc_module_name name, RtlBackendConfig config);

  iss::BoxTestResult box_test(const strata_pipe_ray& ray, const strata_pipe_box& box) override;
  iss::TriangleTestResult triangle_test(const strata_pipe_ray& ray, const strata_pipe_triangle& tri,
                                        const TrianglePartial& previous) override;
  iss::FusedBackendCounts counts() const override;
  // Closes the VCD (if any); the errno of its first failed write, 0 if none
  // (ClockedPipelines::close_vcd). The caller decides what a failure means for the file.
  int close_vcd() { return transactor_.pipelines().close_vcd(); }

 private:
  // One transaction; fatal if the transactor refuses it (a programming error, not an input's).
  void transport(FusedOpExtension& op);

  RtlBackendConfig config_;
  ZeroTimeTransactor transactor_;
  tlm::tlm_generic_payload payload_;
  iss::FusedBackendCounts counts_;  // the cycles are the transactor's
};

}  // namespace strata::rtl
