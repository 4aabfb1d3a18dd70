// Sampled timing inside a TM (docs/sampled-timing.md): the functional fast-forward that runs
// a TP's instructions in batches at the rates its TM measured (tm_sampler.h keeps those).
#include <algorithm>
#include <cmath>

#include "model/tm/tm_thread_processor.h"

namespace strata::tm {

using transport::AccessClass;
using transport::Cycle;

namespace {
iss::HookResult deferred() {
  iss::HookResult r;
  r.status = iss::HookStatus::kDefer;
  return r;
}
bool shared_op(iss::Op op) {
  const iss::InstrClass c = iss::op_info(op).cls;
  return c == iss::InstrClass::kStrataStream || c == iss::InstrClass::kStrataGlobal;
}
}  // namespace

bool ThreadMultiprocessor::fast_forward(Tp& tp, Cycle until) {
  const Cycle start = tp.timing.next_issue();
  sync_to(start);
  sampler_.update_rates(sampler_.window_of(start), live_tps_);
  const double cpi = sampler_.cpi();
  if (tp.ff_clock + 1.0 <= double(start)) tp.ff_clock = double(start);  // detailed time moved it
  // The batch is sized by the average cost, and charged by what it ran.
  const double span = double(until) - tp.ff_clock;
  const uint64_t batch = span > cpi ? static_cast<uint64_t>(span / cpi) : 1u;
  hook_.tp = &tp;
  sampler_.begin_batch(tp.ff_clock, until);
  if (ff_.warming) {
    ff_.warm_log.clear();
    if (ff_.l1_timed_since_warming) {
      ff_.warm_log.forget();
      ff_.l1_timed_since_warming = false;
    }
    tp.memory.set_warm_log(&ff_.warm_log);
  }
  const iss::RunResult r = tp.hart.run(batch);
  tp.memory.set_warm_log(nullptr);
  hook_.tp = nullptr;
  sampler_.end_batch();
  if (ff_.warming) replay_warm_log(tp);
  counters_.instructions += r.executed;
  ++counters_.fast_forward_batches;
  trace_.instructions(r.executed, port_.global_cycle());
  const uint64_t waits = std::min<uint64_t>(sampler_.batch_waits(), r.executed);
  tp.ff_clock += sampler_.charge(r.executed, waits);
  tp.timing.skip_to(std::max(start + 1, static_cast<Cycle>(std::ceil(tp.ff_clock))));

  tp.forwarded = true;
  if (!error_.empty()) return false;
  if (r.reason != iss::StopReason::kInstructionLimit && r.reason != iss::StopReason::kYield &&
      r.reason != iss::StopReason::kDeferred) {
    if (!r.ok()) fail(tp, "firmware stopped: " + iss::describe(r));
    return false;
  }
  return true;
}

void ThreadMultiprocessor::replay_warm_log(const Tp& tp) {
  // The log holds only what changes a tag (tp_memory.h): each entry is one warming request.
  for (const uint64_t e : ff_.warm_log.entries) {
    const uint64_t addr = (e >> 1) << ff_.warm_log.line_shift;
    const bool store = (e & 1u) != 0;
    transport::PooledPayload gp(ff_.pool);
    uint32_t scratch = 0;
    transport::prepare_access(gp, store ? AccessClass::kDataStore : AccessClass::kDataLoad, addr, &scratch, 4,
                              tp.thread_id, tm_id_, transport::kNoTreelet, true, true, false);
    gp.ext().warm = true;
    if (env_.data_classes) gp.ext().data = env_.data_classes->of(static_cast<uint32_t>(addr));
    sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
    data_port->b_transport(*gp, delay);
    ++counters_.warm_requests;
  }
}

bool ThreadMultiprocessor::in_time_order() {
  // As in LT with sync_shared_ops: global time catches up with the op's date first. An op
  // dated past another TP of this TM must wait for that TP, which the TM runs first: the op is
  // deferred (the batch stops before it, and fast_forward() sets the TP's next issue to its
  // date), so the TM's own TPs reach shared state in time order too.
  if (hook_.request_cycle > ff_.others) return false;
  sync_to(hook_.request_cycle, ff_.others, true);
  return true;
}

iss::HookResult ThreadMultiprocessor::execute(const iss::HookCall& call) {
  // Fast-forward: the op is dated as fast_forward() will charge the batch, and the batch stops
  // once its time passes its end (a TP spinning on stream operations would overshoot).
  // One named result and one return, so that execute_op builds it in the caller's slot: with
  // a second return the result was copied out of a temporary with wide loads of narrow,
  // just-written stores, a store-forwarding stall per STRaTA op (about 4% of a fast-forward).
  // With timing.fast_forward_time_order, an op on shared state (stream memory, global
  // registers) first waits for its turn in time order (in_time_order()), or is deferred.
  const bool batch = sampler_.in_batch();
  if (batch) hook_.request_cycle = sampler_.batch_cycle(call.retired_in_run);
  iss::HookResult result =
      batch && ff_.time_order && shared_op(call.op) && !in_time_order() ? deferred() : execute_op(call);
  if (batch) result.yield = sampler_.batch_done_after(call.retired_in_run);
  return result;
}

}  // namespace strata::tm
