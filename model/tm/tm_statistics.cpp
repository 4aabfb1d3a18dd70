// A TM's statistics groups: the instructions its TPs retired (exact, from the ISS), their
// stall cycles and memory requests (from the timing), and its XU crossbar's use by mode and
// unit class. The chip sums them over the TMs (chip.cpp).
#include "model/tm/tm_thread_processor.h"
#include "model/stats/stat_values.h"

namespace strata::tm {

using stats::Basis;
using stats::Unit;

void ThreadMultiprocessor::refresh_stats() {
  stats_.iss_totals = iss_counters();
  stats_.stall_totals = {};
  for (const auto& tp : tps_) {
    const tm::TpStats& s = tp->timing.stats();
    for (size_t i = 0; i < stats_.stall_totals.size(); ++i) stats_.stall_totals[i] += s.stall_cycles[i];
  }
  const transport::Cycle now = env_.report_cycle ? *env_.report_cycle : counters_.finished_cycle;
  stats_.xu_totals = xus_.stats(now);
}

void ThreadMultiprocessor::register_stats() {
  auto sub = [this](const char* name, const char* description, Basis basis = Basis::kInherit) -> stats::Group& {
    stats_.groups.push_back(std::make_unique<stats::Group>(name, description, basis));
    return *stats_.groups.back();
  };
  const TmCounters& k = counters_;
  stats::Group& in = stats_.instructions;
  in.before_snapshot([this] { refresh_stats(); });
  in.count("retired", &stats_.iss_totals.retired, Unit::kCount, "Instructions retired by the TPs (exact in every mode).");
  in.count("fetched", &stats_.iss_totals.retired, Unit::kCount,
           "Instructions fetched: one per retired instruction (in order, no prediction, no refetch).");
  in.count("icache_line_requests", &k.icache_fetch_requests, Unit::kCount,
           "Fetches that moved to another cache line and asked the L1 instruction cache.",
           Basis::kMeasuredInstructions);
  in.count("tp_local_memory_accesses", &k.local_accesses, Unit::kCount,
           "Stack accesses served by the TP's local memory (not cached, no contention).", Basis::kDataOps);
  in.count("l1_requests", &k.l1_requests, Unit::kCount,
           "Requests to the L1 data cache (one per cache line a load, store or pipeline load touches).",
           Basis::kDataOps);
  in.count("stream_requests", &k.stream_requests, Unit::kCount, "Stream-memory operations the TPs issued.",
           Basis::kStreamOps);
  in.count("stream_moves", &k.stream_moves_all, Unit::kCount,
           "Ray pushes and pops the TPs issued (exact in every mode: sampled timing's basis for them).",
           Basis::kExact);
  in.count("path_state_requests", &k.path_state_requests, Unit::kCount,
           "Loads and stores of on-chip path state, sent to the stream memory instead of the L1.", Basis::kDataOps);
  in.count("stream_push_full", &k.stream_push_full, Unit::kCount,
           "Pushes the stream memory refused as full (the TP retries; exact).", Basis::kExact);
  in.count("global_register_ops", &k.global_register_ops, Unit::kCount,
           "Global-register reads, writes and atomics (exact).", Basis::kExact);
  in.count("forced_reconfigurations", &k.forced_reconfigurations, Unit::kCount,
           "Fused operations that found the TM's pipelines in another mode and switched them back.",
           Basis::kTimedInstructions);

  stats::Group& mix = sub("mix", "Retired instructions by class (exact).", Basis::kExact);
  for (unsigned c = 0; c < iss::kClassCount; ++c) {
    const auto cls = static_cast<iss::InstrClass>(c);
    if (cls == iss::InstrClass::kIllegal) continue;  // never retires
    mix.count(iss::class_name(cls), &stats_.iss_totals.by_class[c], Unit::kCount, "Retired instructions of this class.");
  }
  in.child(&mix);
  stats::Group& rf = sub("register_file", "Register-file accesses of the retired instructions, x0 excluded (exact).",
                         Basis::kExact);
  rf.count("int_reads", &stats_.iss_totals.int_reads, Unit::kCount, "Integer register reads.");
  rf.count("int_writes", &stats_.iss_totals.int_writes, Unit::kCount, "Integer register writes.");
  rf.count("fp_reads", &stats_.iss_totals.fp_reads, Unit::kCount, "FP register reads.");
  rf.count("fp_writes", &stats_.iss_totals.fp_writes, Unit::kCount, "FP register writes.");
  in.child(&rf);
  stats::Group& stalls =
      sub("stall_cycles", "TP-cycles an instruction waited to issue, by cause (docs/tm-timing.md).",
          Basis::kTimedInstructions);
  const char* why[tm::kStallCauseCount] = {
      "Waiting for the instruction's fetch (I-cache).",
      "Waiting for a source operand from an XU or the ALU.",
      "Waiting for a memory-like operation's result, or for the memory system to accept.",
      "Waiting for a busy XU or fused pipeline, or a reconfiguration."};
  for (unsigned s = 0; s < tm::kStallCauseCount; ++s)
    stalls.count(tm::stall_cause_name(tm::StallCause(s)), &stats_.stall_totals[s], Unit::kCycles, why[s]);
  in.child(&stalls);

  const tm::XuStats& x = stats_.xu_totals;
  stats::Group& xu = stats_.xu;
  xu.before_snapshot([this] { refresh_stats(); });
  xu.count("box_tests", &x.box_tests, Unit::kCount, "Fused ray-box tests.");
  xu.count("triangle_tests", &x.triangle_tests, Unit::kCount, "Fused ray-triangle (Plücker) tests.");
  xu.count("triangle_divides", &x.triangle_divides, Unit::kCount, "strata.tridiv operations (also fp_div ops).");
  xu.count("fused_multiply_adds", &x.fused_multiply_adds, Unit::kCount,
           "fmadd-family operations (also one fp_mul and one fp_add op each).");
  xu.count("box_busy_cycles", &x.box_busy_cycles, Unit::kCycles, "Lane-cycles of the box pipeline's issue slots.");
  xu.count("triangle_busy_cycles", &x.triangle_busy_cycles, Unit::kCycles,
           "Lane-cycles of the triangle pipeline's issue slots.");
  xu.count("reconfigurations", &x.reconfigurations, Unit::kCount, "Pipeline mode changes.");
  xu.count("reconfiguring_cycles", &x.reconfiguring_cycles, Unit::kCycles, "Switching time after the drains.");
  xu.count("late_requests", &x.late_requests, Unit::kCount,
           "Fidelity: requests for a cycle the crossbar's calendars had forgotten, served at the oldest "
           "remembered cycle. Nonzero means tm.xu_horizon_cycles is too small; must be 0.",
           Basis::kExact);
  xu.level("calendar_overflow_bookings", [this] { return xus_.overflow_bookings(); }, Unit::kCount,
           "Fidelity: bookings beyond the calendars' horizon; must be 0.");
  stats::Group& modes = sub("mode_cycles", "Cycles each pipeline mode was usable (up to the end of the frame).");
  for (unsigned m = 0; m < tm::kModeCount; ++m)
    modes.level(tm::mode_name(tm::PipelineMode(m)), &x.mode_cycles[m], Unit::kCycles,
                "Cycles the TM's reconfigurable units were in this mode.");
  xu.child(&modes);
  const uint32_t units[tm::kXuClassCount] = {setup_.tm.xu.fp_mul.count,      setup_.tm.xu.fp_add.count,
                                             setup_.tm.xu.fp_cmp.count,      setup_.tm.xu.fp_div.count,
                                             setup_.tm.xu.fp_inv_sqrt.count, setup_.tm.xu.int_mul.count,
                                             setup_.tm.xu.int_div.count};
  stats::Group& by_mode = sub("by_mode", "Use of each unit class, by the mode in force when the operation started.");
  for (unsigned m = 0; m < tm::kModeCount; ++m) {
    const char* mode = tm::mode_name(tm::PipelineMode(m));
    stats::Group& in_mode = sub(mode, "Operations started in this mode.");
    for (unsigned c = 0; c < tm::kXuClassCount; ++c) {
      stats::Group& use = sub(tm::xu_class_name(tm::XuClass(c)), "One unit class.");
      use.count("ops", &x.by_mode[m][c].ops, Unit::kCount, "Operations.");
      use.count("busy_unit_cycles", &x.by_mode[m][c].busy_unit_cycles, Unit::kCycles,
                "Unit-cycles the operations held an issue slot (1 per op if pipelined, else the latency).");
      const double n = units[c];
      const std::string mode_path = std::string("mode_cycles.") + mode;
      use.derived("utilisation", Unit::kRatio, "busy_unit_cycles / (units of the class x cycles of the mode).",
                  [n, mode_path](const stats::Scope& s) {
                    const double cycles = s.up(3).number(mode_path);
                    const double busy = s.self().number("busy_unit_cycles");
                    return n * cycles > 0 ? busy / (n * cycles) : 0.0;
                  });
      in_mode.child(&use);
    }
    by_mode.child(&in_mode);
  }
  xu.child(&by_mode);
}

}  // namespace strata::tm
