#include "model/tm/tp_timing.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace strata::tm {

namespace {

constexpr bool bit(uint32_t mask, unsigned i) { return ((mask >> i) & 1u) != 0; }

void assign_bit(uint32_t& mask, unsigned i, bool value) {
  mask = value ? (mask | (1u << i)) : (mask & ~(1u << i));
}

}  // namespace

TpTiming::TpTiming(const OpTimingTable& table, Cycle start) : table_(&table) { reset(start); }

void TpTiming::reset(Cycle start) {
  x_ready_.fill(0);
  f_ready_.fill(0);
  pipe_ready_.fill(0);
  x_from_memory_ = f_from_memory_ = 0;
  pipe_from_memory_ = 0;
  next_slot_ = start;
  pending_valid_ = false;
}

TpTiming::Gate TpTiming::gate(const iss::Decoded& d, const OpTiming& t, Cycle fetch_ready) const {
  Gate g;
  g.slot = next_slot_;
  g.fetched = std::max(g.slot, fetch_ready);
  Cycle operands = 0;
  bool memory = false;
  auto consider = [&](Cycle at, bool from_memory) {
    if (at > operands) {
      operands = at;
      memory = from_memory;
    }
  };
  // A destination counts too: a pending write to it must land first, so a short op
  // cannot overtake a long one to the same register (WAW).
  const uint8_t regs[4] = {d.rd, d.rs1, d.rs2, d.rs3};
  // In slot order: on a tie the first operand names the stall's cause.
  for (unsigned m = t.int_operands | t.fp_operands; m != 0; m &= m - 1) {
    const unsigned slot = static_cast<unsigned>(__builtin_ctz(m));
    const unsigned r = regs[slot] & 31u;
    if (bit(t.int_operands, slot)) {
      if (r != 0) consider(x_ready_[r], bit(x_from_memory_, r));
    } else {
      consider(f_ready_[r], bit(f_from_memory_, r));
    }
  }
  if (t.reads_pipe != 0)  // only the fused ops and pipeline loads
    for (unsigned b = 0; b < kPipeStateCount; ++b)
      if (bit(t.reads_pipe, b)) consider(pipe_ready_[b], bit(pipe_from_memory_, b));
  g.ready = std::max(g.fetched, operands);
  g.memory = memory;
  return g;
}

void TpTiming::retire(const iss::Decoded& d, const OpTiming& t, const Gate& g, Cycle issue, Cycle result,
                      bool from_memory, StallCause unit_wait) {
  auto stall = [&](StallCause c, Cycle cycles) { stats_.stall_cycles[static_cast<unsigned>(c)] += cycles; };
  stall(StallCause::kFetch, g.fetched - g.slot);
  stall(g.memory ? StallCause::kMemory : StallCause::kOperand, g.ready - g.fetched);
  stall(unit_wait, issue - g.ready);

  // gate() waited for pending writes to the destinations, so `result` is the latest one.
  const uint8_t regs[4] = {d.rd, d.rs1, d.rs2, d.rs3};
  for (unsigned m = t.int_results; m != 0; m &= m - 1) {
    const unsigned r = regs[__builtin_ctz(m)] & 31u;
    if (r != 0) {
      x_ready_[r] = result;
      assign_bit(x_from_memory_, r, from_memory);
    }
  }
  for (unsigned m = t.fp_results; m != 0; m &= m - 1) {
    const unsigned r = regs[__builtin_ctz(m)] & 31u;
    f_ready_[r] = result;
    assign_bit(f_from_memory_, r, from_memory);
  }
  // Pipeline input registers are not waited for on write (strata.settmax may follow a
  // strata.ldray still in flight), so keep whichever write lands last.
  for (unsigned b = 0; t.writes_pipe != 0 && b < kPipeStateCount; ++b) {
    if (bit(t.writes_pipe, b) && result >= pipe_ready_[b]) {
      pipe_ready_[b] = result;
      pipe_from_memory_ = static_cast<uint8_t>(from_memory ? (pipe_from_memory_ | (1u << b))
                                                           : (pipe_from_memory_ & ~(1u << b)));
    }
  }
  next_slot_ = issue + 1;
}

IssueTiming TpTiming::issue(const iss::Decoded& d, Cycle fetch_ready, XuCrossbar& xus) {
  const OpTiming& t = (*table_)[d.op];
  if (t.route == Route::kMemory)
    throw std::logic_error(std::string("TpTiming::issue: ") + iss::op_info(d.op).mnemonic +
                           " is memory-like; use begin_memory/complete_memory");
  const Gate g = gate(d, t, fetch_ready);
  Cycle start = g.ready;
  Cycle result = 0;
  // Latencies of shared resources come from the crossbar that booked them.
  switch (t.route) {
    case Route::kXu:
      start = xus.issue_general(t.xu, g.ready);
      result = start + xus.latency(t.xu);
      break;
    case Route::kFusedMultiplyAdd:
      start = xus.issue_fused_multiply_add(g.ready);
      result = start + xus.fused_multiply_add_latency();
      break;
    case Route::kConfigure:
      // The TP goes on; the crossbar makes the fused ops that need the mode wait for it.
      result = xus.configure(t.mode, g.ready);
      break;
    case Route::kBoxTest:
      start = xus.issue_box_test(g.ready);
      result = start + xus.box_latency();
      break;
    case Route::kTriangleTest:
      start = xus.issue_triangle_test(g.ready);
      result = start + xus.triangle_latency();
      break;
    case Route::kTriangleDivide:
      start = xus.issue_triangle_divide(g.ready);
      result = start + xus.triangle_divide_latency();
      break;
    default:  // Route::kLocal
      result = start + t.latency;
      break;
  }
  retire(d, t, g, start, result, false, StallCause::kStructural);
  return {start, result};
}

Cycle TpTiming::begin_memory(const iss::Decoded& d, Cycle fetch_ready) {
  const OpTiming& t = (*table_)[d.op];
  if (t.route != Route::kMemory)
    throw std::logic_error(std::string("TpTiming::begin_memory: ") + iss::op_info(d.op).mnemonic +
                           " is not memory-like; use issue");
  pending_ = gate(d, t, fetch_ready);
  pending_op_ = d.op;
  pending_valid_ = true;
  return pending_.ready;
}

IssueTiming TpTiming::complete_memory(const iss::Decoded& d, Cycle issue, Cycle result_ready) {
  if (!pending_valid_ || d.op != pending_op_)
    throw std::logic_error(std::string("TpTiming::complete_memory: no begin_memory for ") +
                           iss::op_info(d.op).mnemonic);
  if (issue < pending_.ready)
    throw std::logic_error("TpTiming::complete_memory: issue cycle is before the operands are ready");
  pending_valid_ = false;
  const Cycle result = std::max(result_ready, issue + 1);
  retire(d, (*table_)[d.op], pending_, issue, result, true, StallCause::kMemory);
  return {issue, result};
}

}  // namespace strata::tm
