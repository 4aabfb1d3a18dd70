#include "model/chip/chip_config.h"

#include <cstdio>

#include "firmware/abi/frame_abi.h"
#include "json_input/strict_json.h"
#include "model/chip/design.h"

#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "model/memory/stream_sram.h"

namespace strata::chip {
namespace {

void bind_unit(ConfigBinder& b, const std::string& p, tm::XuUnitConfig& u) {
  b.bind(p + ".count", &u.count);
  b.bind(p + ".latency", &u.latency);
  b.bind(p + ".pipelined", &u.pipelined);
}

void bind_pipeline(ConfigBinder& b, const std::string& p, tm::FusedPipelineConfig& f) {
  b.bind(p + ".multipliers", &f.multipliers);
  b.bind(p + ".adders", &f.adders);
  b.bind(p + ".initiation_interval", &f.initiation_interval);
  b.bind(p + ".latency", &f.latency);
  b.bind(p + ".issue_width", &f.issue_width);
}

void bind_dram_timing(ConfigBinder& b, const std::string& p, memory::DramTimingConfig& t) {
  b.bind(p + ".ranks", &t.ranks);
  b.bind(p + ".bank_groups", &t.bank_groups);
  b.bind(p + ".banks_per_group", &t.banks_per_group);
  b.bind(p + ".row_bytes", &t.row_bytes);
  b.bind(p + ".column_bytes", &t.column_bytes);
  b.bind(p + ".hash_banks", &t.hash_banks);
  b.bind(p + ".pack_activates", &t.pack_activates);
  b.bind_enum(p + ".row_policy", &t.row_policy, {"open", "closed"});
  const std::pair<const char*, double*> times[] = {
      {"t_rcd_ns", &t.t_rcd_ns},     {"t_rp_ns", &t.t_rp_ns},       {"t_cl_ns", &t.t_cl_ns},
      {"t_cwl_ns", &t.t_cwl_ns},     {"t_ras_ns", &t.t_ras_ns},     {"t_rc_ns", &t.t_rc_ns},
      {"t_rrd_s_ns", &t.t_rrd_s_ns}, {"t_rrd_l_ns", &t.t_rrd_l_ns}, {"t_faw_ns", &t.t_faw_ns},
      {"t_ccd_s_ns", &t.t_ccd_s_ns}, {"t_ccd_l_ns", &t.t_ccd_l_ns}, {"t_wr_ns", &t.t_wr_ns},
      {"t_wtr_ns", &t.t_wtr_ns},     {"t_rtp_ns", &t.t_rtp_ns},     {"t_refi_ns", &t.t_refi_ns},
      {"t_rfc_ns", &t.t_rfc_ns},     {"controller_ns", &t.controller_ns}};
  for (const auto& [name, field] : times) b.bind(p + "." + name, field);
}

template <class F>
void checked(const char* section, F&& validate) {
  try {
    validate();
  } catch (const std::invalid_argument& e) {
    // The module's validate() names its fields from its own name ("dram.channels: ..."); as
    // the config spells them, that is "memory.dram.channels: ...".
    const std::string s = section, what = e.what();
    const size_t dot = s.rfind('.');
    const std::string parent = dot == std::string::npos ? "" : s.substr(0, dot + 1);  // "memory."
    const std::string own = s.substr(parent.size()) + ".";                              // "dram."
    if (what.compare(0, own.size(), own) == 0) throw ConfigError(parent + what);
    throw ConfigError(s + ": " + what);
  }
}

void require(bool ok, const std::string& message) {
  if (!ok) throw ConfigError(message);
}

// A real number as it was given (%g): std::to_string prints 1e-12 as "0.000000", which reads as
// if an allowed 0 had been refused (issue 39, F12).
std::string real(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// tm.pipeline_impl_tms: "all" (every TM), or TM indices below `tms`, comma-separated.
std::vector<bool> parse_tm_list(const std::string& text, uint32_t tms) {
  const std::string field = "tm.pipeline_impl_tms";
  if (text == "all") return std::vector<bool>(tms, true);
  std::vector<bool> chosen(tms, false);
  size_t from = 0;
  while (true) {
    const size_t comma = text.find(',', from);
    const std::string item = text.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
    const bool digits = !item.empty() && item.size() <= 9 && item.find_first_not_of("0123456789") == std::string::npos;
    require(digits, field + ": expected \"all\" or comma-separated TM indices (e.g. \"0\" or \"0,3\"), got \"" +
                        text + "\"");
    const uint32_t tm = static_cast<uint32_t>(std::stoul(item));
    require(tm < tms, field + ": TM " + item + " does not exist (tms is " + std::to_string(tms) + ")");
    chosen[tm] = true;
    if (comma == std::string::npos) break;
    from = comma + 1;
  }
  return chosen;
}

}  // namespace

void EnergyConfig::validate() const {
  const std::pair<double, const char*> fields[] = {
      {register_file_access_nj, "register_file_access_nj"}, {fp_add_nj, "fp_add_nj"}, {fp_mul_nj, "fp_mul_nj"},
      {fp_cmp_nj, "fp_cmp_nj"}, {fp_div_nj, "fp_div_nj"}, {fp_inv_sqrt_nj, "fp_inv_sqrt_nj"},
      {int_mul_nj, "int_mul_nj"}, {int_div_nj, "int_div_nj"}, {box_test_nj, "box_test_nj"},
      {triangle_test_nj, "triangle_test_nj"}};
  for (const auto& [v, field] : fields)
    // An upper bound too: 1e308 nJ per operation overflows the frame's sums to infinity.
    if (!(v >= 0.0 && v <= 1e6))
      throw std::invalid_argument(std::string(field) + ": energies must be 0..1e6 nJ per operation, got " +
                                  real(v));
}

const char* path_state_name(PathStatePlacement p) {
  switch (p) {
    case PathStatePlacement::kCompact: return "compact";
    case PathStatePlacement::kOnChip: return "on-chip";
    case PathStatePlacement::kDram: return "dram";
  }
  return "?";
}


std::vector<std::string> sampled_only_fields_changed(const TimingConfig& t) {
  const TimingConfig d;
  std::vector<std::string> out;
  const auto check = [&out](bool changed, const char* name) {
    if (changed) out.push_back(name);
  };
  check(t.sample_period_cycles != d.sample_period_cycles, "timing.sample_period_cycles");
  check(t.sample_detail_cycles != d.sample_detail_cycles, "timing.sample_detail_cycles");
  check(t.sample_warmup_cycles != d.sample_warmup_cycles, "timing.sample_warmup_cycles");
  check(t.sample_head_periods != d.sample_head_periods, "timing.sample_head_periods");
  check(t.sample_drain_share != d.sample_drain_share, "timing.sample_drain_share");
  check(t.functional_warming != d.functional_warming, "timing.functional_warming");
  check(t.fast_forward_batch_quanta != d.fast_forward_batch_quanta, "timing.fast_forward_batch_quanta");
  check(t.fast_forward_time_order != d.fast_forward_time_order, "timing.fast_forward_time_order");
  check(t.fast_forward_op_classes != d.fast_forward_op_classes, "timing.fast_forward_op_classes");
  check(t.sample_target_error != d.sample_target_error, "timing.sample_target_error");
  check(t.sample_target_stats != d.sample_target_stats, "timing.sample_target_stats");
  check(t.sample_interval != d.sample_interval, "timing.sample_interval");
  check(t.sample_clock_bound != d.sample_clock_bound, "timing.sample_clock_bound");
  return out;
}

void ChipConfig::bind(ConfigBinder& b) {
  // The name selects the design (model/chip/design.h) and sets its mechanism flags; a flag set
  // after it that contradicts the design is refused by finalize().
  std::vector<std::string> names;
  for (const Design& d : designs()) names.push_back(d.name);
  b.bind_choice("design.name", &design.name, names, [this] { design = design_config(design.name, design.path_state); });
  b.bind("design.streams", &design.streams);
  b.bind("design.pipelines", &design.pipelines);
  b.bind_enum("design.path_state", &design.path_state, {"compact", "on-chip", "dram"});
  b.bind("clock_ghz", &clock_ghz);
  b.bind("tms", &tms);
  b.bind("tps_per_tm", &tps_per_tm);
  b.bind("tp_stack_bytes", &tp_stack_bytes);
  b.bind("global_register_latency_cycles", &global_register_latency_cycles);
  b.bind_enum("timing.mode", &timing.mode, {"lt", "precise", "sampled"});
  b.bind("timing.quantum_cycles", &timing.quantum_cycles);
  b.bind("timing.tp_slack_cycles", &timing.tp_slack_cycles);
  b.bind("timing.sync_shared_ops", &timing.sync_shared_ops);
  b.bind("timing.sample_period_cycles", &timing.sample_period_cycles);
  b.bind("timing.sample_detail_cycles", &timing.sample_detail_cycles);
  b.bind("timing.sample_warmup_cycles", &timing.sample_warmup_cycles);
  b.bind("timing.sample_head_periods", &timing.sample_head_periods);
  b.bind("timing.sample_drain_share", &timing.sample_drain_share);
  b.bind("timing.functional_warming", &timing.functional_warming);
  b.bind("timing.fast_forward_batch_quanta", &timing.fast_forward_batch_quanta);
  b.bind("timing.fast_forward_time_order", &timing.fast_forward_time_order);
  b.bind("timing.fast_forward_op_classes", &timing.fast_forward_op_classes);
  b.bind("timing.sample_target_error", &timing.sample_target_error);
  b.bind("timing.sample_target_stats", &timing.sample_target_stats);
  // The names in IntervalMethod's order.
  b.bind_enum("timing.sample_interval", &timing.sample_interval, {"jackknife", "successive"});
  b.bind("timing.sample_clock_bound", &timing.sample_clock_bound);

  auto& tp = tm.tp;
  b.bind("tm.tp.int_alu_latency", &tp.int_alu_latency);
  b.bind("tm.tp.branch_latency", &tp.branch_latency);
  b.bind("tm.tp.system_latency", &tp.system_latency);
  b.bind("tm.tp.fp_move_latency", &tp.fp_move_latency);
  b.bind("tm.tp.id_latency", &tp.id_latency);
  b.bind("tm.tp.pipe_input_latency", &tp.pipe_input_latency);
  b.bind("tm.tp.control_latency", &tp.control_latency);
  bind_unit(b, "tm.xu.fp_mul", tm.xu.fp_mul);
  bind_unit(b, "tm.xu.fp_add", tm.xu.fp_add);
  bind_unit(b, "tm.xu.fp_cmp", tm.xu.fp_cmp);
  bind_unit(b, "tm.xu.fp_div", tm.xu.fp_div);
  bind_unit(b, "tm.xu.fp_inv_sqrt", tm.xu.fp_inv_sqrt);
  bind_unit(b, "tm.xu.int_mul", tm.xu.int_mul);
  bind_unit(b, "tm.xu.int_div", tm.xu.int_div);
  bind_pipeline(b, "tm.pipelines.box", tm.pipelines.box);
  bind_pipeline(b, "tm.pipelines.triangle", tm.pipelines.triangle);
  b.bind("tm.pipelines.triangle_divide_latency", &tm.pipelines.triangle_divide_latency);
  b.bind("tm.pipelines.reconfigure_cycles", &tm.pipelines.reconfigure_cycles);
  b.bind_enum("tm.pipeline_impl", &pipeline_impl, {"model", "rtl"});
  b.bind_text_or_index("tm.pipeline_impl_tms", &pipeline_impl_tms);
  b.bind("tm.xu_horizon_cycles", &tm.xu_horizon_cycles);
  b.bind("tm.xu_history_cycles", &tm.xu_history_cycles);

  b.bind("memory.l1d.size_bytes", &l1d.size_bytes);
  b.bind("memory.l1d.banks", &l1d.banks);
  b.bind("memory.l1d.line_bytes", &l1d.line_bytes);
  b.bind("memory.l1d.hit_latency_cycles", &l1d.hit_latency_cycles);
  b.bind("memory.l1d.calendar_horizon_cycles", &l1d.calendar_horizon_cycles);
  b.bind("memory.l1d.access_energy_nj", &l1d.access_energy_nj);
  b.bind("memory.l1i.size_bytes", &l1i.size_bytes);
  b.bind("memory.l1i.banks", &l1i.banks);
  b.bind("memory.l1i.line_bytes", &l1i.line_bytes);
  b.bind("memory.l1i.hit_latency_cycles", &l1i.hit_latency_cycles);
  b.bind("memory.l1i.model_misses", &l1i.model_misses);
  b.bind("memory.l1i.calendar_horizon_cycles", &l1i.calendar_horizon_cycles);
  b.bind("memory.l1i.access_energy_nj", &l1i.access_energy_nj);
  b.bind("memory.l2.size_bytes", &l2.size_bytes);
  b.bind("memory.l2.banks", &l2.banks);
  b.bind("memory.l2.line_bytes", &l2.line_bytes);
  b.bind("memory.l2.ways", &l2.ways);
  b.bind("memory.l2.hash_banks", &l2.hash_banks);
  b.bind("memory.l2.hit_latency_cycles", &l2.hit_latency_cycles);
  b.bind("memory.l2.calendar_horizon_cycles", &l2.calendar_horizon_cycles);
  b.bind("memory.l2.access_energy_nj", &l2.access_energy_nj);
  b.bind("memory.stream.size_bytes", &stream.size_bytes);
  b.bind("memory.stream.banks", &stream.banks);
  b.bind("memory.stream.ports", &stream.ports);
  b.bind("memory.stream.access_latency_cycles", &stream.access_latency_cycles);
  b.bind("memory.stream.query_latency_cycles", &stream.query_latency_cycles);
  b.bind_enum("memory.stream.policy", &stream.policy, {"fullest-first", "round-robin"});
  b.bind("memory.stream.sticky", &stream.sticky);
  b.bind("memory.stream.calendar_horizon_cycles", &stream.calendar_horizon_cycles);
  b.bind("memory.stream.access_energy_nj", &stream.access_energy_nj);
  b.bind_enum("memory.dram.model", &dram.model, {"channel", "banked"});
  b.bind("memory.dram.channels", &dram.channels);
  b.bind("memory.dram.bytes_per_cycle", &dram.bytes_per_cycle);
  b.bind("memory.dram.latency_cycles", &dram.latency_cycles);
  b.bind("memory.dram.interleave_bytes", &dram.interleave_bytes);
  b.bind("memory.dram.burst_bytes", &dram.burst_bytes);
  b.bind("memory.dram.hash_channels", &dram.hash_channels);
  b.bind("memory.dram.calendar_horizon_cycles", &dram.calendar_horizon_cycles);
  b.bind("memory.dram.access_energy_nj", &dram.access_energy_nj);
  bind_dram_timing(b, "memory.dram.banked", dram.banked);
  b.bind("memory.interconnect.link_bytes_per_cycle", &interconnect.link_bytes_per_cycle);
  b.bind("memory.interconnect.hop_latency_cycles", &interconnect.hop_latency_cycles);
  b.bind("memory.interconnect.calendar_horizon_cycles", &interconnect.calendar_horizon_cycles);
  b.bind("memory.interconnect.transfer_energy_nj", &interconnect.transfer_energy_nj);

  b.bind("energy.register_file_access_nj", &energy.register_file_access_nj);
  b.bind("energy.fp_add_nj", &energy.fp_add_nj);
  b.bind("energy.fp_mul_nj", &energy.fp_mul_nj);
  b.bind("energy.fp_cmp_nj", &energy.fp_cmp_nj);
  b.bind("energy.fp_div_nj", &energy.fp_div_nj);
  b.bind("energy.fp_inv_sqrt_nj", &energy.fp_inv_sqrt_nj);
  b.bind("energy.int_mul_nj", &energy.int_mul_nj);
  b.bind("energy.int_div_nj", &energy.int_div_nj);
  b.bind("energy.box_test_nj", &energy.box_test_nj);
  b.bind("energy.triangle_test_nj", &energy.triangle_test_nj);
}

void ChipConfig::finalize() {
  (void)checked_design(design);
  require(tms >= 1, "tms: the chip needs at least 1 TM, got " + std::to_string(tms));
  require(tms <= 1024, "tms: at most 1024 TMs are supported, got " + std::to_string(tms));
  require(tps_per_tm >= 1 && tps_per_tm <= 64, "tps_per_tm: must be 1..64, got " + std::to_string(tps_per_tm));
  require(clock_ghz >= kMinClockGhz && clock_ghz <= kMaxClockGhz,
          "clock_ghz: must be in [" + real(kMinClockGhz) + ", " + real(kMaxClockGhz) +
              "] GHz (SystemC's 64-bit picosecond time holds 1.8e13 cycles at the slowest), got " +
              real(clock_ghz));
  require(tp_stack_bytes >= 256 && tp_stack_bytes % 16 == 0,
          "tp_stack_bytes: must be a multiple of 16 and at least 256, got " + std::to_string(tp_stack_bytes));
  // A global register access waits this long: 2^32-1 would stall every TP for ever.
  require(global_register_latency_cycles <= memory::kMaxLatencyCycles,
          "global_register_latency_cycles: must be at most " + std::to_string(memory::kMaxLatencyCycles) +
              " cycles, got " + std::to_string(global_register_latency_cycles));
  require(timing.quantum_cycles >= 1 && timing.quantum_cycles <= 65536,
          "timing.quantum_cycles: must be 1..65536, got " + std::to_string(timing.quantum_cycles));
  require(timing.tp_slack_cycles <= 256, "timing.tp_slack_cycles: at most 256 (the XU calendars remember 512 cycles)");
  require(timing.fast_forward_batch_quanta >= 1 && timing.fast_forward_batch_quanta <= 64,
          "timing.fast_forward_batch_quanta: must be 1..64, got " + std::to_string(timing.fast_forward_batch_quanta));
  require(timing.sample_target_error == 0.0 ||
              (timing.sample_target_error >= 0.001 && timing.sample_target_error <= 0.5),
          "timing.sample_target_error: 0 (off) or a relative half-width in [0.001, 0.5], got " +
              real(timing.sample_target_error));
  require(timing.sample_clock_bound >= 0.0 && timing.sample_clock_bound <= 0.5,
          "timing.sample_clock_bound: a relative error in [0, 0.5], got " + real(timing.sample_clock_bound));
  try {  // its syntax; the names are checked against the tree when the sampler is built
    (void)sampling::sample_target_list(timing.sample_target_stats);
  } catch (const std::invalid_argument& e) {
    throw ConfigError(e.what());
  }
  require(timing.sample_head_periods <= 1000,
          "timing.sample_head_periods: 0 (no head) to 1000 periods, got " + std::to_string(timing.sample_head_periods));
  require(timing.sample_drain_share >= 0.0 && timing.sample_drain_share <= 0.5,
          "timing.sample_drain_share: 0 (no drain stratum) or a share of the frame's pixels up to 0.5, got " +
              real(timing.sample_drain_share));
  if (timing.mode == transport::TimingMode::kSampled) {
    const auto& t = timing;
    // In 64 bits: a warm-up near 2^32 must not wrap the sum and pass.
    require(uint64_t{t.sample_warmup_cycles} + t.quantum_cycles <= t.sample_detail_cycles,
            "timing.sample_detail_cycles: must hold the warm-up plus one quantum (" +
                std::to_string(t.sample_warmup_cycles) + " + " + std::to_string(t.quantum_cycles) + "), got " +
                std::to_string(t.sample_detail_cycles));
    require(t.sample_detail_cycles < t.sample_period_cycles,
            "timing.sample_period_cycles: must be longer than timing.sample_detail_cycles (" +
                std::to_string(t.sample_detail_cycles) + "), got " + std::to_string(t.sample_period_cycles));
  }
  (void)parse_tm_list(pipeline_impl_tms, tms);
  // Without the fused pipelines a design issues no fused test: RTL pipelines would do nothing.
  require(pipeline_impl == PipelineImpl::kModel || design.pipelines,
          "tm.pipeline_impl: rtl needs a design with the fused pipelines (design.pipelines=true)");
  tm.tps = tps_per_tm;
  stream.tms = tms;
  stream.threads = threads();
  // The compact path state rides in a 64-byte ray; path records on chip take their bytes from
  // the stream memory, one per ray it can hold.
  stream.ray_bytes = design.streams && design.path_state == PathStatePlacement::kCompact ? 64u : 48u;
  stream.path_record_bytes =
      design.streams && design.path_state == PathStatePlacement::kOnChip ? kernels::kPathRecordBytes : 0;
  // Each TM binds its L1 data cache, its L1 instruction cache and its stream port.
  interconnect.tm_ports = 3 * tms;
  interconnect.l2_banks = l2.banks;
  interconnect.l2_line_bytes = l2.line_bytes;
  interconnect.l2_hash_banks = l2.hash_banks;
  // The stream memory's banks each have a link of the crossbar's width; it books them itself.
  interconnect.stream_link = false;
  stream.link_bytes_per_cycle = interconnect.link_bytes_per_cycle;
  checked("tm", [&] { tm.validate(); });
  checked("memory.l1d", [&] { l1d.validate(); });
  checked("memory.l1i", [&] { l1i.validate(); });
  checked("memory.l2", [&] { l2.validate(); });
  checked("memory.stream", [&] { stream.validate(); });
  checked("memory.dram", [&] { dram.validate(); });
  checked("memory.interconnect", [&] { interconnect.validate(); });
  checked("energy", [&] { energy.validate(); });
  // An L1 fill is one L2 line or less: a longer L1 line would straddle L2 lines.
  for (const auto& [bytes, field] : {std::pair{l1d.line_bytes, "memory.l1d.line_bytes"},
                                     std::pair{l1i.line_bytes, "memory.l1i.line_bytes"}})
    require(bytes <= l2.line_bytes, std::string(field) + ": must be at most memory.l2.line_bytes (" +
                                        std::to_string(l2.line_bytes) + "), got " + std::to_string(bytes));
  if (design.streams) {
    uint32_t capacity = 0;
    checked("memory.stream", [&] { capacity = memory::make_stream_layout(stream).capacity; });
    require(capacity >= threads(), "memory.stream.size_bytes: " + std::to_string(stream.size_bytes) +
                                       " bytes hold " + std::to_string(capacity) + " rays, fewer than one per TP (" +
                                       std::to_string(threads()) + ")");
  }
  for (uint32_t horizon : {l1d.calendar_horizon_cycles, l2.calendar_horizon_cycles, dram.calendar_horizon_cycles})
    require(horizon > timing.quantum_cycles,
            "timing.quantum_cycles: must be below every calendar horizon (" + std::to_string(horizon) + ")");
}

bool ChipConfig::rtl_pipelines(uint32_t tm_index) const {
  return pipeline_impl == PipelineImpl::kRtl && parse_tm_list(pipeline_impl_tms, tms).at(tm_index);
}

ChipConfig load_chip_config(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  ChipConfig config;
  ConfigBinder binder;
  config.bind(binder);
  if (!file.empty()) {
    std::error_code ec;
    if (std::filesystem::exists(file, ec) && !std::filesystem::is_regular_file(file, ec))
      throw ConfigError(file.string() + ": cannot open config file: not a regular file");
    std::ifstream in(file);
    if (!in) throw ConfigError(file.string() + ": cannot open config file");
    nlohmann::json doc;
    try {  // no duplicate key, at most json_input::kMaxDepth levels; errors say where
      doc = json_input::parse_strict(in, file.string());
    } catch (const json_input::JsonInputError& e) {
      throw ConfigError(e.what());
    }
    binder.apply(doc, file.string());
  }
  for (const std::string& o : overrides) binder.apply_override(o);
  config.finalize();
  return config;
}

nlohmann::json to_json(ChipConfig config) {
  ConfigBinder binder;
  config.bind(binder);
  return binder.dump();
}

}  // namespace strata::chip
