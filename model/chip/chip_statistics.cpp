// The chip's statistics tree (docs/statistics.md is generated from it):
//
//   chip     the chip's size and clock
//   frame    cycles, time, frame rate
//   rays     rays by type, paths, node visits, triangle tests (from the kernels' counters)
//   sampling sampled timing only: how much was timed, and the extrapolation factors
//   instructions, xu      each TM's groups, summed (per TM with --stats-detail tm)
//   memory   l1d, l1i (per TM, summed), l2 (banks), stream, interconnect, dram (channels)
//   treelets the TMs' treelet sessions (per TM, summed), buffers and rays in flight
//   energy_nj            the paper's split, from the counts above
//   fidelity             the sentinels that say whether the timing can be trusted
#include <algorithm>

#include "model/chip/chip.h"
#include "model/sampling/sampling_factors.h"
#include "model/stats/stat_values.h"

namespace strata::chip {

using stats::Basis;
using stats::Scope;
using stats::Unit;

void Chip::register_stats() {
  auto own = [this](const char* name, const char* description, Basis basis = Basis::kInherit) -> stats::Group& {
    stat_groups_.push_back(std::make_unique<stats::Group>(name, description, basis));
    return *stat_groups_.back();
  };
  stats::Group& root = stats_;
  root.before_snapshot([this] {
    snapshot_.report_cycle = cycles();
    snapshot_.ray_totals = ray_counters();
    snapshot_.ray_total = 0;
    for (uint32_t t = 0; t < kernels::kRayTypes; ++t) snapshot_.ray_total += snapshot_.ray_totals.rays[t];
  });

  stats::Group& info = own("chip", "The simulated chip's size and clock.", Basis::kExact);
  info.level("tms", [this] { return uint64_t{config_.tms}; }, Unit::kCount, "Thread multiprocessors.");
  info.level("tps_per_tm", [this] { return uint64_t{config_.tps_per_tm}; }, Unit::kCount, "Thread processors per TM.");
  info.level("threads", [this] { return uint64_t{config_.threads()}; }, Unit::kCount, "TPs on the chip.");
  info.level("clock_ghz", [this] { return config_.clock_ghz; }, Unit::kGigahertz, "The chip clock.");
  root.child(&info);

  stats::Group& frame = own("frame", "The frame's simulated time.", Basis::kExact);
  frame.level("cycles", [this] { return snapshot_.report_cycle; }, Unit::kCycles,
              "Cycles until the last TP finished (a run stopped early: as far as global time got).");
  const double hz = config_.clock_ghz * 1e9;
  frame.derived("seconds", Unit::kSeconds, "cycles at the chip clock.",
                [hz](const Scope& s) { return s.self().number("cycles") / hz; });
  frame.derived("frames_per_second", Unit::kPerSecond, "1 / seconds; null when the frame did not finish.",
                [this](const Scope& s) {
                  const double sec = s.self().number("seconds");
                  return finished() && sec > 0 ? 1.0 / sec : std::nan("");
                });
  frame.level("pixels_done", [this] { return uint64_t{pixels_done()}; }, Unit::kCount,
              "Pixels whose every sample is finished (baseline: handed out).");
  root.child(&frame);

  stats::Group& rays = own("rays", "Rays the kernels traced, from their own counters (exact).", Basis::kExact);
  const char* type_names[kernels::kRayTypes] = {"primary", "bounce", "shadow"};
  for (uint32_t t = 0; t < kernels::kRayTypes; ++t) {
    stats::Group& g = own(type_names[t], t == kernels::kShadowRay ? "Shadow rays to the light." : "Closest-hit rays.");
    g.count("traced", &snapshot_.ray_totals.rays[t], Unit::kCount, "Rays of this type traced.");
    g.count(t == kernels::kShadowRay ? "occluded" : "hit", &snapshot_.ray_totals.hits[t], Unit::kCount,
            t == kernels::kShadowRay ? "Shadow rays that found an occluder." : "Rays that hit a triangle.");
    rays.child(&g);
  }
  rays.count("total", &snapshot_.ray_total, Unit::kCount, "Rays of every type.");
  rays.count("paths", &snapshot_.ray_totals.paths, Unit::kCount, "Paths (samples) finished.");
  rays.count("node_visits", &snapshot_.ray_totals.node_visits, Unit::kCount, "BVH node reads.");
  rays.count("triangle_tests", &snapshot_.ray_totals.triangle_tests, Unit::kCount, "Ray-triangle tests.");
  root.child(&rays);

  if (config_.timing.mode == transport::TimingMode::kSampled) {
    stats::Group& s = own("sampling",
                          "Sampled timing only: how much of the frame was timed in detail, and the factors the "
                          "estimated counts were extrapolated by.",
                          Basis::kExact);
    const auto sum = [this](uint64_t TmCounters::*field) {
      return [this, field] {
        uint64_t n = 0;
        for (const auto& t : tms_) n += t->counters().*field;
        return n;
      };
    };
    s.level("period_cycles", [this] { return uint64_t{config_.timing.sample_period_cycles}; }, Unit::kCycles,
            "The sampling period.");
    s.level("detail_cycles", [this] { return uint64_t{config_.timing.sample_detail_cycles}; }, Unit::kCycles,
            "The detailed window at the start of each period.");
    s.level("warmup_cycles", [this] { return uint64_t{config_.timing.sample_warmup_cycles}; }, Unit::kCycles,
            "The window's first cycles, timed but not measured.");
    s.count_probe("timed_instructions", sum(&TmCounters::detailed_instructions), Unit::kCount,
                  "Instructions timed one by one (the detailed windows).");
    s.count_probe("measured_instructions", sum(&TmCounters::measured_instructions), Unit::kCount,
                  "Of those, instructions in the measured parts (past the warm-up).");
    s.count_probe("measured_data_ops", sum(&TmCounters::measured_data_ops), Unit::kCount,
                  "Loads, stores and pipeline loads in the measured parts.");
    s.count_probe("measured_stream_ops", sum(&TmCounters::stream_requests), Unit::kCount,
                  "Stream-memory operations in the measured parts.");
    s.count_probe("measured_stream_moves", sum(&TmCounters::stream_moves), Unit::kCount,
                  "Ray pushes and pops in the measured parts.");
    s.count_probe("measured_cycles", [this] { return schedule_->measured_cycles_before(snapshot_.report_cycle); },
                  Unit::kCycles, "Cycles of the measured parts (the windows past their warm-up) in the frame.");
    s.level("target_error", [this] { return config_.timing.sample_target_error; }, Unit::kRatio,
            "The 95% relative half-width asked of the statistics timing.sample_target_stats names (0: the period is "
            "fixed).");
    s.level("windows", [this] { return uint64_t{sampler_ ? sampler_->batches().windows() : 0}; }, Unit::kCount,
            "Detailed windows the frame held before its last (partial) one.");
    s.level("period_changes", [this] { return uint64_t{schedule_ ? schedule_->changes() : 0}; }, Unit::kCount,
            "Times the error target changed the sampling period.");
    s.level("last_period_cycles", [this] { return schedule_ ? schedule_->sampled_period_at(snapshot_.report_cycle) : uint64_t{0}; },
            Unit::kCycles,
            "The period at the frame's end, or before its drain (the configured one unless an error target changed it).");
    s.level("head_cycles", [this] { return schedule_ ? std::min(schedule_->head_cycles(), snapshot_.report_cycle) : uint64_t{0}; },
            Unit::kCycles,
            "The frame's first cycles, timed and measured in full as a stratum of their own (timing.sample_head_periods; "
            "0: no head).");
    s.level("drain_cycles",
            [this] {
              const uint64_t from = schedule_ ? schedule_->drain_from() : 0;
              return from > 0 && snapshot_.report_cycle > from ? snapshot_.report_cycle - from : uint64_t{0};
            },
            Unit::kCycles,
            "The frame's last cycles, from the window after the pixels left fell to timing.sample_drain_share, timed in "
            "full as a stratum of their own (0: no drain stratum).");
    s.level("targets_out_of_reach", [this] { return uint64_t{sampler_ ? sampler_->out_of_reach().size() : 0}; },
            Unit::kCount,
            "Statistics of timing.sample_target_stats whose target the shortest period could not reach: the plan "
            "left them out (their intervals are what the other targets' windows give).");
    s.level("short_frame_rest_cycles", [this] { return sampler_ ? sampler_->short_frame_rest() : uint64_t{0}; },
            Unit::kCycles,
            "The rest of the frame, as projected shortly before its head's end, when that was fewer than 8 "
            "configured periods: the whole frame was then timed in full, as LT times it (0: it was sampled).");
    s.level("min_period_cycles", [this] { return sampler_ ? sampler_->min_period() : uint64_t{0}; },
            Unit::kCycles, "The shortest period an error target may choose (0: no sampler).");
    s.level("functional_warming", [this] { return uint64_t{config_.timing.functional_warming ? 1u : 0u}; },
            Unit::kCount, "1: fast-forward loads and stores kept the L1 data and L2 tags current.");
    s.level("warm_requests", sum(&TmCounters::warm_requests), Unit::kCount,
            "Warming requests the fast-forward sent: its loads and stores by L1 line, less runs of accesses to one "
            "line and loads of lines the L1 is known to hold (they would change nothing).");
    s.level("fast_forward_batch_cycles",
            [this] { return uint64_t{config_.timing.fast_forward_batch_quanta} * config_.timing.quantum_cycles; },
            Unit::kCycles, "How far past its TM's runner-up TP one fast-forward batch of a TP may run.");
    s.level("fast_forward_batches", sum(&TmCounters::fast_forward_batches), Unit::kCount,
            "Fast-forward batches run: each is one TP's instructions until the batch's cycles are spent or the TP "
            "halts.");
    s.derived("fast_forward_instructions", Unit::kCount, "Instructions run functionally (retired - timed).",
              [](const Scope& x) {
                return x.root().number("instructions.retired") - x.self().number("timed_instructions");
              },
              true);
    const auto factor = [](Basis b) {
      return [b](const Scope& x) { return sampling::extrapolation_factors(x.root())[b]; };
    };
    s.derived("extrapolation_factor", Unit::kRatio, "Instructions retired / timed: XU and stall counts.",
              factor(Basis::kTimedInstructions));
    s.derived("memory_extrapolation_factor", Unit::kRatio,
              "Data operations of the frame / measured: L1 data, L2, interconnect, DRAM.", factor(Basis::kDataOps));
    s.derived("fetch_extrapolation_factor", Unit::kRatio, "Instructions retired / measured: instruction fetch.",
              factor(Basis::kMeasuredInstructions));
    s.derived("stream_extrapolation_factor", Unit::kRatio,
              "Stream operations of the frame / measured: stream memory.", factor(Basis::kStreamOps));
    root.child(&s);
  }

  if (config_.pipeline_impl == PipelineImpl::kRtl) {
    stats::Group& rtl = own("rtl_pipelines",
                            "tm.pipeline_impl=rtl only: the fused tests the verilated RTL pipelines computed, and the "
                            "latency the RTL showed against the one the TM config charges (the chip's timing is the "
                            "config's). Exact in every timing mode: every fused test goes to the RTL.",
                            Basis::kExact);
    register_rtl_pipeline_stats(rtl);
    root.child(&rtl);
  }

  std::vector<const stats::Group*> instructions, xus, l1d, l1i;
  for (size_t t = 0; t < tms_.size(); ++t) {
    instructions.push_back(&tms_[t]->instruction_stats());
    xus.push_back(&tms_[t]->xu_stats());
    l1d.push_back(&l1d_[t]->stats());
    l1i.push_back(&l1i_[t]->stats());
  }
  root.instances("instructions", instructions, "tm", "TM");
  root.instances("xu", xus, "tm", "TM");
  stats::Group& memory = own("memory", "Every level of the memory system, with its traffic by data class.");
  memory.instances("l1d", l1d, "tm", "TM's L1 data cache");
  memory.instances("l1i", l1i, "tm", "TM's L1 instruction cache");
  memory.child(&l2_->stats());
  memory.child(&stream_->stats());
  memory.child(&interconnect_->stats());
  memory.child(&dram_->stats());
  root.child(&memory);

  stats::Group& treelets = own("treelets",
                               "The treelet mechanism (streaming designs; 0 on TRaX): each TM's treelet sessions, "
                               "with the rays they traced and the L1 data lines they filled, and where the rays were "
                               "over the frame.");
  register_treelet_stats(treelets);
  root.child(&treelets);

  // Energy per frame, split as the STRaTA paper does: from the counts above, after sampled
  // timing's extrapolation.
  stats::Group& energy = own("energy_nj", "Energy per frame by component (nJ).", Basis::kExact);
  const EnergyConfig e = config_.energy;
  const double fetch_nj = config_.l1i.access_energy_nj;
  energy.derived("l1_data", Unit::kNanojoules, "L1 data cache lookups and fills.",
                 [](const Scope& s) { return s.root().number("memory.l1d.energy_nj"); });
  energy.derived("l2_and_stream", Unit::kNanojoules, "L2 and stream-memory accesses.", [](const Scope& s) {
    return s.root().number("memory.l2.energy_nj") + s.root().number("memory.stream.energy_nj");
  });
  energy.derived("dram", Unit::kNanojoules, "DRAM bursts.",
                 [](const Scope& s) { return s.root().number("memory.dram.energy_nj"); });
  energy.derived("instruction_fetch", Unit::kNanojoules,
                 "Every retired instruction's fetch at the I-cache's energy per access.",
                 [fetch_nj](const Scope& s) { return s.root().number("instructions.retired") * fetch_nj; });
  energy.derived("register_file", Unit::kNanojoules, "Register-file reads and writes at energy.register_file_access_nj.",
                 [e](const Scope& s) {
                   const stats::Values& rf = s.root().group("instructions.register_file");
                   return (rf.number("int_reads") + rf.number("int_writes") + rf.number("fp_reads") +
                           rf.number("fp_writes")) *
                          e.register_file_access_nj;
                 });
  energy.derived("xu", Unit::kNanojoules, "XU operations and fused tests at their energy.* figures.",
                 [e](const Scope& s) {
                   const stats::Values& xu = s.root().group("xu");
                   const double per_class[tm::kXuClassCount] = {e.fp_mul_nj, e.fp_add_nj,    e.fp_cmp_nj,
                                                                e.fp_div_nj, e.fp_inv_sqrt_nj, e.int_mul_nj,
                                                                e.int_div_nj};
                   double nj = xu.number("box_tests") * e.box_test_nj + xu.number("triangle_tests") * e.triangle_test_nj;
                   for (unsigned c = 0; c < tm::kXuClassCount; ++c) {
                     double ops = 0;
                     for (unsigned m = 0; m < tm::kModeCount; ++m)
                       ops += xu.number(std::string("by_mode.") + tm::mode_name(tm::PipelineMode(m)) + "." +
                                        tm::xu_class_name(tm::XuClass(c)) + ".ops");
                     nj += ops * per_class[c];
                   }
                   return nj;
                 });
  energy.derived("total", Unit::kNanojoules, "The sum of the parts above.", [](const Scope& s) {
    const stats::Values& g = s.self();
    return g.number("l1_data") + g.number("l2_and_stream") + g.number("dram") + g.number("instruction_fetch") +
           g.number("register_file") + g.number("xu");
  });
  root.child(&energy);

  stats::Group& fidelity = own("fidelity",
                               "Sentinels of the timing's trustworthiness. Overflow bookings and late XU requests "
                               "must be 0; reordered lookups are corrections loosely timed makes by design.",
                               Basis::kExact);
  fidelity.derived("calendar_overflow_bookings", Unit::kCount,
                   "Reservation-calendar bookings beyond their horizon, over every module. Nonzero: the "
                   "contention of those requests was approximated; raise the calendar_horizon_cycles.",
                   [](const Scope& s) {
                     const stats::Values& r = s.root();
                     double n = r.number("xu.calendar_overflow_bookings");
                     for (const char* m : {"l1d", "l1i", "l2", "stream", "interconnect", "dram"})
                       n += r.number(std::string("memory.") + m + ".calendar_overflow_bookings");
                     return n;
                   },
                   true);
  fidelity.derived("xu_late_requests", Unit::kCount,
                   "XU requests older than the crossbar remembered. Nonzero: raise tm.xu_horizon_cycles.",
                   [](const Scope& s) { return s.root().number("xu.late_requests"); }, true);
  fidelity.derived("reordered_lookups", Unit::kCount,
                   "Cache lookups that arrived out of time order and were answered as time order would.",
                   [](const Scope& s) {
                     const stats::Values& r = s.root();
                     return r.number("memory.l1d.reordered") + r.number("memory.l1i.reordered") +
                            r.number("memory.l2.reordered");
                   },
                   true);
  fidelity.derived("reordered_share", Unit::kRatio, "reordered_lookups / all cache lookups.", [](const Scope& s) {
    const stats::Values& r = s.root();
    const double all =
        r.number("memory.l1d.accesses") + r.number("memory.l1i.accesses") + r.number("memory.l2.accesses");
    return all > 0 ? s.self().number("reordered_lookups") / all : 0.0;
  });
  root.child(&fidelity);
}

void Chip::register_rtl_pipeline_stats(stats::Group& g) {
  const auto sum = [this](uint64_t iss::FusedBackendCounts::*field) {
    return [this, field] {
      uint64_t n = 0;
      for (const auto& t : tms_)
        if (t->pipeline_backend() != nullptr) n += t->pipeline_backend()->counts().*field;
      return n;
    };
  };
  g.level("tms", [this] {
    uint64_t n = 0;
    for (const auto& t : tms_) n += t->pipeline_backend() != nullptr ? 1 : 0;
    return n;
  }, Unit::kCount, "TMs whose fused tests ran on the RTL (tm.pipeline_impl_tms).");
  using C = iss::FusedBackendCounts;
  g.count_probe("box_tests", sum(&C::box_tests), Unit::kCount, "Box tests the RTL box pipeline computed.");
  g.count_probe("triangle_tests", sum(&C::triangle_tests), Unit::kCount,
                "Triangle tests the RTL triangle pipeline computed (strata.tridiv stays in C++).");
  g.count_probe("box_latency_mismatches", sum(&C::box_latency_mismatches), Unit::kCount,
                "Box tests whose RTL latency differed from tm.pipelines.box.latency; 0 when the RTL and the config "
                "agree.");
  g.count_probe("triangle_latency_mismatches", sum(&C::triangle_latency_mismatches), Unit::kCount,
                "Triangle tests whose RTL latency differed from tm.pipelines.triangle.latency (the slow path's "
                "documented 2 extra cycles excepted); 0 when the RTL and the config agree.");
  g.count_probe("triangle_slow_path_tests", sum(&C::triangle_slow_path_tests), Unit::kCount,
                "Triangle tests on the RTL's exact-fallback path, 2 cycles longer than the config's latency, "
                "which the chip charged the ordinary latency (docs/rtl-cosim.md).");
  g.count_probe("box_rtl_cycles", sum(&C::box_cycles), Unit::kCycles,
                "Cycles of the RTL box pipeline's own clock run for the tests (not chip cycles).");
  g.count_probe("triangle_rtl_cycles", sum(&C::triangle_cycles), Unit::kCycles,
                "Cycles of the RTL triangle pipeline's own clock run for the tests (not chip cycles).");
}

}  // namespace strata::chip
