#include "model/chip/chip_report.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "model/chip/guest_layout.h"
#include "model/sampling/sampling_factors.h"

namespace strata::chip {
namespace {

using stats::Unit;

// printf into a std::string of any length.
std::string format(const char* f, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* f, ...) {
  va_list a, b;
  va_start(a, f);
  va_copy(b, a);
  const int n = std::vsnprintf(nullptr, 0, f, a);
  va_end(a);
  std::string s(n > 0 ? size_t(n) : 0, '\0');
  if (n > 0) std::vsnprintf(s.data(), s.size() + 1, f, b);
  va_end(b);
  return s;
}

unsigned long long ull(uint64_t v) { return static_cast<unsigned long long>(v); }

// "path state 71%, triangles 15%, nodes 12%" from a level's by_data group, by bytes.
std::string by_data_line(const stats::Values& by_data, double* total_bytes) {
  std::vector<std::pair<double, std::string>> parts;
  double total = 0;
  for (unsigned c = 0; c < transport::kDataClassCount; ++c) {
    const auto cls = static_cast<transport::DataClass>(c);
    const double bytes = by_data.number(std::string(transport::data_class_name(cls)) + ".bytes");
    total += bytes;
    if (bytes > 0) parts.emplace_back(bytes, transport::data_class_label(cls));
  }
  *total_bytes = total;
  std::stable_sort(parts.begin(), parts.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::string out;
  double rest = 0;
  int small = 0;
  for (const auto& [bytes, label] : parts) {
    const double share = 100.0 * bytes / total;
    if (share < 0.5) {
      rest += share;
      ++small;
      continue;
    }
    out += (out.empty() ? "" : ", ") + label + format(" %.0f%%", share);
  }
  if (small > 0) out += format(", %d more %.1f%%", small, rest);
  return out;
}

}  // namespace

const std::set<std::string>& FrameReport::detail_axes() {
  static const std::set<std::string> axes = {"tm", "l2-bank", "channel"};
  return axes;
}

FrameReport::FrameReport(const Chip& chip, double wall_seconds, bool interrupted)
    : chip_(chip),
      wall_(wall_seconds),
      interrupted_(interrupted),
      resident_bytes_(chip.backing().resident_bytes()),
      simulation_("simulation", "The simulator's own speed and footprint (host figures, not the chip's).",
                  stats::Basis::kExact) {
  simulation_.level("wall_seconds", [this] { return wall_; }, Unit::kSeconds,
                    "Host wall-clock time of the simulation itself (loading and output excluded).");
  simulation_.derived("instructions_per_second", Unit::kPerSecond, "Simulated instructions per host second.",
                      [](const stats::Scope& s) {
                        const double w = s.self().number("wall_seconds");
                        return w > 0 ? s.root().number("instructions.retired") / w : 0.0;
                      });
  simulation_.derived("rays_per_second", Unit::kPerSecond, "Simulated rays per host second.",
                      [](const stats::Scope& s) {
                        const double w = s.self().number("wall_seconds");
                        return w > 0 ? s.root().number("rays.total") / w : 0.0;
                      });
  simulation_.level("host_memory_resident_bytes", &resident_bytes_, Unit::kBytes,
                    "Host memory the simulated guest memory takes (sparse pages touched).");

  values_ = stats::Values::snapshot(chip.statistics());
  const stats::Values raw = values_;
  // Sampled timing: the windows of a sparser stretch count for more, and the strata timed in
  // full (the frame's head and drain) are estimated by their own ratios.
  if (!has_intervals()) {
    values_.scale(sampling::extrapolation_factors(values_));  // 1 outside sampled timing
  } else {
    const stats::BatchMeans& b = *chip.window_batches();
    const stats::Values middle = b.weighted_total(raw);
    simulated_cycles_ = raw.number("frame.cycles");
    const sampling::SampledEstimate estimate(middle, b.strata(raw), simulated_cycles_);
    samples_cycles_ = estimate.samples_cycles();
    values_ = estimate.scaled(middle);
    // The sampling group reports what was timed and measured, not its weighted sums.
    const auto sampling = [](const std::string& path, const stats::Values::Stat&) {
      return path.compare(0, 9, "sampling.") == 0;
    };
    const stats::Values scaled = values_;
    values_.combine(scaled, -1, sampling);
    values_.combine(raw, +1, sampling);
  }
  values_.append(stats::Values::snapshot(simulation_));
  values_.derive();
  if (has_intervals()) estimate_intervals(raw);
}

void FrameReport::estimate_intervals(const stats::Values& raw) {
  const stats::BatchMeans& b = *chip_.window_batches();
  batches_ = b.batches(raw);
  windows_ = b.windows();
  // A replicate's frame time is the simulated one scaled by the change in the samples' frame
  // time, so the rates (frames/s, GB/s) and static energies vary with it as they would.
  const bool stratified = !b.strata(raw).empty();
  const sampling::SampledEstimate estimate(b.weighted_total(raw), b.strata(raw), raw.number("frame.cycles"));
  std::vector<std::string> paths;
  raw.visit([&](const std::string& path, const stats::Values::Stat&) { paths.push_back(path); });
  const auto measure = [&](stats::Values r) {
    const stats::Values e = estimate(std::move(r));
    std::vector<double> out;
    out.reserve(paths.size());
    e.visit([&](const std::string&, const stats::Values::Stat& s) { out.push_back(s.null ? 0.0 : s.value()); });
    return out;
  };
  // How much of the frame the windows measured: reported, but not used to narrow the
  // intervals (docs/sampled-timing.md, "Confidence intervals": no finite-population correction).
  const double cycles = raw.number("frame.cycles");
  measured_share_ = cycles > 0 ? std::clamp(raw.number("sampling.measured_cycles") / cycles, 0.0, 1.0) : 0.0;
  std::vector<std::vector<double>> replicates;
  const std::vector<double> hw = b.half_widths(raw, measure, kConfidence, &replicates);
  if (hw.empty() && batches_ == 0 && stratified) {
    timed_in_full_ = true;
    interval_note_ = "no confidence intervals: the frame was timed in full as its head and drain strata "
                     "(timing.sample_head_periods, timing.sample_drain_share), with no sampled middle";
    return;
  }
  if (hw.empty() && stratified) {
    interval_note_ = "no confidence intervals: the sampled middle between the frame's head and drain held " +
                     std::to_string(windows_) + " window(s), at least 2 are needed (" +
                     format("%.1f%%", 100 * measured_share_) +
                     " of the frame measured; lower timing.sample_period_cycles or timing.sample_head_periods)";
    return;
  }
  if (hw.empty()) {
    interval_note_ = "no confidence intervals: the frame spanned " + std::to_string(batches_) +
                     " sampling window(s); at least 2 are needed (lower timing.sample_period_cycles)";
    return;
  }
  for (size_t i = 0; i < paths.size(); ++i)
    if (hw[i] > 0 && std::isfinite(hw[i])) half_widths_[paths[i]] = hw[i];
  add_clock_systematic(raw, paths, measure);
  // The replicates of the figures a comparison reads (and the error target's), so a wide
  // interval can be traced to the batches that make it.
  std::vector<std::string> shown = {"frame.cycles", "memory.dram.bytes", "memory.l2.accesses"};
  if (chip_.config().timing.sample_target_error > 0)
    for (const std::string& t : sampling::sample_target_list(chip_.config().timing.sample_target_stats))
      if (std::find(shown.begin(), shown.end(), t) == shown.end()) shown.push_back(t);
  for (size_t i = 0; i < paths.size(); ++i)
    if (std::find(shown.begin(), shown.end(), paths[i]) != shown.end()) replicates_[paths[i]] = replicates[i];
}

void FrameReport::add_clock_systematic(const stats::Values& raw, const std::vector<std::string>& paths,
                                       const std::function<std::vector<double>(stats::Values)>& centre) {
  // The frame time is the simulated clock, whose warm-ups and fast-forwards move it by a few
  // percent against LT, an error the batches' spread cannot see (docs/sampled-timing.md, "The
  // frame time"). The samples' own estimate (instructions at their measured cycles per
  // instruction) errs in other ways. The larger of their disagreement and a measured bound is
  // added to the interval of the frame time and of every figure that follows from it (rates,
  // static energy), as the change those figures show with the frame time moved by it.
  // Their disagreement is not always enough (both may err the same way: Hairball 512x512
  // strata-pipelines, clock -1.11% and samples -0.65% against LT), so the frame time is moved
  // by at least timing.sample_clock_bound, the largest clock error measured against LT.
  if (!(simulated_cycles_ > 0)) return;
  const double disagreement = samples_cycles_ > 0 ? samples_cycles_ / simulated_cycles_ - 1.0 : 0.0;
  const double shift = std::max(std::fabs(disagreement), chip_.config().timing.sample_clock_bound);
  if (!(shift > 0)) return;
  const stats::BatchMeans& b = *chip_.window_batches();
  const stats::Values middle = b.weighted_total(raw);
  const sampling::SampledEstimate at_samples(middle, b.strata(raw),
                                             simulated_cycles_ * (1.0 + (disagreement < 0 ? -shift : shift)));
  const std::vector<double> clock = centre(middle);
  std::vector<double> moved;
  moved.reserve(paths.size());
  at_samples(middle).visit(
      [&](const std::string&, const stats::Values::Stat& s) { moved.push_back(s.null ? 0.0 : s.value()); });
  if (moved.size() != clock.size()) throw std::logic_error("FrameReport: the clock's systematic lost a statistic");
  for (size_t i = 0; i < paths.size(); ++i) {
    const double d = std::fabs(moved[i] - clock[i]);
    if (!(d > 0) || !std::isfinite(d)) continue;
    clock_systematic_[paths[i]] = d;
    half_widths_[paths[i]] += d;
  }
}

std::string FrameReport::pm(const std::string& path) const {
  const auto it = half_widths_.find(path);
  const double v = std::fabs(values_.number(path));
  if (it == half_widths_.end() || v <= 0) return "";
  return format(" \u00b1 %.1f%%", 100.0 * it->second / v);
}

std::string FrameReport::pm_points(const std::string& path) const {
  const auto it = half_widths_.find(path);
  return it == half_widths_.end() ? "" : format(" \u00b1 %.2f points", 100.0 * it->second);
}

nlohmann::json FrameReport::to_json(const std::set<std::string>& detail) const {
  const ChipConfig& cfg = chip_.config();
  nlohmann::json j = values_.to_json(detail);
  j["timing"] = {{"mode", to_string(cfg.timing.mode)}, {"quantum_cycles", cfg.timing.quantum_cycles}};
  j["design"] = {{"name", cfg.design.name}, {"streams", cfg.design.streams}, {"pipelines", cfg.design.pipelines}};
  if (cfg.design.streams) j["design"]["path_state"] = path_state_name(cfg.design.path_state);
  j["simulation"]["timing_mode"] = to_string(cfg.timing.mode);
  j["simulation"]["quantum_cycles"] = cfg.timing.quantum_cycles;
  // Which program ran: frames are comparable only under the same kernel image.
  j["simulation"]["kernel"] = {{"elf", chip_.kernel_name()}, {"image_digest", chip_.kernel_digest()}};
  if (interrupted_) j["interrupted"] = true;
  j["units"] = values_.units();
  if (has_intervals()) {
    // Each estimate's interval beside the tree: intervals.stats mirrors its paths.
    nlohmann::json iv = {{"confidence", kConfidence},
                         {"method", std::string("delete-one-batch replicates over consecutive batches of sampling "
                                                "windows, their spread by ") +
                                        stats::interval_method_name(chip_.window_batches()->method()) +
                                        ", Student t (docs/sampled-timing.md)"},
                         {"windows", windows_},
                         {"batches", batches_},
                         {"measured_share", measured_share_},
                         {"simulated_frame_cycles", simulated_cycles_},
                         // Beside the clock, for the frame time's validation against LT (the
                         // interval is the samples' spread, centred on the clock).
                         {"samples_frame_cycles", samples_cycles_},
                         // The clock's own error allowed in the frame time's interval, relative:
                         // the larger of their disagreement and timing.sample_clock_bound.
                         {"frame_time_systematic", clock_systematic_relative()}};
    if (!replicates_.empty()) {
      // Each figure re-estimated without one batch, in batch order (the frame's start first).
      nlohmann::json r = nlohmann::json::object();
      for (const auto& [path, values] : replicates_) r[path] = values;
      iv["replicates"] = r;
    }
    if (!interval_note_.empty()) iv["note"] = interval_note_;
    if (cfg.timing.sample_target_error > 0) {
      // Each named statistic's interval against the target (-1: no interval was given).
      nlohmann::json t = {{"error", cfg.timing.sample_target_error}, {"stats", nlohmann::json::object()}};
      for (const std::string& path : sampling::sample_target_list(cfg.timing.sample_target_stats)) {
        const double got = target_reached(path);
        t["stats"][path] = {{"relative", got}, {"met", got >= 0 && got <= cfg.timing.sample_target_error}};
      }
      iv["target"] = std::move(t);
    }
    nlohmann::json tree = nlohmann::json::object();
    for (const auto& [path, hw] : half_widths_) {
      nlohmann::json* node = &tree;
      size_t from = 0;
      for (size_t dot = path.find('.'); dot != std::string::npos; from = dot + 1, dot = path.find('.', from))
        node = &(*node)[path.substr(from, dot - from)];
      const double v = std::fabs(values_.number(path));
      nlohmann::json& entry = (*node)[path.substr(from)];
      entry = {{"half_width", hw}, {"relative", v > 0 ? hw / v : 0.0}};
      const auto sys = clock_systematic_.find(path);
      if (sys != clock_systematic_.end()) entry["clock_systematic"] = sys->second;  // of half_width
      const std::string unit = j["units"].value(path, "");
      if (!unit.empty()) j["units"]["intervals.stats." + path + ".half_width"] = unit;
      if (!unit.empty() && sys != clock_systematic_.end())
        j["units"]["intervals.stats." + path + ".clock_systematic"] = unit;
      j["units"]["intervals.stats." + path + ".relative"] = "ratio";
    }
    iv["stats"] = std::move(tree);
    j["intervals"] = std::move(iv);
  }
  j["config"] = chip::to_json(cfg);
  return j;
}

std::string FrameReport::summary() const {
  const stats::Values& v = values_;
  const ChipConfig& cfg = chip_.config();
  const std::string mode = to_string(cfg.timing.mode);
  const char* m = mode.c_str();
  const bool sampled = cfg.timing.mode == transport::TimingMode::kSampled;
  // Estimates carry their interval's level in the tag; what is exact in every mode says so.
  const std::string ci = sampled && !half_widths_.empty() ? mode + ", " + format("%.0f%%", 100 * kConfidence) + " CI" : mode;
  const char* exact = sampled ? " [exact]" : "";
  std::string s;
  s += format("design         %s (%u TMs x %u TPs, %.2f GHz); timing mode %s, quantum %u cycles\n",
              cfg.design.name.c_str(), cfg.tms, cfg.tps_per_tm, cfg.clock_ghz, m, cfg.timing.quantum_cycles);
  if (interrupted_)  // no frame rate: the frame did not finish
    s += format("frame          %llu cycles simulated before the interrupt, %llu pixels done [%s]\n",
                ull(v.count("frame.cycles")), ull(v.count("frame.pixels_done")), m);
  else
    s += format("frame          %llu cycles%s = %.3f ms simulated -> %.2f frames/s [%s]\n", ull(v.count("frame.cycles")),
                pm("frame.cycles").c_str(), v.number("frame.seconds") * 1e3, v.number("frame.frames_per_second"),
                ci.c_str());
  if (cfg.design.streams) {
    // What bounds the paths in flight: the stream memory's rays, or the frame's pixels.
    const uint32_t capacity = uint32_t(v.count("memory.stream.capacity"));
    const uint64_t work = chip_.work_items();
    const uint32_t paths = paths_in_flight_for(capacity, cfg.threads(), work);
    const bool frame_bound = paths == work && capacity > cfg.threads() && capacity - cfg.threads() > work;
    const std::string bound =
        !frame_bound ? "bound by the stream memory, a ray's room kept back per thread"
        : chip_.samples_together()
            ? format("bound by the frame's %llu samples (%u pixels x %u, in flight together), not the stream memory",
                     ull(work), chip_.pixel_count(), uint32_t(work / chip_.pixel_count()))
            : format("bound by the frame's %u pixels, not the stream memory", chip_.pixel_count());
    s += format("path state     %s: %.2f MB of stream memory hold %u rays (%llu B each), paths in flight at most "
                "%u (%s)\n",
                path_state_name(cfg.design.path_state), double(cfg.stream.size_bytes) / 1048576.0, capacity,
                ull(v.count("memory.stream.sram_bytes_per_ray")), paths,
                bound.c_str());
  }
  s += format("rays           %llu primary, %llu bounce, %llu shadow (%llu total)%s\n",
              ull(v.count("rays.primary.traced")), ull(v.count("rays.bounce.traced")),
              ull(v.count("rays.shadow.traced")), ull(v.count("rays.total")), exact);
  const stats::Values& rf = v.group("instructions.register_file");
  const double retired = v.number("instructions.retired");
  s += format("instructions   %llu retired, %llu register-file accesses%s\n", ull(v.count("instructions.retired")),
              ull(rf.count("int_reads") + rf.count("int_writes") + rf.count("fp_reads") + rf.count("fp_writes")), exact);
  const stats::Values& l1d = v.group("memory.l1d");
  s += format("L1 data        %.2f%% hit rate%s (%llu accesses%s, %llu bank conflicts) [%s]\n",
              100.0 * l1d.number("hit_rate"), pm_points("memory.l1d.hit_rate").c_str(), ull(l1d.count("accesses")),
              pm("memory.l1d.accesses").c_str(), ull(l1d.count("bank_conflicts")), ci.c_str());
  const stats::Values& l1i = v.group("memory.l1i");
  const double tp_cycles = v.number("frame.cycles") * double(cfg.threads());
  s += format("L1 instruction %.2f%% hit rate (%llu line requests); fetch stalls %.1f%% of TP-cycles [%s]\n",
              100.0 * l1i.number("hit_rate"), ull(l1i.count("accesses")),
              tp_cycles > 0 ? 100.0 * v.number("instructions.stall_cycles.fetch") / tp_cycles : 0.0, m);
  s += format("L2 / stream    %llu L2 accesses%s, %llu stream accesses%s [%s]\n", ull(v.count("memory.l2.accesses")),
              pm("memory.l2.accesses").c_str(), ull(v.count("memory.stream.accesses")),
              pm("memory.stream.accesses").c_str(), ci.c_str());
  s += format("DRAM           %.3f MB%s, %.1f GB/s%s of %.0f GB/s peak [%s]\n", v.number("memory.dram.bytes") * 1e-6,
              pm("memory.dram.bytes").c_str(), v.number("memory.dram.bandwidth_gb_per_s"),
              pm("memory.dram.bandwidth_gb_per_s").c_str(), v.number("memory.dram.peak_gb_per_s"), ci.c_str());
  if (v.has("memory.dram.banked.channels.row_hits")) {  // memory.dram.model = banked
    const stats::Values& rows = v.group("memory.dram.banked.channels");
    const double requests = rows.number("row_hits") + rows.number("row_misses") + rows.number("row_conflicts");
    const auto share = [&](const char* name) { return requests > 0 ? 100.0 * rows.number(name) / requests : 0.0; };
    s += format("DRAM rows      %.1f%% hits, %.1f%% misses, %.1f%% conflicts; mean read latency %.1f cycles; "
                "%.1f requests in service and %.1f reads in flight at once, on average [%s]\n",
                share("row_hits"), share("row_misses"), share("row_conflicts"),
                rows.number("mean_read_latency_cycles"), rows.number("bank_level_parallelism"),
                rows.number("mean_reads_in_flight"), m);
  }
  const std::pair<const char*, const char*> levels[] = {{"L1 data", "memory.l1d.by_data"},
                                                         {"interconnect", "memory.interconnect.by_data"},
                                                         {"L2", "memory.l2.by_data"},
                                                         {"stream", "memory.stream.by_data"},
                                                         {"DRAM", "memory.dram.by_data"}};
  bool first = true;
  for (const auto& [label, path] : levels) {
    double total = 0;
    const std::string line = by_data_line(v.group(path), &total);
    if (total <= 0) continue;
    s += format("%-14s %s %.3f MB: %s [%s]\n", first ? "bytes by data" : "", label, total * 1e-6, line.c_str(), m);
    first = false;
  }
  if (cfg.design.streams) s += treelet_lines(ci);
  const stats::Values& e = v.group("energy_nj");
  s += format("energy         %.3f mJ/frame%s: L1 %.3f, L2+stream %.3f, DRAM %.3f, fetch %.3f, RF %.3f, XU %.3f mJ [%s]\n",
              e.number("total") * 1e-6, pm("energy_nj.total").c_str(), e.number("l1_data") * 1e-6,
              e.number("l2_and_stream") * 1e-6, e.number("dram") * 1e-6, e.number("instruction_fetch") * 1e-6,
              e.number("register_file") * 1e-6, e.number("xu") * 1e-6, ci.c_str());
  const stats::Values& f = v.group("fidelity");
  const uint64_t overflows = f.count("calendar_overflow_bookings"), late = f.count("xu_late_requests");
  s += format("fidelity       %llu calendar overflows, %llu late XU requests, %.2f%% of cache lookups reordered [%s]\n",
              ull(overflows), ull(late), 100.0 * f.number("reordered_share"), m);
  if (overflows > 0)
    s += format("warning        %llu bookings fell beyond a reservation calendar's horizon: their contention is "
                "approximate, so cycles and queueing are less accurate; raise the calendar_horizon_cycles of "
                "the modules that report them (stats.json: calendar_overflow_bookings)\n",
                ull(overflows));
  if (late > 0)
    s += format("warning        %llu XU requests came later than the crossbar's history: they were timed at the "
                "oldest remembered cycle, so XU contention is approximate; raise tm.xu_horizon_cycles\n",
                ull(late));
  // Precise mode sends every TP request when global time reaches its cycle, so the L1s see
  // theirs in time order. The L2 may still correct a few: an L1 sends a miss below at its
  // own answer cycle, a cycle or two ahead of global time (counted in `reordered` alone).
  const uint64_t l1_reordered = v.count("memory.l1d.reordered") + v.count("memory.l1i.reordered");
  if (l1_reordered > 0 && cfg.timing.mode == transport::TimingMode::kPrecise)
    s += format("warning        %llu L1 lookups arrived out of time order in precise mode, which should never "
                "happen: the precise reference is not exact\n",
                ull(l1_reordered));
  if (v.has("rtl_pipelines")) {  // tm.pipeline_impl=rtl
    const stats::Values& r = v.group("rtl_pipelines");
    const uint64_t mismatches = r.count("box_latency_mismatches") + r.count("triangle_latency_mismatches");
    s += format("RTL pipelines  %llu box + %llu triangle tests computed by the verilated RTL in %llu TM(s); RTL latency "
                "vs config: %llu box and %llu triangle mismatches, %llu slow-path triangle tests (+2 cycles, charged "
                "the config's latency) [exact]\n",
                ull(r.count("box_tests")), ull(r.count("triangle_tests")), ull(r.count("tms")),
                ull(r.count("box_latency_mismatches")), ull(r.count("triangle_latency_mismatches")),
                ull(r.count("triangle_slow_path_tests")));
    if (mismatches > 0)
      s += format("warning        %llu fused tests took a different number of cycles in the RTL than "
                  "tm.pipelines.<box|triangle>.latency charges: the RTL and the config disagree\n",
                  ull(mismatches));
  }
  s += format("simulator      %.2f s wall, %.2f M simulated instructions/s, %.3f M rays/s\n",
              v.number("simulation.wall_seconds"), v.number("simulation.instructions_per_second") * 1e-6,
              v.number("simulation.rays_per_second") * 1e-6);
  if (v.has("sampling")) {
    const stats::Values& sm = v.group("sampling");
    const double timed = sm.number("timed_instructions");
    // With an error target the period moves (the target line says where it ended).
    if (sm.count("short_frame_rest_cycles") > 0)  // the note below says why
      s += format("sampling       %.1f%% of instructions timed: the whole frame, no windows [sampled]\n",
                  retired > 0 ? 100.0 * timed / retired : 0.0);
    else
      s += format("sampling       %.1f%% of instructions timed (%llu of every %llu cycles%s, %llu warm-up); memory "
                  "figures extrapolated x%.2f, XU x%.2f [sampled]\n",
                  retired > 0 ? 100.0 * timed / retired : 0.0, ull(sm.count("detail_cycles")),
                  ull(sm.count("period_cycles")), sm.count("period_changes") > 0 ? " at first" : "",
                  ull(sm.count("warmup_cycles")),
                  sm.number("memory_extrapolation_factor"), sm.number("extrapolation_factor"));
    if (simulated_cycles_ > 0 && !clock_systematic_.empty())
      s += format("frame time     the simulated clock, %llu cycles, its warm-ups and fast-forwards included; the samples "
                  "estimate %llu (%+.2f%%); the clock's own error, the larger of that and %.1f%% (timing.sample_clock_bound), "
                  "is in the interval of the frame time and of what follows from it (docs/sampled-timing.md, \"The "
                  "clock's error in the interval\") [sampled]\n",
                  ull(static_cast<uint64_t>(simulated_cycles_)), ull(static_cast<uint64_t>(samples_cycles_ + 0.5)),
                  100.0 * (samples_cycles_ / simulated_cycles_ - 1.0), 100.0 * cfg.timing.sample_clock_bound);
    else if (simulated_cycles_ > 0)
      s += format("frame time     the simulated clock, %llu cycles, its warm-ups and fast-forwards included [sampled]\n",
                  ull(static_cast<uint64_t>(simulated_cycles_)));
    if (sm.count("short_frame_rest_cycles") > 0)
      s += format("note           too short for sampling: near its head's end the frame was projected to run %llu "
                  "more cycles, fewer than %.0f periods of %llu, so all of it was timed in full, as LT times it "
                  "[sampled]\n",
                  ull(sm.count("short_frame_rest_cycles")), WindowSampler::kShortFramePeriods,
                  ull(sm.count("period_cycles")));
    if (sm.count("head_cycles") > 0 || sm.count("drain_cycles") > 0)
      s += format("strata         head %llu cycles, drain %llu cycles: timed in full and estimated apart from the "
                  "sampled middle [sampled]\n",
                  ull(sm.count("head_cycles")), ull(sm.count("drain_cycles")));
    if (!interval_note_.empty())
      s += format("%s %s\n", timed_in_full_ ? "intervals     " : "warning       ", interval_note_.c_str());
    else
      s += format("intervals      %.0f%% confidence, from %zu windows in %zu batches (%s; %.1f%% of the frame "
                  "measured); figures without a \u00b1 are exact [sampled]\n",
                  100 * kConfidence, windows_, batches_,
                  stats::interval_method_name(chip_.window_batches()->method()), 100 * measured_share_);
    if (cfg.timing.sample_target_error > 0) s += target_lines();
  }
  return s;
}

double FrameReport::clock_systematic_relative() const {
  const auto it = clock_systematic_.find("frame.cycles");
  return it == clock_systematic_.end() || !(simulated_cycles_ > 0) ? 0.0 : it->second / simulated_cycles_;
}

double FrameReport::target_reached(const std::string& path) const {
  const auto it = half_widths_.find(path);
  const double v = std::fabs(values_.number(path));
  return it == half_widths_.end() || !(v > 0) ? -1.0 : it->second / v;
}

std::string FrameReport::target_lines() const {
  const ChipConfig& cfg = chip_.config();
  const stats::Values& sm = values_.group("sampling");
  const double target = cfg.timing.sample_target_error;
  const auto label = [](const std::string& path) { return path == "frame.cycles" ? std::string("frame cycles") : path; };
  std::string s, missed, unshrinkable;
  std::vector<std::string> missed_paths;
  for (const std::string& path : sampling::sample_target_list(cfg.timing.sample_target_stats)) {
    const double got = target_reached(path);
    if (got >= 0 && got <= target)
      s += format("target         %s \u00b1 %.1f%% asked, \u00b1 %.2f%% reached [sampled]\n", label(path).c_str(),
                  100 * target, 100 * got);
    else {
      missed_paths.push_back(path);
      missed += format("%s%s \u00b1 %.1f%% asked, %s reached", missed.empty() ? "" : "; ", label(path).c_str(),
                       100 * target, got >= 0 ? format("\u00b1 %.2f%%", 100 * got).c_str() : "no interval");
    }
    // A systematic part the windows cannot shrink: say so rather than blame the period.
    const auto sys = clock_systematic_.find(path);
    const double v = std::fabs(values_.number(path));
    if (got > target && sys != clock_systematic_.end() && v > 0 && sys->second / v >= target)
      unshrinkable += format("%s%s \u00b1 %.2f%%", unshrinkable.empty() ? "" : ", ", label(path).c_str(),
                             100 * sys->second / v);
  }
  const uint64_t last = sm.count("last_period_cycles"), shortest = sm.count("min_period_cycles");
  s += format("target         the period ended at %llu cycles after %llu change(s), planned for the widest of %s [sampled]\n",
              ull(last), ull(sm.count("period_changes")), cfg.timing.sample_target_stats.c_str());
  // Targets the plan left out as out of reach: said first, with when and what they needed.
  std::string left_out;
  for (const WindowSampler::OutOfReach& o : chip_.targets_out_of_reach())
    left_out += o.cycle == 0
                    ? format("%s%s from the start (its interval holds the clock's own error, at least "
                             "timing.sample_clock_bound = \u00b1 %.2f%%)",
                             left_out.empty() ? "" : ", ", label(o.stat).c_str(), 100 * o.best)
                    : format("%s%s at cycle %llu (projected then to end at \u00b1 %.2f%% even so)",
                             left_out.empty() ? "" : ", ", label(o.stat).c_str(), ull(o.cycle), 100 * o.best);
  if (!left_out.empty())
    s += format("target         out of reach at the shortest period (%llu cycles), left out of the plan: %s; the "
                "windows were planned for the others%s [sampled]\n",
                ull(shortest), left_out.c_str(),
                chip_.targets_out_of_reach().size() == sampling::sample_target_list(cfg.timing.sample_target_stats).size()
                    ? " (none left: the configured period)"
                    : "");
  if (missed.empty()) return s;
  // Why: the period reached its shortest (the frame ended first), or the sampler still had
  // room to shorten it, so its last plan expected the target met.
  const uint64_t windows = sm.count("windows");
  std::string why =
      windows < WindowSampler::kPilotWindows
          ? format("no plan was possible: the frame held %llu window(s) before its last, and the sampler plans after "
                   "%zu (lower timing.sample_period_cycles, or use timing.mode=lt for this frame)",
                   ull(windows), WindowSampler::kPilotWindows)
      : last <= shortest
          ? format("the frame ended before enough windows were measured (the period was %llu cycles at the "
                   "end, the shortest allowed): use timing.mode=lt for this frame, or accept the wider interval",
                   ull(last))
          : format("the sampler's last plan expected it met (the period was %llu cycles at the end, above the "
                   "shortest allowed, %llu), but the frame's final interval came out wider: run again with a "
                   "tighter target, or accept the wider interval",
                   ull(last), ull(shortest));
  // Each missed statistic for its own reason: its interval's systematic part alone is wider than
  // the target, the plan left it out as out of reach, or the windows ran out (`why`).
  std::vector<std::string> reasons;
  if (!unshrinkable.empty())
    reasons.push_back("the clock's systematic error alone (" + unshrinkable +
                      ": the larger of the simulated clock against the samples' frame time and "
                      "timing.sample_clock_bound) is wider than the target, and more windows do not shrink it");
  bool others = false, any_left_out = false;
  for (const std::string& path : missed_paths) {
    const auto& gone = chip_.targets_out_of_reach();
    const bool left = std::any_of(gone.begin(), gone.end(), [&](const WindowSampler::OutOfReach& o) { return o.stat == path; });
    const auto sys = clock_systematic_.find(path);
    const double v = std::fabs(values_.number(path));
    const bool systematic = sys != clock_systematic_.end() && v > 0 && sys->second / v >= target;
    any_left_out = any_left_out || (left && !systematic);
    others = others || (!left && !systematic);
  }
  if (any_left_out)
    reasons.push_back("those left out of the plan were out of reach at the shortest period, and no windows were spent "
                      "on them");
  if (others) reasons.push_back(why);
  std::string all;
  for (const std::string& r : reasons) all += (all.empty() ? "" : "; ") + r;
  if (others) return s + format("warning        the error target was not met: %s; %s\n", missed.c_str(), all.c_str());
  return s + format("warning        the error target was not met: %s; %s: use timing.mode=lt for this frame, or accept "
                    "the wider interval\n",
                    missed.c_str(), all.c_str());
}

std::string FrameReport::treelet_lines(const std::string& ci) const {
  // DRAM traffic as sessions x lines per session; the rays each visit serves, and the rays in
  // flight that feed the buffers, against the capacity.
  const stats::Values& t = values_.group("treelets.sessions");
  const double sessions = t.number("sessions");
  std::string s = format("treelets       %llu sessions (node %llu, triangle %llu; %llu traced no ray), %.1f rays/session; "
                         "%.1f L1 data lines filled/session%s: L2 hit %.1f, DRAM %.1f, merged at the L2 %.1f [%s]\n",
                         ull(t.count("sessions")), ull(t.count("node.sessions")), ull(t.count("triangle.sessions")),
                         ull(t.count("rays_histogram.zero")), t.number("rays_per_session"), t.number("lines_per_session"),
                         pm("treelets.sessions.lines_per_session").c_str(), t.number("l2_hit_lines_per_session"),
                         t.number("dram_lines_per_session"), sessions > 0 ? t.number("lines_l2_merged") / sessions : 0.0,
                         ci.c_str());
  for (const char* kind : {"node", "triangle"}) {
    const stats::Values& k = t.group(kind);
    s += format("%-14s %s treelets: %.1f rays/session, %.1f lines/session (L2 hit %.1f, DRAM %.1f) [%s]\n", "",
                kind, k.number("rays_per_session"), k.number("lines_per_session"),
                k.number("l2_hit_lines_per_session"), k.number("dram_lines_per_session"), ci.c_str());
  }
  const stats::Values& f = values_.group("treelets.rays_in_flight");
  const stats::Values& b = values_.group("treelets.buffers");
  const double capacity = f.number("capacity");
  const auto share = [capacity](double n) { return capacity > 0 ? 100.0 * n / capacity : 0.0; };
  s += format("rays in flight mean %.0f (%.1f%% of the %llu-ray capacity), steady state %.0f (%.1f%%) until cycle %llu; "
              "%.1f buffers held rays, %.1f rays each (time-weighted) [%s]\n",
              f.number("mean"), share(f.number("mean")), ull(f.count("capacity")), f.number("steady_state"),
              share(f.number("steady_state")), ull(f.count("steady_end_cycle")), b.number("nonempty_mean"),
              b.number("rays_per_nonempty_mean"), to_string(chip_.config().timing.mode));
  if (chip_.config().timing.mode == transport::TimingMode::kSampled && !chip_.config().timing.fast_forward_time_order)
    s += "note           the sessions are every session of the sampled execution, whose fast-forward in arrival order "
         "(timing.fast_forward_time_order=false) changes the ray schedule (fewer, longer sessions than LT): read "
         "sessions and rays per session from LT (docs/sampled-timing.md, \"Treelet sessions\")\n";
  return s;
}

nlohmann::json chip_report(const Chip& chip, double wall_seconds) { return FrameReport(chip, wall_seconds).to_json(); }

}  // namespace strata::chip
