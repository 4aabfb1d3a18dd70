// A thread multiprocessor: its TPs (functional harts with in-order issue timing), the XU
// crossbar with the fused pipelines, and sockets to its L1 data cache, L1 instruction cache
// and (through the interconnect) the ray stream memory.
//
// One SC_THREAD runs all the TPs of the TM: it always steps the TP whose next issue cycle is
// earliest, so TPs compete for the TM's XUs in time order. The TM runs ahead of global time
// by at most the quantum (loosely timed) or waits for global time at every cycle it issues in
// (precise). A TP that has halted leaves the schedule and costs nothing; one that is stalled
// is simply scheduled at the cycle it can issue again, so no cycle is ever ticked idly.
// The TMs wait for global time in turns (turn_order.h): TMs resuming at the same cycle run in
// a round-robin order of their ids, so the shared memories see their requests in an order
// that depends on the model alone.
//
// Sampled timing runs the same model in short detailed windows and, between them, runs each
// TP's instructions in batches, functionally, advancing its time by the cycles per
// instruction its TM showed in the last detailed window (docs/sampled-timing.md).
//
// Each instruction is first executed functionally (the hart; loads and stores go to the
// sparse backing store), then timed: its fetch (I-cache, on a change of cache line), its
// operands (scoreboard), its unit (XU crossbar) or its memory access (L1 socket, the TP's
// local stack memory, the stream memory, or the global registers). The fused box and triangle
// tests' values come from the C++ pipeline model, or, for a TM that tm.pipeline_impl=rtl
// selects, from a backend the environment's factory makes (the verilated RTL); their timing is
// the XU crossbar's either way.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include "model/tm/fused_backend_factory.h"
#include "model/tm/global_registers.h"
#include "model/sampling/tm_sampler.h"
#include "model/tm/tm_setup.h"
#include "model/tm/tm_trace.h"
#include "model/tm/tp_memory.h"
#include "model/tm/tp_schedule.h"
#include "tlm/turn_order.h"
#include "model/tm/treelet_sessions.h"
#include "model/iss/functional_strata_hook.h"
#include "model/iss/hart.h"
#include "model/memory/sparse_memory.h"
#include "model/memory/window_trace.h"
#include "model/stats/stat_group.h"
#include "model/tm/tp_timing.h"
#include "model/tm/xu_crossbar.h"
#include "tlm/clock.h"
#include "tlm/memory_port.h"
#include "tlm/payload_pool.h"

namespace strata::tm {

// What the chip hands every TM: shared state and the guest memory map.
struct TmEnvironment {
  const TmSetup* setup = nullptr;
  memory::SparseMemory* backing = nullptr;
  iss::CodeImage* code = nullptr;
  GlobalRegisters* globals = nullptr;
  uint32_t entry_pc = 0;
  uint32_t tohost = 0;       // 0: none
  uint32_t guest_low = 0;    // lowest valid data address (above the null page)
  uint64_t guest_high = 0;   // one past the highest
  uint32_t stacks_base = 0;  // thread t's stack: [stacks_base + t * stack, + stack)
  const transport::DataClassMap* data_classes = nullptr;  // what each data address holds (may be null)
  // On-chip path state: loads and stores to [path_begin, path_end) go to the stream memory.
  bool path_state_on_chip = false;
  uint32_t stream_ray_bytes = 48;  // one stream entry's ray: 48, or 64 with the compact path state
  uint64_t path_begin = 0, path_end = 0;
  // Sampled timing: where the detailed windows fall (null in the other modes).
  const sampling::SamplingSchedule* schedule = nullptr;
  // The cycle statistics are taken at (the frame's end): the XUs count each mode's cycles up to it.
  const transport::Cycle* report_cycle = nullptr;
  // tm.pipeline_impl=rtl: makes the backend of each TM that uses it (null otherwise).
  const FusedBackendFactory* pipeline_backend = nullptr;
  // Treelets [0, node_treelets) hold BVH nodes, the rest triangles (the scene header's count).
  uint32_t node_treelets = 0;
  // The order the TMs run in against global time (turn_order.h); TM i takes turns as id i.
  transport::TurnOrder* turns = nullptr;
};

struct TmCounters {
  uint64_t instructions = 0;
  uint64_t detailed_instructions = 0;  // timed one by one (all of them unless sampled)
  uint64_t measured_instructions = 0;  // sampled only: timed in the measured part (past the warm-up)
  uint64_t measured_data_ops = 0;      // ... of which loads, stores and pipeline loads (is_data_op)
  uint64_t icache_fetch_requests = 0;  // line changes that went to the I-cache
  uint64_t local_accesses = 0;         // stack accesses served by TP local memory
  uint64_t l1_requests = 0;
  uint64_t path_state_requests = 0;  // on-chip path state: loads and stores sent to the stream memory
  uint64_t stream_requests = 0, stream_push_full = 0;
  // Ray pushes and pops: every one (exact in every mode), and those of the measured parts.
  uint64_t stream_moves_all = 0, stream_moves = 0;
  uint64_t global_register_ops = 0;
  uint64_t forced_reconfigurations = 0;  // fused ops that found the TM in another mode
  uint64_t warm_requests = 0;  // sampled, functional warming: L1 lines replayed as tag updates
  uint64_t fast_forward_batches = 0;  // sampled: functional batches run (one TP each)
  transport::Cycle finished_cycle = 0;
};

// Loads, stores and pipeline-input loads: the instructions whose data go through the L1.
inline bool is_data_op(iss::InstrClass c) {
  return c == iss::InstrClass::kLoad || c == iss::InstrClass::kStore || c == iss::InstrClass::kStrataPipeLoad;
}

class ThreadMultiprocessor : public sc_core::sc_module, private iss::StrataHook {
 public:
  tlm_utils::simple_initiator_socket<ThreadMultiprocessor> data_port{"data_port"};
  tlm_utils::simple_initiator_socket<ThreadMultiprocessor> fetch_port{"fetch_port"};
  tlm_utils::simple_initiator_socket<ThreadMultiprocessor> stream_port{"stream_port"};

