// Everything that describes one simulated chip: the design (which STRaTA mechanisms are on),
// its size, every module's parameters, the energy table, and the timing mode. One typed
// struct per module (model/memory/config.h, model/tm/tm_config.h); this file composes them,
// binds every field to a JSON path (sim/configs/*.json, `--set path=value`), and checks the
// values against each other.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "model/chip/config_binder.h"
#include "model/memory/config.h"
#include "model/stats/interval_method.h"
#include "model/tm/tm_config.h"
#include "tlm/clock.h"
#include "tlm/timing_mode.h"

namespace strata::chip {

// Where the streaming kernels keep what a path needs between its rays (throughput, radiance,
// its sample, the pending bounce; docs/path-state.md).
enum class PathStatePlacement : uint8_t {
  // In the ray itself: a 64-byte stream entry carries its path's state, with throughput and
  // radiance packed (firmware/kernels/streams_compact_paths.h). One ray per path in flight, so
  // the stream memory's whole capacity is paths. The paper's budget (48 B per ray) plus 16 B.
  kCompact,
  // A 96-byte record per path, in a region carved from the stream memory's SRAM beside the rays (ARCHITECTURE.md: ray
  // state never leaves the chip). Its loads and stores go to the stream memory through the
  // interconnect, take its ports and cost its energy per access; the ray capacity shrinks by
  // the records' bytes. Never in the L1, L2 or DRAM.
  kOnChip,
  // In a table in guest memory like any data: through the L1 data cache, the L2 and DRAM.
  kDram,
};

// What computes the fused box and triangle tests' results (the timing always comes from the
// TM config, through the XU crossbar): the C++ pipeline model (firmware/common/intersect.h),
// or the verilated RTL pipelines (rtl/pipelines/, docs/rtl-cosim.md), which the program running
// the chip must supply (FrameInputs::pipeline_backend).
enum class PipelineImpl : uint8_t { kModel, kRtl };

// timing.sample_target_stats's entries, trimmed; an empty or a repeated entry throws
// ConfigError naming the field (the window sampler checks the names against the tree).
std::vector<std::string> sample_target_list(const std::string& list);

// The config's name of a placement: "compact", "on-chip" or "dram".
const char* path_state_name(PathStatePlacement p);

struct DesignConfig {
  std::string name = "strata-streams-pipelines";  // selects the design (model/chip/design.h)
  bool streams = true;    // ray stream memory + treelet scheduling (else: TRaX-style L2 only)
  bool pipelines = true;  // fused box/triangle pipelines (else: general-purpose XUs only)
  PathStatePlacement path_state = PathStatePlacement::kCompact;  // streaming designs only
};

struct TimingConfig;
// The sampled-timing fields (timing.sample_*, functional_warming, fast_forward_batch_quanta) whose
// value differs from the built-in default: in LT or precise mode they do nothing, and the run
// warns that they were set.
std::vector<std::string> sampled_only_fields_changed(const TimingConfig& timing);

struct TimingConfig {
  transport::TimingMode mode = transport::TimingMode::kLooselyTimed;
  uint32_t quantum_cycles = 1000;  // LT: how far a TM may run ahead of global time
  // LT: how far one TP may run ahead of the other TPs of its TM before the TM switches to the
  // earliest one. Larger bursts simulate faster; the XU and memory calendars still see every
  // request at its own cycle.
  uint32_t tp_slack_cycles = 32;
  // LT: a stream-memory or global-register operation waits until global time reaches its
  // cycle, so the ray buffers, the treelet assignments and the global registers change in
  // time order, as in precise mode. Off, they change in arrival order: a TM a quantum ahead
  // drains the fullest buffer before the others ask, so TMs spread over treelets instead of
  // sharing the fullest one, and LT shows fewer L1 misses than precise
  // (docs/memory-system.md, "Where LT differs").
  bool sync_shared_ops = true;
  // Sampled: every sample_period_cycles, sample_detail_cycles run loosely timed; the rest of
  // the period fast-forwards functionally at each TM's measured cycles per instruction. The
  // first sample_warmup_cycles of a detailed window refill the scoreboards and calendars
  // and are not measured. docs/sampled-timing.md.
  uint32_t sample_period_cycles = 100000;
  uint32_t sample_detail_cycles = 20000;
  uint32_t sample_warmup_cycles = 8000;
  // Sampled: the frame's two ends, where its rates change fastest, are strata of their own,
  // timed in full and estimated apart from the sampled middle (window_sampler.h,
  // docs/sampled-timing.md "Head and drain strata"). The head: the first sample_head_periods
  // configured periods (0: none), cold caches and the first camera rays, whose windows skewed
  // STRaTA's DRAM estimate when they were sampled like the middle. The drain: from the first window after every
  // pixel has been handed out and the pixels left to finish have fallen to sample_drain_share
  // of the frame's (0: none), where the rays in flight run out.
  uint32_t sample_head_periods = 4;
  double sample_drain_share = 0.25;
  // Sampled: during fast-forward, replay every load and store as a tag update of the L1 data
  // cache and the L2 (no time, no counts), so a detailed window starts from warm caches.
  bool functional_warming = true;
  // Sampled: how far past the TM's runner-up TP one fast-forward batch of a TP may run, in
  // quanta (it never runs into a detailed window). A TP advances by about this much per batch,
  // so longer batches pay the per-batch costs (switching TPs, reloading the TP's state into
  // the host's caches) less often, but reorder the stream operations over a longer stretch.
  // 16 is as accurate against LT as shorter batches, and faster (docs/sampled-timing.md,
  // "Fast-forward batch length", has the measurement).
  uint32_t fast_forward_batch_quanta = 16;
  // Sampled: a fast-forwarded TP's stream and global-register operations wait, as in LT with
  // sync_shared_ops, until global time reaches the cycle the measured rates date them at, so
  // the ray buffers and treelet assignments change in time order through the whole frame.
  // Off, they change in arrival order (a TM up to the batch length ahead): faster, but the
  // buffers then hold more rays per treelet than LT's, the detailed windows inherit them, and
  // STRaTA's L1 misses, L2 accesses and DRAM bytes come out low (docs/sampled-timing.md,
  // "The fast-forward's ray schedule").
  bool fast_forward_time_order = true;
  // Sampled: charge a fast-forwarded stream or global-register op the mean latency measured for
  // its kind of outcome (assign found/none, pop ray/empty, push stored/full, global), not the
  // mean over all of them (tm_sampler.h, OpClass).
  bool fast_forward_op_classes = true;
  // Sampled: 0, or the relative half-width (e.g. 0.02) the 95% intervals of the statistics
  // sample_target_stats names should reach; the sampler then chooses the period itself
  // (window_sampler.h).
  double sample_target_error = 0.0;
  // Comma-separated statistics the target holds for: counts or formulas over counts. By default
  // the figures a design comparison reads: frame time, DRAM bytes and L2 accesses (DRAM varies
  // far more between windows than cycles do, so a target on cycles alone leaves it wide).
  std::string sample_target_stats = "frame.cycles,memory.dram.bytes,memory.l2.accesses";
  // Sampled: how the batches' replicates become an interval (model/stats/interval_method.h).
  // "successive" (differences of neighbouring batches) follows the frame's trends, as windows
  // spread evenly over it do; "jackknife" treats the batches as exchangeable and counts a trend
  // as variance, so STRaTA's DRAM intervals stay wide whatever the windows
  // (docs/sampled-timing.md, "Trends and the interval").
  stats::IntervalMethod sample_interval = stats::IntervalMethod::kSuccessiveDifferences;
};

// Per-access energies not owned by a memory module (nJ). The STRaTA table gives the register
// file (128 B, CACTI 6.5, 65 nm); the XU figures are 65 nm single-precision FPU estimates
// (Galal and Horowitz, "Energy-Efficient Floating-Point Unit Design", IEEE TC 2011: about
// 8-10 pJ per FMA-class op at 65 nm), applied per op, and the same for a fused pipeline
// stage-op.
struct EnergyConfig {
  double register_file_access_nj = 0.008;
  double fp_add_nj = 0.009;
  double fp_mul_nj = 0.009;
  double fp_cmp_nj = 0.002;
  double fp_div_nj = 0.05;      // iterative: many add/shift steps
  double fp_inv_sqrt_nj = 0.05;
  double int_mul_nj = 0.005;
  double int_div_nj = 0.03;
  double box_test_nj = 0.108;       // 6 mul + 6 add of the box pipeline
  double triangle_test_nj = 0.20;   // the multiplies and adds of one Plücker test
  void validate() const;
};

struct ChipConfig {
  DesignConfig design;
  double clock_ghz = 1.0;
  // The slowest clock the model supports. SystemC time is a 64-bit count of picoseconds (the
  // default resolution), and a cycle lasts 1000 / clock_ghz of them, so time can hold
  // 2^64 * clock_ghz / 1000 cycles. At 0.001 GHz that is 1.8e13 cycles (5 hours of chip time at
  // 1 GHz, thousands of times any frame we run); at 1e-12 GHz it was 18,446, and the frame's
  // time wrapped (59,650 calendar overflows, issue 39). The fastest, 100 GHz, is 10 ps a cycle.
  static constexpr double kMinClockGhz = 0.001;
  static constexpr double kMaxClockGhz = 100.0;
  // The chip's cycle as SystemC time: the one conversion the TMs, every memory module, the
  // window sampler and the progress monitor share, so a cycle is the same cycle everywhere and
  // the frame's cycle counts do not depend on clock_ghz (only its seconds do).
  transport::Clock clock() const { return transport::Clock(sc_core::sc_time(1.0 / clock_ghz, sc_core::SC_NS)); }
  uint32_t tms = 128;
  uint32_t tps_per_tm = 32;
  uint32_t tp_stack_bytes = 2048;   // per-TP local memory for the stack (not cached)
  uint32_t global_register_latency_cycles = 4;
  TimingConfig timing;
  tm::TmConfig tm;
  PipelineImpl pipeline_impl = PipelineImpl::kModel;  // tm.pipeline_impl
  // tm.pipeline_impl_tms: the TMs that use pipeline_impl, "all" or a comma-separated list of
  // TM indices ("0", "0,3"); the others use the C++ model.
  std::string pipeline_impl_tms = "all";
  memory::L1DataCacheConfig l1d;
  memory::L1InstructionCacheConfig l1i;
  memory::L2Config l2;
  memory::StreamMemoryConfig stream;
  memory::DramConfig dram;
  memory::InterconnectConfig interconnect;
  EnergyConfig energy;

  // Derives the fields that must agree (TP counts in the TM and stream configs, the
  // interconnect's L2 banks and ports), then checks everything; throws ConfigError naming the
  // field. stream.treelets (one head pointer per treelet) is set from the scene by the caller.
  void finalize();
  uint32_t threads() const { return tms * tps_per_tm; }
  // Whether TM `tm` runs its fused tests on the RTL pipelines (tm.pipeline_impl and _tms).
  bool rtl_pipelines(uint32_t tm) const;
  void bind(ConfigBinder& b);
};

// Defaults, then the file, then each override in order; then finalize(). Errors name the file
// (or the override) and the field.
ChipConfig load_chip_config(const std::filesystem::path& file, const std::vector<std::string>& overrides);
nlohmann::json to_json(ChipConfig config);

}  // namespace strata::chip
