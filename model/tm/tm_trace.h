// A TM's VCD signals (`strata-sim run --vcd`): instructions and fused tests per cycle over each
// window, the pipeline mode, and the treelet its TPs last took. Off until opened: each call
// then costs one test of enabled().
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include <systemc>

#include "model/iss/ops.h"
#include "model/memory/window_trace.h"
#include "tlm/memory_extension.h"

namespace strata::tm {

class TmTrace {
 public:
  TmTrace()
      : mode_(trace_.add_level("pipeline_mode")),
        instructions_(trace_.add_rate("instructions")),
        box_(trace_.add_rate("box_tests")),
        triangle_(trace_.add_rate("triangle_tests")),
        treelet_(trace_.add_level("treelet")) {}

  void open(sc_core::sc_trace_file* file, const std::string& prefix, const memory::TraceWindow& window) {
    trace_.open(file, prefix, window);
  }
  void instructions(uint64_t n, transport::Cycle now) {
    if (trace_.enabled()) trace_.count(instructions_, n, now);
  }
  // A fused test counts in its pipeline's rate; a pipeline configuration sets the mode.
  void pipeline_op(iss::Op op, double mode, transport::Cycle now) {
    if (!trace_.enabled()) return;
    if (op == iss::Op::kStBoxTest) trace_.count(box_, 1, now);
    if (op == iss::Op::kStTriangleTest) trace_.count(triangle_, 1, now);
    if (iss::op_info(op).cls == iss::InstrClass::kStrataPipeConfig) trace_.level(mode_, mode, now);
  }
  void treelet(uint32_t treelet, transport::Cycle now) {
    if (trace_.enabled()) trace_.level(treelet_, treelet == transport::kNoTreelet ? -1.0 : double(treelet), now);
  }

 private:
  memory::WindowTrace trace_;
  std::size_t mode_, instructions_, box_, triangle_, treelet_;
};

}  // namespace strata::tm