  SC_HAS_PROCESS(ThreadMultiprocessor);
  ThreadMultiprocessor(sc_core::sc_module_name name, const TmEnvironment& env, uint32_t tm_id);
  ~ThreadMultiprocessor() override;

  const TmCounters& counters() const { return counters_; }
  const tm::XuCrossbar& xus() const { return xus_; }
  // This TM's statistics groups: its TPs' instructions and stalls, and its XU crossbar.
  const stats::Group& instruction_stats() const { return stats_.instructions; }
  const stats::Group& xu_stats() const { return stats_.xu; }
  // Its treelet sessions: rays traced and L1 lines filled per treelet buffer it took.
  const stats::Group& session_stats() const { return sessions_.stats(); }
  tm::TpStats tp_stats() const;  // summed over the TM's TPs
  iss::Counters iss_counters() const;
  bool failed() const { return !error_.empty(); }
  const std::string& error() const { return error_; }
  bool finished() const { return finished_; }
  // The backend computing this TM's fused tests, or null for the C++ pipeline model.
  const iss::FusedPipelineBackend* pipeline_backend() const { return pipeline_backend_.get(); }

  // VCD: pipeline mode, fused ops and instructions per window, current treelet.
  using sc_core::sc_object::trace;  // ours adds a window; the base's stays visible
  void trace(sc_core::sc_trace_file* file, const memory::TraceWindow& window);

 private:
  struct Tp;
  void run();
  // The memory port's sync_to (tlm/memory_port.h): global time catches up with `t` when the
  // TM's lead calls for it, never past `others`, the earliest next cycle of the TM's other TPs
  // (a TP behind global time would have its requests moved to it by every calendar). After a
  // wait, the XU crossbar forgets what lies before every TP of the TM.
  void sync_to(transport::Cycle t, transport::Cycle others = transport::MemoryPort::kNoLimit, bool exact = false);
  // The cycle at which `tp`'s next instruction must reach the shared resources in time order
  // (precise: every memory-like op; LT with timing.sync_shared_ops: stream and global-register
  // ops), or 0 if it need not. Makes the instruction's fetch (kept in the Tp).
  transport::Cycle synchronised_issue(Tp& tp);
  bool step(Tp& tp);  // false: the TP is done (halted, or failed)
  // Sampled timing: runs `tp` functionally until about `until`; false when it is done.
  bool fast_forward(Tp& tp, transport::Cycle until);
  // Functional warming: the batch's logged loads and stores as tag updates (ff_.warm_log).
  void replay_warm_log(const Tp& tp);
  // Whether the current access goes into the statistics (sampled: measured parts only).
  bool counting() const { return sampler_.counting(); }
  transport::Cycle fetch(Tp& tp, uint32_t pc);
  transport::Cycle time_data_access(Tp& tp, transport::Cycle at);
  // One access of `tp` through the memory port; its answer is port_.answer(). A refused one
  // fails the TP and returns `at`.
  transport::Cycle transact(tlm_utils::simple_initiator_socket<ThreadMultiprocessor>& socket,
                            transport::AccessClass access, uint64_t addr, void* data, uint32_t bytes,
                            transport::Cycle at, bool timing_only, uint32_t treelet, Tp& tp);
  void fail(const Tp& tp, const std::string& what);
  void register_stats();  // tm_statistics.cpp
  void refresh_stats();

