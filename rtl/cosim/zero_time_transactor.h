// A zero-time TLM-2.0 transactor for the verilated fused pipelines: the transactions of
// PipelineTransactor (pipeline_transactor.h; one FusedOpExtension per payload, command
// TLM_IGNORE_COMMAND), but b_transport never waits. It runs the operation on C++-mode models
// it clocks itself (clocked_pipelines.h) from the operation's arrival until its result leaves,
// and returns with the annotated delay untouched: simulated time does not move and the SystemC
// scheduler does not run. The RTL chip run (rtl_fused_backend.h) uses it so that a TM gets the
// RTL's values at the point the C++ model would have given them, with nothing else in the
// chip able to run in between: a clock toggled in delta cycles would let the other TMs'
// threads run inside a TM's burst and reorder their requests to the shared memory system
// (docs/rtl-cosim.md, "RTL inside a chip run").
//
// One operation at a time, so nothing queues (queued_cycles = 0); the cycles in the extension
// are the clocked pipeline's own (clocked_pipelines.h). A payload without the extension or
// with another command gets TLM_COMMAND_ERROR_RESPONSE; a pipeline that gives no result,
// TLM_GENERIC_ERROR_RESPONSE.
#pragma once

#include <cstdint>
#include <string>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_target_socket.h>

#include "rtl/cosim/clocked_pipelines.h"
#include "rtl/cosim/fused_op_extension.h"

namespace strata::rtl {

class ZeroTimeTransactor : public sc_core::sc_module {
 public:
  static constexpr uint64_t kResetCycles = ClockedPipelines::kResetCycles;

  tlm_utils::simple_target_socket<ZeroTimeTransactor> socket;

  explicit ZeroTimeTransactor(sc_core::sc_module_name name);

  // Rising edges of each pipeline's clock so far (reset included).
  uint64_t box_cycle() const { return pipelines_.box_cycle(); }
  uint64_t triangle_cycle() const { return pipelines_.triangle_cycle(); }
  // The pipelines' VCD (ClockedPipelines::open_vcd, close_vcd, trace_from, trace_off).
  ClockedPipelines& pipelines() { return pipelines_; }

 private:
  void b_transport(tlm::tlm_generic_payload& payload, sc_core::sc_time& delay);

  ClockedPipelines pipelines_;
};

}  // namespace strata::rtl
