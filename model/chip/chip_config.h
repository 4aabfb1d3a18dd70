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
#include "model/sampling/timing_config.h"
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


// The config's name of a placement: "compact", "on-chip" or "dram".
const char* path_state_name(PathStatePlacement p);

struct DesignConfig {
  std::string name = "strata-streams-pipelines";  // selects the design (model/chip/design.h)
  bool streams = true;    // ray stream memory + treelet scheduling (else: TRaX-style L2 only)
  bool pipelines = true;  // fused box/triangle pipelines (else: general-purpose XUs only)
  PathStatePlacement path_state = PathStatePlacement::kCompact;  // streaming designs only
};

using sampling::TimingConfig;  // model/sampling/timing_config.h
// The sampled-timing fields (timing.sample_*, functional_warming, fast_forward_batch_quanta) whose
// value differs from the built-in default: in LT or precise mode they do nothing, and the run
// warns that they were set.
std::vector<std::string> sampled_only_fields_changed(const TimingConfig& timing);


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
