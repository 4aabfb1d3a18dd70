// Both verilated fused pipelines as C++-mode models (Verilator --cc), clocked by hand one
// operation at a time: the operation is put on the pins, accepted at the next rising edge (or
// once its lane is ready), and its result taken at the edge where out_valid is seen. No
// SystemC here: the verilated runtime of these models is built without it, and the TLM-2.0
// face is zero_time_transactor.h.
//
// Cycles are rising edges of each pipeline's own clock since construction (the two reset
// edges included), counted separately for the box and the triangle pipeline: a pipeline is
// clocked only while it has an operation. Handshakes are sampled as PipelineTransactor samples
// them (pipeline_transactor.h): an edge sees the pins as they were just before it, so accept,
// done and latency mean the same in both. Triangle tests alternate between the two lanes.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "rtl/cosim/fused_op.h"

namespace strata::rtl {

struct OpTiming {
  uint64_t accept_cycle = 0, done_cycle = 0;  // the edges of acceptance and of the result
  uint32_t latency_cycles = 0;                // done - accept
  uint32_t lane = 0;                          // the triangle lane (0 for a box test)
};

class ClockedPipelines {
 public:
  static constexpr int kTriangleLanes = 2;
  static constexpr uint64_t kResetCycles = 2;

  ClockedPipelines();
  ~ClockedPipelines();
  ClockedPipelines(const ClockedPipelines&) = delete;
  ClockedPipelines& operator=(const ClockedPipelines&) = delete;

  // Throw std::runtime_error if the pipeline gives no result (a broken RTL, not a slow one).
  BoxResult box(const BoxOperands& in, OpTiming* timing);
  TriangleResult triangle(const TriangleOperands& in, OpTiming* timing);

  uint64_t box_cycle() const { return box_cycle_; }
  uint64_t triangle_cycle() const { return triangle_cycle_; }

  // VCD of both pipelines' signals, every level of hierarchy; throws if the file cannot be
  // written. While tracing is on, each half cycle the pipelines are clocked is dumped at the
  // next trace time (1 ps units): trace_from(t) moves it to t unless the dumps already got
  // past t, so the trace's times only increase. trace_off() stops the dumps (the pipelines
  // still run). The file is closed by close_vcd() or with the object.
  void open_vcd(const std::string& path);
  // Closes the VCD (flushing what Verilator buffered) and returns the errno of its first failed
  // write, 0 if every byte was written. Verilator would abort the process on a failed write
  // (a full disk); the file records it instead, so the caller can refuse the file cleanly.
  int close_vcd();
  void trace_from(uint64_t time_ps);
  void trace_off() { tracing_ = false; }

 private:
  struct Models;  // the verilated models and their context, kept out of this header
  template <class Model>
  uint64_t clock(Model& model, uint64_t& cycle);
  void dump();

  std::unique_ptr<Models> m_;
  uint64_t box_cycle_ = 0, triangle_cycle_ = 0;
  int next_lane_ = 0;
  bool tracing_ = false;
  uint64_t trace_time_ = 0;  // the next dump's time
};

}  // namespace strata::rtl
