// Issue timing of one thread processor (TP): in order, single issue, with a scoreboard of
// when each register's pending value arrives. The functional ISS (model/iss) decides what
// an instruction does; this decides when it issues and when its results can be read.
//
// An instruction issues at the latest of
//   - the TP's next issue slot (the cycle after its previous instruction issued),
//   - fetch_ready (when the caller's instruction fetch delivers it),
//   - its sources, pipeline inputs and destinations (a pending write: no WAW overtaking),
//   - its unit: an XU, a fused pipeline, or the memory system (the caller's answer).
// Its destinations become readable at issue + latency (memory: the caller's result cycle).
// The TP does not wait for results, only for the operands of later instructions.
//
// Usage per instruction, with d = *hart.next_instruction():
//   if (!tp.is_memory(d)) { tp.issue(d, fetch_ready, xus); }
//   else { Cycle at = tp.begin_memory(d, fetch_ready);
//          ... the caller books memory at `at` (or later) and learns when data arrive ...
//          tp.complete_memory(d, accepted, data_ready); }
// No allocation or virtual call on this path.
#pragma once

#include "model/iss/decoder.h"
#include "model/tm/cycle.h"
#include "model/tm/op_timing.h"
#include "model/tm/tp_stats.h"
#include "model/tm/xu_crossbar.h"

#include <array>
#include <cstdint>

namespace strata::tm {

struct IssueTiming {
  Cycle issue;         // the cycle it issued (its unit, pipeline or memory access started)
  Cycle result_ready;  // its destinations are readable from here (configure: the mode is usable)
};

class TpTiming {
 public:
  // `table` must outlive the TP; build it from the same TmConfig as the crossbar.
  explicit TpTiming(const OpTimingTable& table, Cycle start = 0);

  // Everything ready, next issue slot at `start`; counters kept.
  void reset(Cycle start);
  // Only moves the next issue slot (sampled timing's fast-forward, which reset()s once it ends).
  void skip_to(Cycle start) { next_slot_ = start; }

  // Memory-like ops (Route::kMemory) go through begin_memory/complete_memory.
  bool is_memory(const iss::Decoded& d) const { return (*table_)[d.op].route == Route::kMemory; }

  // Issues a non-memory instruction, booking its XU or pipeline (or reconfiguring the
  // crossbar for strata.pipe.*). std::logic_error for a memory-like op.
  IssueTiming issue(const iss::Decoded& d, Cycle fetch_ready, XuCrossbar& xus);

  // Memory-like op, phase 1: the earliest cycle it can issue (slot, fetch and operands).
  Cycle begin_memory(const iss::Decoded& d, Cycle fetch_ready);
  // Phase 2: the memory system accepted it at `issue` (>= begin_memory's answer; the
  // difference is a memory stall) and its result arrives at `result_ready`. Stores and
  // other ops without a destination may pass issue + 1.
  IssueTiming complete_memory(const iss::Decoded& d, Cycle issue, Cycle result_ready);

  Cycle next_issue() const { return next_slot_; }
  // The same, as a clock an ISS can read (Hart::use_cycle_clock): this TP's mcycle.
  const Cycle* clock() const { return &next_slot_; }
  Cycle int_ready(unsigned r) const { return x_ready_[r & 31]; }
  Cycle fp_ready(unsigned r) const { return f_ready_[r & 31]; }
  const TpStats& stats() const { return stats_; }

 private:
  // Where the wait before an instruction ends, cause by cause.
  struct Gate {
    Cycle slot;     // next issue slot
    Cycle fetched;  // max(slot, fetch_ready)
    Cycle ready;    // max(fetched, operands)
    bool memory;    // the latest operand comes from a memory-like op
  };

  Gate gate(const iss::Decoded& d, const OpTiming& t, Cycle fetch_ready) const;
  void retire(const iss::Decoded& d, const OpTiming& t, const Gate& g, Cycle issue, Cycle result,
              bool from_memory, StallCause unit_wait);

  const OpTimingTable* table_;
  std::array<Cycle, 32> x_ready_{};
  std::array<Cycle, 32> f_ready_{};
  uint32_t x_from_memory_ = 0;  // bit r: x[r]'s latest value comes from a memory-like op
  uint32_t f_from_memory_ = 0;
  std::array<Cycle, kPipeStateCount> pipe_ready_{};  // by PipeState bit
  uint8_t pipe_from_memory_ = 0;
  Cycle next_slot_ = 0;
  Gate pending_{};
  iss::Op pending_op_ = iss::Op::kIllegal;
  bool pending_valid_ = false;
  TpStats stats_;
};

}  // namespace strata::tm
