// Sampled timing inside a TM (docs/sampled-timing.md): which instructions of a detailed
// window are measured, the rates measured there, and the functional fast-forward that runs
// a TP's instructions in batches at those rates.
#include <cmath>

#include "model/chip/tm_thread_processor.h"

namespace strata::chip {

using transport::Cycle;

bool ThreadMultiprocessor::count_measured(Cycle window, Cycle t) {
  // A TP lagging in an older window does not count; the first TP in a newer one restarts.
  if (window > measure_window_) {
    measure_window_ = window;
    measured_ = measured_waits_ = measured_wait_cycles_ = 0;
  }
  if (window != measure_window_ || t - window < warmup_) return false;
  ++measured_;
  return true;
}

double ThreadMultiprocessor::fast_forward_cpi(Cycle window) {
  // Once per fast-forward stretch. The TM's TPs share its issue slots, XUs and memory, so
  // the TP-cycles of the measured part of the window (its length times the TPs running) are
  // spread over the instructions issued in it. Stream and global-register operations are
  // charged apart, at their measured latency: a TP waiting for work spends its time in them,
  // and must not slow down a TP of the same TM that has work.
  if (cpi_window_ != window) {
    cpi_window_ = window;
    // Fewer instructions than TPs is too little to measure (all stalled, or halting, or the
    // window was missed): keep the rates of the last window that had enough (at first, 1).
    if (window != measure_window_ || measured_ < std::max<uint32_t>(live_tps_, 1)) return cpi_;
    const double tp_cycles = double(detail_ - warmup_) * double(std::max<uint32_t>(live_tps_, 1));
    const double issued = double(measured_);
    const double waits = double(measured_waits_);
    const double wait_cycles = std::min(tp_cycles, double(measured_wait_cycles_));
    cpi_ = tp_cycles / issued;
    wait_cycles_ = waits > 0 ? wait_cycles / waits : double(config_.global_register_latency_cycles);
    compute_cpi_ = std::max(1.0, (tp_cycles - wait_cycles) / std::max(1.0, issued - waits));
  }
  return cpi_;
}

bool ThreadMultiprocessor::fast_forward(Tp& tp, Cycle until) {
  const Cycle start = tp.timing.next_issue();
  sync_to(start);
  const double cpi = fast_forward_cpi(start - start % period_);
  if (tp.ff_clock + 1.0 <= double(start)) tp.ff_clock = double(start);  // detailed time moved it
  // The batch is sized by the average cost, and charged by what it ran.
  const double span = double(until) - tp.ff_clock;
  const uint64_t batch = span > cpi ? static_cast<uint64_t>(span / cpi) : 1u;
  current_ = &tp;
  functional_ = true;
  measuring_ = false;
  ff_start_ = tp.ff_clock;
  ff_until_ = until;
  ff_waits_ = 0;
  const iss::RunResult r = tp.hart.run(batch);
  current_ = nullptr;
  functional_ = false;
  counters_.instructions += r.executed;
  if (trace_.enabled()) trace_.count(tr_instructions_, r.executed, global_cycle_);
  const uint64_t waits = std::min<uint64_t>(ff_waits_, r.executed);
  tp.ff_clock += ff_charge(r.executed, waits);
  tp.timing.skip_to(std::max(start + 1, static_cast<Cycle>(std::ceil(tp.ff_clock))));
  const Cycle charged = tp.timing.next_issue() - start;  // mcycle follows the charged time
  if (charged > r.executed) tp.hart.add_stall_cycles(charged - r.executed);
  tp.forwarded = true;
  if (!error_.empty()) return false;
  if (r.reason != iss::StopReason::kInstructionLimit && r.reason != iss::StopReason::kYield) {
    if (!r.ok()) fail(tp, "firmware stopped: " + iss::describe(r));
    return false;
  }
  return true;
}

iss::HookResult ThreadMultiprocessor::execute(const iss::HookCall& call) {
  if (!functional_) return execute_op(call);
  // Fast-forward: the op is dated as fast_forward() will charge the batch, and the batch stops
  // once its time passes its end (a TP spinning on stream operations would overshoot).
  request_cycle_ = static_cast<Cycle>(ff_start_ + ff_charge(call.retired_in_run, ff_waits_));
  iss::HookResult result = execute_op(call);
  result.yield = ff_start_ + ff_charge(call.retired_in_run + 1, ff_waits_) >= double(ff_until_);
  return result;
}

}  // namespace strata::chip
