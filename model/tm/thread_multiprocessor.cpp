#include "model/tm/thread_multiprocessor.h"

#include <cstdio>
#include <cstring>
#include <utility>

#include "model/tm/tm_thread_processor.h"
#include "model/iss/hart_impl.h"

namespace strata::tm {

using transport::AccessClass;
using transport::Cycle;
using transport::MemoryExtension;
using transport::StreamStatus;

ThreadMultiprocessor::ThreadMultiprocessor(sc_core::sc_module_name name, const TmEnvironment& env,
                                           uint32_t tm_id)
    : sc_core::sc_module(name),
      env_(env),
      setup_(*env.setup),
      tm_id_(tm_id),
      port_(env.setup->clock, env.setup->timing.mode, env.setup->timing.quantum_cycles, tm_id,
            [this](Cycle target) { env_.turns->wait_turn(tm_id_, target); }),
      op_table_(env.setup->tm),
      burst_slack_(env.setup->timing.mode == transport::TimingMode::kPrecise ? 0 : env.setup->timing.tp_slack_cycles),
      sync_all_memory_(env.setup->timing.mode == transport::TimingMode::kPrecise),
      sync_shared_(sync_all_memory_ || env.setup->timing.sync_shared_ops),
      xus_(env.setup->tm),
      sampler_(env.setup->timing, env.schedule, env.setup->global_register_latency_cycles),
      sessions_(env.node_treelets) {
  port_.set_data_classes(env.data_classes);
  while ((1u << fetch_line_shift_) < setup_.l1i_line_bytes) ++fetch_line_shift_;
  ff_.warming = sampler_.enabled() && setup_.timing.functional_warming;
  ff_.time_order = sampler_.enabled() && setup_.timing.fast_forward_time_order;
  sampler_.set_op_classes(setup_.timing.fast_forward_op_classes);
  ff_.warm_log.line_shift = 0;
  while ((1u << ff_.warm_log.line_shift) < setup_.l1d_line_bytes) ++ff_.warm_log.line_shift;
  if (ff_.warming) {
    ff_.warm_log.known.assign(setup_.l1d_size_bytes / setup_.l1d_line_bytes, 0);
    // Not cached, so not warmed: the TPs' stacks (local memory) and on-chip path state.
    ff_.warm_log.skip_lo[0] = env.stacks_base;
    ff_.warm_log.skip_hi[0] = env.stacks_base + uint64_t{setup_.threads()} * setup_.tp_stack_bytes;
    if (env.path_state_on_chip) {
      ff_.warm_log.skip_lo[1] = env.path_begin;
      ff_.warm_log.skip_hi[1] = env.path_end;
    }
  }
  if (setup_.rtl_pipelines.at(tm_id)) {
    if (env.pipeline_backend == nullptr || !*env.pipeline_backend)
      throw std::runtime_error("tm.pipeline_impl: rtl, but the program running the chip supplied no RTL pipeline backend");
    FusedBackendSetup setup;
    setup.tm = tm_id;
    setup.cycle = [this] { return hook_.tp != nullptr ? hook_.tp->timing.next_issue() : port_.global_cycle(); };
    pipeline_backend_ = (*env.pipeline_backend)(setup);
    if (!pipeline_backend_) throw std::runtime_error("tm.pipeline_impl: rtl, but no RTL pipeline backend was made for TM " +
                                              std::to_string(tm_id));
  }
  for (uint32_t tp = 0; tp < setup_.tps_per_tm; ++tp) {
    const uint32_t thread = tm_id * setup_.tps_per_tm + tp;
    tps_.push_back(std::make_unique<Tp>(*env.code, *env.backing, env, this, thread, tp, tm_id, op_table_));
    Tp& t = *tps_.back();
    t.hart.reset(env.entry_pc);
    t.hart.set_x(2, t.stack_hi);  // crt0 keeps a preset sp
    t.hart.use_cycle_clock(t.timing.clock());  // mcycle counts this TP's cycles
    if (env.tohost) t.hart.set_tohost(env.tohost);
    t.pipe.set_backend(pipeline_backend_.get());  // null: the C++ pipeline model
  }
  register_stats();
  SC_THREAD(run);
}

ThreadMultiprocessor::~ThreadMultiprocessor() = default;

void ThreadMultiprocessor::trace(sc_core::sc_trace_file* file, const memory::TraceWindow& window) {
  trace_.open(file, name(), window);
}

tm::TpStats ThreadMultiprocessor::tp_stats() const {
  tm::TpStats sum;
  for (const auto& tp : tps_) {
    const tm::TpStats& s = tp->timing.stats();
    for (size_t i = 0; i < sum.stall_cycles.size(); ++i) sum.stall_cycles[i] += s.stall_cycles[i];
  }
  return sum;
}

iss::Counters ThreadMultiprocessor::iss_counters() const {
  iss::Counters sum;
  for (const auto& tp : tps_) sum += tp->hart.counters();
  return sum;
}

void ThreadMultiprocessor::fail(const Tp& tp, const std::string& what) {
  char where[96];
  std::snprintf(where, sizeof where, "TM %u, TP %u (thread %u), pc 0x%08x: ", tm_id_,
                tp.thread_id % setup_.tps_per_tm, tp.thread_id, tp.hart.pc());
  error_ = where + what;
  sc_core::sc_stop();
}

void ThreadMultiprocessor::sync_to(Cycle t, Cycle others, bool exact) {
  if (!port_.sync_to(t, others, exact)) return;
  // The crossbar may forget what lies before every TP of this TM: the TP being stepped may be
  // up to the TP slack ahead of the others (which can still ask for those cycles).
  const Cycle global = port_.global_cycle();
  xus_.retire_before(global > burst_slack_ ? global - burst_slack_ : 0);
}

Cycle ThreadMultiprocessor::synchronised_issue(Tp& tp) {
  const iss::Decoded* d = tp.hart.next_instruction();
  if (d == nullptr || !tp.timing.is_memory(*d)) return 0;
  if (!sync_all_memory_) {
    const iss::InstrClass cls = iss::op_info(d->op).cls;
    if (cls != iss::InstrClass::kStrataStream && cls != iss::InstrClass::kStrataGlobal) return 0;
  }
  if (!tp.fetched) {
    tp.fetch_ready = fetch(tp, tp.hart.pc());
    tp.fetched = true;
  }
  return tp.timing.begin_memory(*d, tp.fetch_ready);
}

void ThreadMultiprocessor::run() {
  // The TP with the earliest next issue cycle goes next (ties: the lower TP). It keeps
  // issuing until it passes the runner-up (loosely timed: by up to timing.tp_slack_cycles,
  // which the XU and memory calendars absorb, since they accept requests out of time order;
  // precise: not at all), so the schedule is consulted once per burst. Global time never
  // passes a TP of the TM (sync_to), and the ops that must reach shared state in time order
  // (precise: every memory-like op; LT: stream and global-register ops) wait for global time
  // to reach their issue cycle, handing the TM to its other TPs meanwhile.
  schedule_ = TpSchedule(static_cast<uint32_t>(tps_.size()));
  TpSchedule& schedule = schedule_;
  live_tps_ = static_cast<uint32_t>(tps_.size());
  env_.turns->wait_turn(tm_id_, port_.clock().now());  // registers; no TM runs before all have
  port_.observe();
  while (schedule.top() != TpSchedule::kDone && error_.empty()) {
    const uint64_t best = schedule.top();
    const uint64_t second = schedule.runner_up();
    const uint32_t index = static_cast<uint32_t>(best & 63u);
    const Cycle start = best >> 6;
    const Cycle others = second == TpSchedule::kDone ? TpSchedule::kDone : second >> 6;  // the runner-up's cycle
    Cycle until = others == TpSchedule::kDone ? TpSchedule::kDone : others + burst_slack_;
    Tp& tp = *tps_[index];
    // Every TP of this TM issues at or after `start` during this burst.
    xus_.set_floor(start);
    Cycle window = 0;
    if (sampler_.enabled()) {
      window = sampler_.window_of(start);
      if (!sampler_.detailed(start)) {
        // Fast-forward: batches of up to timing.fast_forward_batch_quanta past the runner-up,
        // never into the next detailed window. Nothing is booked; the batch's stream and
        // global-register ops wait for their dates, or stop it when dated past `others`
        // (timing.fast_forward_time_order, tm_fast_forward.cpp).
        const Cycle next_window = sampler_.next_window(window);
        const Cycle ahead = Cycle{setup_.timing.fast_forward_batch_quanta} * setup_.timing.quantum_cycles;
        const Cycle ff_until = others == TpSchedule::kDone ? next_window : std::min(next_window, others + ahead);
        ff_.others = others;
        if (fast_forward(tp, std::max(ff_until, start + 1))) {
          schedule.set(index, tp.timing.next_issue());
        } else {
          counters_.finished_cycle = std::max(counters_.finished_cycle, tp.timing.next_issue());
          schedule.done(index);
          --live_tps_;
        }
        continue;
      }
      until = std::min(until, sampler_.window_end(window));
      if (tp.forwarded) {  // detailed timing resumes with an empty scoreboard
        tp.timing.reset(start);
        tp.fetch_line = 0xFFFFFFFFu;
        tp.fetched = false;
        tp.forwarded = false;
      }
    }
    for (Cycle t = start;; t = tp.timing.next_issue()) {
      sync_to(t, others);
      // An op that must reach shared state in time order is sent when global time reaches
      // the cycle it issues in (its operands and fetch may hold it back); if another TP of
      // this TM issues before then, that one goes first.
      if (sync_shared_) {
        const Cycle at = synchronised_issue(tp);
        if (at > others) {
          schedule.set(index, at);
          break;
        }
        if (at != 0) {
          sync_to(at, others, true);
          tp.begun = true;
          tp.begun_at = at;
        }
      }
      if (sampler_.enabled()) sampler_.count_measured(window, t);
      if (!step(tp)) {
        counters_.finished_cycle = std::max(counters_.finished_cycle, tp.timing.next_issue());
        schedule.done(index);
        --live_tps_;
        break;
      }
      if (tp.timing.next_issue() > until) {
        schedule.set(index, tp.timing.next_issue());
        break;
      }
    }
  }
  finished_ = error_.empty();
  env_.turns->leave();
}

Cycle ThreadMultiprocessor::transact(tlm_utils::simple_initiator_socket<ThreadMultiprocessor>& socket,
                                     AccessClass access, uint64_t addr, void* data, uint32_t bytes, Cycle at,
                                     bool timing_only, uint32_t treelet, Tp& tp) {
  transport::PortAccess a;
  a.access = access;
  a.addr = addr;
  a.data = data;
  a.bytes = bytes;
  a.at = at;
  a.thread = tp.thread_id;
  a.treelet = treelet;
  a.timing_only = timing_only;
  a.functional = sampler_.in_batch();
  a.uncounted = !counting();
  Cycle completed = at;
  if (!port_.access(socket, a, &completed)) fail(tp, port_.refusal());
  return completed;
}

Cycle ThreadMultiprocessor::fetch(Tp& tp, uint32_t pc) {
  // A TP fetches through a one-line buffer: only a change of I-cache line goes to the cache.
  const uint32_t line = pc >> fetch_line_shift_;  // line sizes are powers of two (validated)
  if (line == tp.fetch_line) return 0;
  tp.fetch_line = line;
  if (counting()) ++counters_.icache_fetch_requests;
  uint32_t word = 0;
  return transact(fetch_port, AccessClass::kInstructionFetch, pc, &word, 4, tp.timing.next_issue(), true,
                  transport::kNoTreelet, tp);
}

Cycle ThreadMultiprocessor::time_data_access(Tp& tp, Cycle at) {
  const AccessRecord& r = tp.memory.record();
  const uint32_t stacks_end = env_.stacks_base + setup_.threads() * setup_.tp_stack_bytes;
  if (r.first >= env_.stacks_base && r.first < stacks_end) {
    if (r.first < tp.stack_lo || r.last > tp.stack_hi) {
      fail(tp, "stack access outside this TP's " + std::to_string(setup_.tp_stack_bytes) +
                   "-byte local memory (stack overflow? raise tp_stack_bytes)");
      return at;
    }
    if (counting()) ++counters_.local_accesses;
    return at + 1;  // TP local memory: one cycle, no cache, no contention
  }
  if (env_.path_state_on_chip && r.first >= env_.path_begin && r.first < env_.path_end) {
    // On-chip path state: one access to the stream memory's SRAM, never the L1 (a record
    // field is a word; a wider one is one port access up to a ray's width).
    if (r.last > env_.path_end || r.last - r.first > 48) {
      fail(tp, "path-state access crosses the path records' end or is wider than 48 bytes");
      return at;
    }
    if (counting()) ++counters_.path_state_requests;
    uint8_t scratch[48];
    return transact(stream_port, r.store ? AccessClass::kStreamPathWrite : AccessClass::kStreamPathRead, r.first,
                    scratch, r.last - r.first, at, true, transport::kNoTreelet, tp);
  }
  // One request per cache line touched (a pipeline operand may straddle two lines); they
  // issue together and the access completes with the last of them.
  ff_.l1_timed_since_warming = true;
  const uint32_t line = setup_.l1d_line_bytes;
  uint8_t scratch[256];
  Cycle ready = at;
  for (uint32_t a = r.first; a < r.last && error_.empty();) {
    const uint32_t end = std::min(r.last, (a / line + 1) * line);
    const uint32_t bytes = std::min<uint32_t>(end - a, sizeof scratch);
    if (counting()) ++counters_.l1_requests;
    ready = std::max(ready, transact(data_port, r.store ? AccessClass::kDataStore : AccessClass::kDataLoad, a,
                                     scratch, bytes, at, true, transport::kNoTreelet, tp));
    if (setup_.streams && counting()) sessions_.answered(port_.answer().served_by);  // as the L1 counts fills
    a += bytes;
  }
  return ready;
}

bool ThreadMultiprocessor::step(Tp& tp) {
  const iss::Decoded* d = tp.hart.next_instruction();
  if (d == nullptr) {
    fail(tp, "the pc left the firmware's code");
    return false;
  }
  const Cycle fetch_ready = tp.fetched ? tp.fetch_ready : fetch(tp, tp.hart.pc());
  tp.fetched = false;
  const bool memory_like = tp.timing.is_memory(*d);
  const Cycle earliest = !memory_like ? 0 : tp.begun ? tp.begun_at : tp.timing.begin_memory(*d, fetch_ready);
  tp.begun = false;
  const iss::Decoded decoded = *d;  // the hart may rewrite the code image (self-modifying code)
  tp.memory.record().clear();
  hook_.tp = &tp;
  hook_.request_cycle = earliest;
  hook_.timed = false;
  const iss::RunResult r = tp.hart.run(1);
  hook_.tp = nullptr;
  if (!error_.empty()) return false;
  const bool stopped = r.reason != iss::StopReason::kInstructionLimit;
  if (stopped && !r.ok()) {
    fail(tp, "firmware stopped: " + iss::describe(r));
    return false;
  }
  ++counters_.instructions;
  ++counters_.detailed_instructions;
  if (sampler_.measuring()) {  // sampled timing only: the base of its extrapolation
    ++counters_.measured_instructions;
    if (is_data_op(iss::op_info(decoded.op).cls)) ++counters_.measured_data_ops;
  }
  trace_.instructions(1, port_.global_cycle());
  if (memory_like) {
    Cycle ready = earliest + 1;
    if (tp.memory.record().any) ready = std::max(ready, time_data_access(tp, earliest));
    if (hook_.timed) {
      ready = std::max(ready, hook_.ready);
      if (sampler_.measuring()) sampler_.note_wait(ready - earliest, hook_.op_class);
    }
    tp.timing.complete_memory(decoded, earliest, ready);
  } else {
    // The pipeline mode belongs to the TM. A TP configured it before its fused ops, but
    // another TP of the TM (working on a ray of another treelet kind) may have switched it
    // since: the TM then switches back before the op issues, and pays the switch again.
    const tm::PipelineMode needed = decoded.op == iss::Op::kStBoxTest ? tm::PipelineMode::kBox
                                    : (decoded.op == iss::Op::kStTriangleTest || decoded.op == iss::Op::kStTriangleDivide)
                                        ? tm::PipelineMode::kTriangle
                                        : tm::PipelineMode::kGeneral;
    if (needed != tm::PipelineMode::kGeneral && xus_.mode() != needed) {
      xus_.configure(needed, std::max(fetch_ready, tp.timing.next_issue()));
      ++counters_.forced_reconfigurations;
    }
    tp.timing.issue(decoded, fetch_ready, xus_);
    trace_.pipeline_op(decoded.op, static_cast<double>(xus_.mode()), port_.global_cycle());
  }
  return !stopped && error_.empty();
}

iss::HookResult ThreadMultiprocessor::execute_op(const iss::HookCall& call) {
  iss::HookResult result;
  Tp& tp = *hook_.tp;
  const uint32_t tp_index = tp.thread_id % setup_.tps_per_tm;
  switch (call.op) {
    case iss::Op::kStThreadId: result.dest[0] = tp.thread_id; return result;
    case iss::Op::kStTpId: result.dest[0] = tp_index; return result;
    case iss::Op::kStTmId: result.dest[0] = tm_id_; return result;
    case iss::Op::kStThreadCount: result.dest[0] = setup_.threads(); return result;
    case iss::Op::kStTpsPerTm: result.dest[0] = setup_.tps_per_tm; return result;
    case iss::Op::kStTmCount: result.dest[0] = setup_.tms; return result;
    case iss::Op::kStAtomicInc:
    case iss::Op::kStAtomicAdd:
    case iss::Op::kStGlobalRead:
    case iss::Op::kStGlobalWrite: {
      if (call.rs1 >= env_.globals->values.size()) {
        result.status = iss::HookStatus::kIllegal;
        result.message = "global register index out of range";
        return result;
      }
      uint32_t& g = env_.globals->values[call.rs1];
      result.dest[0] = g;
      if (call.op == iss::Op::kStAtomicInc) g += 1;
      if (call.op == iss::Op::kStAtomicAdd) g += call.rs2;
      if (call.op == iss::Op::kStGlobalWrite) g = call.rs2;
      ++env_.globals->operations;
      ++counters_.global_register_ops;
      hook_.op_class = sampling::TmSampler::kGlobal;
      if (sampler_.in_batch()) sampler_.note_batch_wait(hook_.op_class);
      hook_.timed = true;
      hook_.ready = hook_.request_cycle + setup_.global_register_latency_cycles;
      return result;
    }
    case iss::Op::kStStreamCapacity:
    case iss::Op::kStStreamPush:
    case iss::Op::kStStreamPop:
    case iss::Op::kStStreamPush64:
    case iss::Op::kStStreamPop64:
    case iss::Op::kStStreamAssign: return execute_stream(call);
    default: return tp.pipe.execute(call);  // pipeline configuration, inputs and fused tests
  }
}

iss::HookResult ThreadMultiprocessor::execute_stream(const iss::HookCall& call) {
  iss::HookResult result;
  Tp& tp = *hook_.tp;
  if (!setup_.streams) {
    result.status = iss::HookStatus::kIllegal;
    result.message = "stream memory operations need a design with streams (design.streams)";
    return result;
  }
  // A push or pop moves one entry: the instruction's width must be the stream memory's.
  const uint32_t ray_bytes = iss::stream_ray_bytes(call.op);
  if (ray_bytes != 0 && ray_bytes != env_.stream_ray_bytes) {
    result.status = iss::HookStatus::kIllegal;
    result.message = env_.stream_ray_bytes == 64
                         ? "a 48-byte stream push/pop, but the stream memory holds 64-byte rays "
                           "(design.path_state=compact runs the *_compact kernels)"
                         : "a 64-byte stream push/pop, but the stream memory holds 48-byte rays "
                           "(the *_compact kernels need design.path_state=compact)";
    return result;
  }
  const MemoryExtension& ext = port_.answer();  // each case reads the answer of its one access
  uint8_t scratch[64] = {};
  if (counting()) ++counters_.stream_requests;
  if (ray_bytes != 0) {
    ++counters_.stream_moves_all;
    if (counting()) ++counters_.stream_moves;
  }
  hook_.op_class = sampling::TmSampler::kOtherOp;
  switch (call.op) {
    case iss::Op::kStStreamCapacity:
      hook_.ready = transact(stream_port, AccessClass::kStreamCapacity, 0, scratch, 4, hook_.request_cycle, false,
                             transport::kNoTreelet, tp);
      result.dest[0] = ext.result;
      break;
    case iss::Op::kStStreamPush:
    case iss::Op::kStStreamPush64:
      std::memcpy(scratch, call.in, ray_bytes);
      hook_.ready = transact(stream_port, AccessClass::kStreamPush, 0, scratch, ray_bytes, hook_.request_cycle, false,
                             call.rs2, tp);
      result.dest[0] = ext.stream_status == StreamStatus::kOk ? 1u : 0u;
      if (ext.stream_status == StreamStatus::kFull) ++counters_.stream_push_full;
      hook_.op_class = result.dest[0] ? sampling::TmSampler::kPushStored : sampling::TmSampler::kPushFull;
      break;
    case iss::Op::kStStreamPop:
    case iss::Op::kStStreamPop64:
      hook_.ready = transact(stream_port, AccessClass::kStreamPop, 0, scratch, ray_bytes, hook_.request_cycle, false,
                             transport::kNoTreelet, tp);
      result.dest[0] = ext.stream_status == StreamStatus::kOk ? 1u : 0u;
      hook_.op_class = result.dest[0] ? sampling::TmSampler::kPopRay : sampling::TmSampler::kPopEmpty;
      if (result.dest[0]) {
        std::memcpy(call.out, scratch, ray_bytes);
        result.status = iss::HookStatus::kStore;
        sessions_.popped();
      }
      break;
    default:  // kStStreamAssign
      hook_.ready = transact(stream_port, AccessClass::kStreamAssign, 0, scratch, 4, hook_.request_cycle, false,
                             transport::kNoTreelet, tp);
      result.dest[0] = ext.result;
      sessions_.assigned(ext.result);
      hook_.op_class = ext.result == transport::kNoTreelet ? sampling::TmSampler::kAssignNone : sampling::TmSampler::kAssignFound;
      trace_.treelet(ext.result, port_.global_cycle());
      break;
  }
  if (sampler_.in_batch()) sampler_.note_batch_wait(hook_.op_class);
  hook_.timed = true;
  return result;
}

}  // namespace strata::tm

namespace strata::iss {
template class Hart<strata::tm::TpMemory>;
}
