// Timing parameters of one thread multiprocessor (TM): its thread processors (TPs), the
// shared execution units (XUs) and the fused box and triangle pipelines built from them.
// Defaults follow ../shared/ARCHITECTURE.md; docs/tm-timing.md says where a value is our
// own assumption because the paper does not give it. validate() names the bad field.
#pragma once

#include <cstdint>

namespace strata::tm {

// One class of shared XU. A pipelined unit accepts a new operation every cycle; a
// non-pipelined one is busy for its whole latency.
struct XuUnitConfig {
  uint32_t count;
  uint32_t latency;  // cycles from issue until the result can be read
  bool pipelined;
};

struct XuConfig {
  XuUnitConfig fp_mul{8, 2, true};
  XuUnitConfig fp_add{8, 2, true};  // add, subtract, and conversions (see docs)
  XuUnitConfig fp_cmp{8, 1, true};  // compare, min, max; count is our assumption
  // One divider: an iterative design is the cheap choice for a rarely used unit.
  XuUnitConfig fp_div{1, 16, false};
  // fsqrt.s; the paper names an inverse square root unit and gives no figures, so it is
  // modelled like the divider.
  XuUnitConfig fp_inv_sqrt{1, 16, false};
  XuUnitConfig int_mul{2, 2, true};
  // RV32M div/rem; the paper lists no integer divider, so one iterative unit is assumed.
  XuUnitConfig int_div{1, 16, false};
};

// A fused pipeline chained from general FP multipliers and adders. It accepts up to
// issue_width operations per window of initiation_interval cycles (issue_width
// independent lanes, each taking one operation every initiation_interval cycles).
struct FusedPipelineConfig {
  uint32_t multipliers;
  uint32_t adders;
  uint32_t initiation_interval;
  uint32_t latency;
  uint32_t issue_width;
};

struct PipelineConfig {
  FusedPipelineConfig box{6, 6, 1, 8, 1};
  FusedPipelineConfig triangle{4, 2, 18, 31, 2};
  // strata.tridiv runs on the shared FP divider (busy as for a divide); its three
  // results are ready this many cycles after it starts.
  uint32_t triangle_divide_latency = 16;
  // MUX and latch switching once the units that change have drained.
  uint32_t reconfigure_cycles = 4;
};

// Latencies of the work a TP does itself, without a shared unit.
struct TpConfig {
  uint32_t int_alu_latency = 1;    // integer ALU, lui/auipc, address generation
  uint32_t branch_latency = 1;     // branches and jumps (link register)
  uint32_t system_latency = 1;     // CSR access, fence, ecall, ebreak, mret, wfi
  uint32_t fp_move_latency = 1;    // sign injection, fmv, fclass: bit moves, no arithmetic
  uint32_t id_latency = 1;         // strata.threadid and the other id reads
  uint32_t pipe_input_latency = 1; // strata.settmax into the pipeline input registers
  uint32_t control_latency = 1;    // strata.halt
};

struct TmConfig {
  uint32_t tps = 32;
  TpConfig tp;
  XuConfig xu;
  PipelineConfig pipelines;
  // Each XU calendar remembers this many cycles (rounded up to a power of two). Requests
  // that arrive up to xu_history_cycles behind the newest one are still timed exactly.
  // A TP's request can lie a whole memory wait ahead of its TM's earliest TP: 8192 covers the
  // longest seen on a 128-TM Sibenik frame (fidelity.xu_late_requests stays 0).
  uint32_t xu_horizon_cycles = 8192;
  uint32_t xu_history_cycles = 512;

  // Throws std::invalid_argument naming the first impossible field.
  void validate() const;
};

}  // namespace strata::tm
