// TLM-2.0 transactor for the verilated fused pipelines (rtl/pipelines/box_pipeline.sv,
// triangle_pipeline.sv in Verilator's SystemC mode): a target socket that takes one fused
// operation per transaction (FusedOpExtension, rtl/cosim/fused_op_extension.h), drives the
// RTL's pins cycle by cycle against the transactor's sc_clock, and returns the result with the
// latency it observed.
//
// Design: one SC_METHOD on the clock's rising edge owns every pin. b_transport (any number of
// initiator threads) synchronises to the initiator's local time (waits the annotated delay),
// queues its request and waits on the request's own event. At each rising edge the method
// samples the handshakes (in_valid && in_ready: accepted; out_valid && out_ready: result),
// then presents the oldest queued requests: the box pipeline takes one per cycle (II 1), each
// triangle lane one per 18 cycles (II 18, 2 lanes). The pipelines are in order per lane, so a
// FIFO per lane matches results to requests. A request that arrives at the time of a rising
// edge is presented after that edge (at the next one it can be accepted), whatever the order
// the kernel runs the processes in: the transactor is deterministic.
//
// Timing convention (IEEE 1666 loosely-timed rules): the call first waits the annotated
// delay (the initiator's local time offset), then returns at the rising edge at which the
// result left the pipeline, with the delay set to zero: the simulated time the call took is
// the queueing plus the RTL's latency, and it is not charged a second time through the delay.
// The extension holds the observed cycles (accept, done, latency, queueing, lane).
#pragma once

#include <cstdint>
#include <deque>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_target_socket.h>

#include "Vbox_pipeline.h"
#include "Vtriangle_pipeline.h"
#include "rtl/cosim/fused_op_extension.h"

namespace strata::rtl {

class PipelineTransactor : public sc_core::sc_module {
 public:
  static constexpr int kTriangleLanes = 2;
  static constexpr int kTriangleOperands = 15;
  static constexpr int kBoxOperands = 14;
  static constexpr uint64_t kResetCycles = 2;

  tlm_utils::simple_target_socket<PipelineTransactor> socket;

  SC_HAS_PROCESS(PipelineTransactor);
  PipelineTransactor(sc_core::sc_module_name name, sc_core::sc_time clock_period);

  // Rising edges of the transactor's clock so far.
  uint64_t cycle() const { return cycle_; }
  const sc_core::sc_time& clock_period() const { return clk_.period(); }
  // Operations completed, per pipeline.
  uint64_t box_operations() const { return box_done_; }
  uint64_t triangle_operations() const { return triangle_done_; }

 private:
  struct Request {
    FusedOpExtension* op = nullptr;
    sc_core::sc_time arrived;
    uint64_t first_edge = 0;  // first rising edge after arrival
    sc_core::sc_event done;
  };

  void b_transport(tlm::tlm_generic_payload& payload, sc_core::sc_time& delay);
  void on_edge();
  void drive_box();
  void drive_triangle();

  sc_core::sc_clock clk_;
  sc_core::sc_signal<bool> rst_{"rst", true};

  // Box pipeline pins.
  sc_core::sc_signal<bool> box_in_valid_{"box_in_valid"}, box_in_ready_{"box_in_ready"};
  sc_core::sc_signal<bool> box_out_valid_{"box_out_valid"}, box_out_ready_{"box_out_ready"};
  sc_core::sc_signal<bool> box_out_hit_{"box_out_hit"}, box_out_overlap_{"box_out_overlap"};
  sc_core::sc_signal<uint32_t> box_operand_[kBoxOperands];
  sc_core::sc_signal<uint32_t> box_out_t_entry_{"box_out_t_entry"};
  Vbox_pipeline box_;

  // Triangle pipeline pins (bit l / word l of each: lane l).
  sc_core::sc_signal<uint32_t> tri_in_valid_{"tri_in_valid"}, tri_in_ready_{"tri_in_ready"};
  sc_core::sc_signal<uint32_t> tri_out_valid_{"tri_out_valid"}, tri_out_ready_{"tri_out_ready"};
  sc_core::sc_signal<uint32_t> tri_out_hit_{"tri_out_hit"}, tri_out_exact_{"tri_out_exact"};
  sc_core::sc_signal<uint64_t> tri_operand_[kTriangleOperands];
  sc_core::sc_signal<uint64_t> tri_out_e0_{"tri_out_e0"}, tri_out_e1_{"tri_out_e1"}, tri_out_e2_{"tri_out_e2"},
      tri_out_t_num_{"tri_out_t_num"}, tri_out_t_den_{"tri_out_t_den"};
  Vtriangle_pipeline triangle_;

  uint64_t cycle_ = 0;
  // Requests not yet presented, in arrival order.
  std::deque<Request*> box_queue_, triangle_queue_;
  // The request on the input pins (waiting for in_ready), then those inside the pipeline.
  Request* box_presented_ = nullptr;
  std::deque<Request*> box_in_flight_;
  Request* tri_presented_[kTriangleLanes] = {nullptr, nullptr};
  std::deque<Request*> tri_in_flight_[kTriangleLanes];
  uint64_t tri_last_accept_[kTriangleLanes] = {0, 0};
  uint64_t box_done_ = 0, triangle_done_ = 0;
};

}  // namespace strata::rtl