  iss::HookResult execute(const iss::HookCall& call) override;
  bool in_time_order();  // fast-forward, time order: false when the op must be deferred
  iss::HookResult execute_op(const iss::HookCall& call);
  iss::HookResult execute_stream(const iss::HookCall& call);

  TmEnvironment env_;
  const TmSetup& setup_;  // the chip as the TM sees it
  uint32_t tm_id_;
  // Time against global time, and the TM's own accesses (tlm/memory_port.h).
  transport::MemoryPort port_;
  tm::OpTimingTable op_table_;
  transport::Cycle burst_slack_;
  bool sync_all_memory_ = false;  // precise mode
  bool sync_shared_ = false;      // precise, or LT with timing.sync_shared_ops
  tm::XuCrossbar xus_;
  std::unique_ptr<iss::FusedPipelineBackend> pipeline_backend_;  // before tps_: they point at it
  std::vector<std::unique_ptr<Tp>> tps_;
  // run()'s TP schedule, a member rather than a local: an interrupted simulation never
  // returns from run() (its SC_THREAD stays suspended), so a local would leak at exit.
  TpSchedule schedule_{0};
  TmCounters counters_;
  std::string error_;
  bool finished_ = false;
  uint32_t live_tps_ = 0;              // TPs that have not halted
  uint32_t fetch_line_shift_ = 0;      // log2(L1I line bytes)

  sampling::TmSampler sampler_;  // sampled timing's state (enabled in that mode only)

  // Sampled timing's fast-forward (tm_fast_forward.cpp).
  struct FastForward {
    transport::PayloadPool pool;  // functional warming's tag updates
    WarmLog warm_log;             // the current batch's L1 lines (functional warming)
    bool warming = false;
    bool l1_timed_since_warming = true;  // a timed access changed the L1: warm_log.forget()
    // timing.fast_forward_time_order: a batch's stream and global-register ops wait for global
    // time to reach their date, and one dated past `others` (the earliest next cycle of the
    // TM's other TPs) is deferred: the batch stops before it, and the TP resumes there when it
    // is the TM's earliest.
    bool time_order = false;
    transport::Cycle others = 0;
  };
  FastForward ff_;

  // The instruction being executed, for the hook (execute()).
  struct Executing {
    Tp* tp = nullptr;
    transport::Cycle request_cycle = 0;  // when its memory-like op may reach its target
    transport::Cycle ready = 0;          // when the hook's op completed
    bool timed = false;                  // the hook timed the op itself
    unsigned op_class = 0;               // TmSampler::OpClass of the stream/global op just executed
  };
  Executing hook_;

  // Statistics (tm_statistics.cpp): sums over the TPs and the crossbar's counters, refreshed
  // before a snapshot, and the groups that publish them.
  struct Statistics {
    iss::Counters iss_totals;
    std::array<uint64_t, tm::kStallCauseCount> stall_totals{};
    tm::XuStats xu_totals;
    stats::Group instructions{"instructions", "What the TPs executed, and why they waited.", stats::Basis::kExact};
    stats::Group xu{"xu", "The shared execution units: use by mode and class, fused pipelines, reconfigurations.",
                    stats::Basis::kTimedInstructions};
    std::vector<std::unique_ptr<stats::Group>> groups;  // the sub-groups of both
  };
  Statistics stats_;
  TreeletSessions sessions_;

  TmTrace trace_;  // VCD signals
};

}  // namespace strata::tm
