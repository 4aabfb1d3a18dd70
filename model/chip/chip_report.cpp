#include "model/chip/chip_report.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace strata::chip {
namespace {

double ratio(double a, double b) { return b > 0 ? a / b : 0.0; }

nlohmann::json rays_json(const kernels::RayCounters& c) {
  const char* names[] = {"primary", "bounce", "shadow"};
  nlohmann::json j;
  uint64_t total = 0;
  for (uint32_t t = 0; t < kernels::kRayTypes; ++t) {
    j[names[t]] = {{"traced", c.rays[t]}, {t == kernels::kShadowRay ? "occluded" : "hit", c.hits[t]}};
    total += c.rays[t];
  }
  j["total"] = total;
  j["paths"] = c.paths;
  j["node_visits"] = c.node_visits;
  j["triangle_tests"] = c.triangle_tests;
  return j;
}

// Sampled timing counts memory accesses in the measured parts of its detailed windows only
// (past the warm-up), and XU operations and stalls in the whole detailed windows; each is
// extrapolated to the frame by instructions retired over the instructions of the part it
// was counted in (1 in the other modes). Occupancies, capacities and rates stay as they are.
class Extrapolation {
 public:
  explicit Extrapolation(double scale) : scale_(scale) {}
  double scale() const { return scale_; }
  uint64_t operator()(uint64_t v) const { return static_cast<uint64_t>(std::llround(double(v) * scale_)); }
  double operator()(double v) const { return v * scale_; }
  nlohmann::json json(nlohmann::json j) const {
    if (scale_ == 1.0) return j;
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string& key = it.key();
      if (key == "capacity" || key == "stored" || key == "peak_gb_per_s" || key == "bandwidth_gb_per_s") continue;
      if (it->is_object()) *it = json(*it);
      else if (it->is_number_unsigned()) *it = (*this)(it->get<uint64_t>());
      else if (it->is_number()) *it = (*this)(it->get<double>());
    }
    return j;
  }

 private:
  double scale_;
};

struct CacheSums {
  uint64_t accesses = 0, hits = 0, misses = 0, merged = 0, conflicts = 0, bytes = 0;
  double energy_nj = 0;
};

}  // namespace

nlohmann::json chip_report(const Chip& chip, double wall_seconds) {
  const ChipConfig& cfg = chip.config();
  const transport::Cycle cycles = chip.cycles();
  const double seconds = double(cycles) / (cfg.clock_ghz * 1e9);
  nlohmann::json j;
  j["timing"] = {{"mode", to_string(cfg.timing.mode)}, {"quantum_cycles", cfg.timing.quantum_cycles}};
  j["design"] = {{"name", cfg.design.name}, {"streams", cfg.design.streams}, {"pipelines", cfg.design.pipelines}};
  j["chip"] = {{"tms", cfg.tms}, {"tps_per_tm", cfg.tps_per_tm}, {"threads", cfg.threads()}, {"clock_ghz", cfg.clock_ghz}};
  j["frame"] = {{"cycles", cycles}, {"seconds", seconds}, {"frames_per_second", ratio(1.0, seconds)}};
  const kernels::RayCounters rays = chip.ray_counters();
  j["rays"] = rays_json(rays);

  // Sampled timing: each counter is extrapolated by the instructions that cause it, whose
  // whole-frame counts the ISS knows exactly: fetches by instructions, data traffic by
  // loads/stores/pipeline loads, stream traffic by stream operations.
  iss::Counters mix;  // exact in every mode: instructions, their classes, register-file accesses
  uint64_t timed = 0, measured = 0, measured_data = 0, measured_stream = 0;
  for (const auto& t : chip.tms()) {
    mix += t->iss_counters();
    timed += t->counters().detailed_instructions;
    measured += t->counters().measured_instructions;
    measured_data += t->counters().measured_data_ops;
    measured_stream += t->counters().stream_requests;
  }
  const uint64_t retired = mix.retired;
  uint64_t frame_data = 0;
  for (unsigned c = 0; c < iss::kClassCount; ++c)
    if (is_data_op(iss::InstrClass(c))) frame_data += mix.by_class[c];
  const uint64_t frame_stream = mix.of(iss::InstrClass::kStrataStream);
  const bool sampled = cfg.timing.mode == transport::TimingMode::kSampled;
  auto factor = [&](uint64_t all, uint64_t part) { return sampled && part > 0 ? double(all) / double(part) : 1.0; };
  const Extrapolation x(factor(retired, timed));
  const Extrapolation fetch(factor(retired, measured));
  const Extrapolation mem(factor(frame_data, measured_data));
  const Extrapolation stream(factor(frame_stream, measured_stream));
  if (sampled)
    j["sampling"] = {{"period_cycles", cfg.timing.sample_period_cycles},
                     {"detail_cycles", cfg.timing.sample_detail_cycles},
                     {"warmup_cycles", cfg.timing.sample_warmup_cycles},
                     {"timed_instructions", timed},
                     {"measured_instructions", measured},
                     {"fast_forward_instructions", retired - timed},
                     {"extrapolation_factor", x.scale()},
                     {"memory_extrapolation_factor", mem.scale()},
                     {"fetch_extrapolation_factor", fetch.scale()},
                     {"stream_extrapolation_factor", stream.scale()},
                     {"extrapolated", "memory, XU, stall, fetch-request and energy counters (not rays, "
                                      "instructions, register-file accesses or cycles)"}};

  // Stalls and XUs, summed over the TMs.
  tm::TpStats tp;  // only its stall cycles: the ISS counts instructions and registers exactly
  tm::XuStats xu;
  uint64_t local = 0, icache_requests = 0;
  for (const auto& t : chip.tms()) {
    const tm::TpStats s = t->tp_stats();
    for (size_t i = 0; i < s.stall_cycles.size(); ++i) tp.stall_cycles[i] += s.stall_cycles[i];
    const tm::XuStats u = t->xus().stats(cycles);
    for (unsigned m = 0; m < tm::kModeCount; ++m)
      for (unsigned c = 0; c < tm::kXuClassCount; ++c) {
        xu.by_mode[m][c].ops += x(u.by_mode[m][c].ops);
        xu.by_mode[m][c].busy_unit_cycles += x(u.by_mode[m][c].busy_unit_cycles);
      }
    xu.box_tests += x(u.box_tests);
    xu.triangle_tests += x(u.triangle_tests);
    xu.triangle_divides += x(u.triangle_divides);
    xu.reconfigurations += x(u.reconfigurations);
    for (unsigned m = 0; m < tm::kModeCount; ++m) xu.mode_cycles[m] += u.mode_cycles[m];
    local += mem(t->counters().local_accesses);
    icache_requests += fetch(t->counters().icache_fetch_requests);
  }
  for (uint64_t& s : tp.stall_cycles) s = x(s);
  nlohmann::json& ins = j["instructions"];
  ins["retired"] = mix.retired;
  for (unsigned c = 0; c < iss::kClassCount; ++c)
    if (mix.by_class[c]) ins["mix"][iss::class_name(iss::InstrClass(c))] = mix.by_class[c];
  // Every retired instruction was fetched once and read its registers once; the ISS counts
  // both exactly in every timing mode.
  ins["fetched"] = mix.retired;
  ins["icache_line_requests"] = icache_requests;
  ins["register_file"] = {{"int_reads", mix.int_reads}, {"int_writes", mix.int_writes},
                          {"fp_reads", mix.fp_reads}, {"fp_writes", mix.fp_writes}};
  for (unsigned s = 0; s < tm::kStallCauseCount; ++s)
    ins["stall_cycles"][tm::stall_cause_name(tm::StallCause(s))] = tp.stall_cycles[s];
  ins["tp_local_memory_accesses"] = local;

  const char* mode_names[] = {"general", "box", "triangle"};
  const uint32_t units[tm::kXuClassCount] = {cfg.tm.xu.fp_mul.count, cfg.tm.xu.fp_add.count,
                                             cfg.tm.xu.fp_cmp.count, cfg.tm.xu.fp_div.count,
                                             cfg.tm.xu.fp_inv_sqrt.count, cfg.tm.xu.int_mul.count,
                                             cfg.tm.xu.int_div.count};
  nlohmann::json& xj = j["xu"];
  for (unsigned m = 0; m < tm::kModeCount; ++m) {
    const double mode_cycles = double(xu.mode_cycles[m]);
    xj["mode_cycles"][mode_names[m]] = xu.mode_cycles[m];
    for (unsigned c = 0; c < tm::kXuClassCount; ++c) {
      const tm::XuUse& use = xu.by_mode[m][c];
      if (use.ops == 0) continue;
      xj["by_mode"][mode_names[m]][tm::xu_class_name(tm::XuClass(c))] = {
          {"ops", use.ops}, {"utilisation", ratio(double(use.busy_unit_cycles), units[c] * mode_cycles)}};
    }
  }
  xj["box_tests"] = xu.box_tests;
  xj["triangle_tests"] = xu.triangle_tests;
  xj["triangle_divides"] = xu.triangle_divides;
  xj["reconfigurations"] = xu.reconfigurations;

  // Memory: caches summed over the TMs, then the shared levels.
  CacheSums l1d, l1i;
  for (const auto& c : chip.l1d()) {
    const auto& k = c->counters();
    l1d.accesses += mem(k.accesses);
    l1d.hits += mem(k.hits);
    l1d.misses += mem(k.misses);
    l1d.merged += mem(k.merged_misses);
    l1d.conflicts += mem(k.bank_conflicts);
    l1d.bytes += mem(k.bytes_read + k.bytes_written);
    l1d.energy_nj += mem(k.energy_nj);
  }
  for (const auto& c : chip.l1i()) {
    const auto& k = c->counters();
    l1i.accesses += fetch(k.accesses);
    l1i.hits += fetch(k.hits);
    l1i.misses += fetch(k.misses);
    l1i.conflicts += fetch(k.bank_conflicts);
    l1i.energy_nj += fetch(k.energy_nj);
  }
  nlohmann::json& mj = j["memory"];
  mj["l1d"] = {{"accesses", l1d.accesses}, {"hits", l1d.hits}, {"misses", l1d.misses},
               {"merged_misses", l1d.merged}, {"bank_conflicts", l1d.conflicts},
               {"hit_rate", ratio(double(l1d.hits), double(l1d.hits + l1d.misses))}, {"energy_nj", l1d.energy_nj}};
  mj["l1i"] = {{"accesses", l1i.accesses}, {"hits", l1i.hits}, {"misses", l1i.misses},
               {"bank_conflicts", l1i.conflicts}, {"energy_nj", l1i.energy_nj}};
  mj["l2"] = mem.json(chip.l2().stats().to_json());
  mj["stream"] = stream.json(chip.stream().stats().to_json());
  mj["interconnect"] = mem.json(chip.interconnect().stats().to_json());
  const auto& dram = chip.dram().counters();
  const uint64_t dram_bytes = mem(dram.bytes_read + dram.bytes_written);
  mj["dram"] = mem.json(chip.dram().stats().to_json());
  mj["dram"]["bytes"] = dram_bytes;
  mj["dram"]["bandwidth_gb_per_s"] = ratio(double(dram_bytes), seconds) * 1e-9;
  mj["dram"]["peak_gb_per_s"] = double(cfg.dram.bytes_per_cycle) * cfg.clock_ghz;

  // Energy per frame (nJ), split as the STRaTA paper does.
  const EnergyConfig& e = cfg.energy;
  const double per_class[tm::kXuClassCount] = {e.fp_mul_nj, e.fp_add_nj, e.fp_cmp_nj, e.fp_div_nj,
                                               e.fp_inv_sqrt_nj, e.int_mul_nj, e.int_div_nj};
  double xu_nj = double(xu.box_tests) * e.box_test_nj + double(xu.triangle_tests) * e.triangle_test_nj;
  for (unsigned c = 0; c < tm::kXuClassCount; ++c) xu_nj += double(xu.total(tm::XuClass(c)).ops) * per_class[c];
  const double fetch_nj = double(mix.retired) * cfg.l1i.access_energy_nj;
  const double rf_nj = double(mix.int_reads + mix.int_writes + mix.fp_reads + mix.fp_writes) * e.register_file_access_nj;
  const double l2_stream_nj = mem(chip.l2().counters().energy_nj) + stream(chip.stream().counters().energy_nj);
  const double dram_nj = mem(dram.energy_nj);
  nlohmann::json& en = j["energy_nj"];
  en["l1_data"] = l1d.energy_nj;
  en["l2_and_stream"] = l2_stream_nj;
  en["dram"] = dram_nj;
  en["instruction_fetch"] = fetch_nj;
  en["register_file"] = rf_nj;
  en["xu"] = xu_nj;
  en["total"] = l1d.energy_nj + l2_stream_nj + dram_nj + fetch_nj + rf_nj + xu_nj;

  j["simulation"] = {{"timing_mode", to_string(cfg.timing.mode)},
                     {"quantum_cycles", cfg.timing.quantum_cycles},
                     {"wall_seconds", wall_seconds},
                     {"instructions_per_second", ratio(double(mix.retired), wall_seconds)},
                     {"rays_per_second", ratio(double(j["rays"]["total"].get<uint64_t>()), wall_seconds)},
                     {"host_memory_resident_bytes", chip.backing().resident_bytes()}};
  j["config"] = to_json(cfg);
  return j;
}

std::string summary_text(const nlohmann::json& r) {
  char buf[4096];
  const auto& f = r["frame"];
  const auto& rays = r["rays"];
  const auto& m = r["memory"];
  const auto& e = r["energy_nj"];
  const auto& s = r["simulation"];
  const std::string mode = r["timing"]["mode"].get<std::string>();
  char frame[256];
  if (r.value("interrupted", false))  // no frame rate: the frame did not finish
    std::snprintf(frame, sizeof frame, "%llu cycles simulated before the interrupt, %u pixels done [%s]",
                  f["cycles"].get<unsigned long long>(), f.value("pixels_done", 0u), mode.c_str());
  else
    std::snprintf(frame, sizeof frame, "%llu cycles = %.3f ms simulated -> %.2f frames/s [%s]",
                  f["cycles"].get<unsigned long long>(), f["seconds"].get<double>() * 1e3,
                  f["frames_per_second"].get<double>(), mode.c_str());
  std::snprintf(
      buf, sizeof buf,
      "design         %s (%u TMs x %u TPs, %.2f GHz); timing mode %s, quantum %u cycles\n"
      "frame          %s\n"
      "rays           %llu primary, %llu bounce, %llu shadow (%llu total)\n"
      "instructions   %llu retired, %llu register-file accesses\n"
      "L1 data        %.2f%% hit rate (%llu accesses, %llu bank conflicts) [%s]\n"
      "L2 / stream    %.0f L2 accesses, %.0f stream accesses [%s]\n"
      "DRAM           %.3f MB, %.1f GB/s of %.0f GB/s peak [%s]\n"
      "energy         %.3f mJ/frame: L1 %.3f, L2+stream %.3f, DRAM %.3f, fetch %.3f, RF %.3f, XU %.3f mJ [%s]\n"
      "simulator      %.2f s wall, %.2f M simulated instructions/s, %.3f M rays/s\n",
      r["design"]["name"].get<std::string>().c_str(), r["chip"]["tms"].get<unsigned>(),
      r["chip"]["tps_per_tm"].get<unsigned>(), r["chip"]["clock_ghz"].get<double>(), mode.c_str(),
      r["timing"]["quantum_cycles"].get<unsigned>(), frame,
      rays["primary"]["traced"].get<unsigned long long>(), rays["bounce"]["traced"].get<unsigned long long>(),
      rays["shadow"]["traced"].get<unsigned long long>(), rays["total"].get<unsigned long long>(),
      r["instructions"]["retired"].get<unsigned long long>(),
      (r["instructions"]["register_file"]["int_reads"].get<unsigned long long>() +
       r["instructions"]["register_file"]["int_writes"].get<unsigned long long>() +
       r["instructions"]["register_file"]["fp_reads"].get<unsigned long long>() +
       r["instructions"]["register_file"]["fp_writes"].get<unsigned long long>()),
      100.0 * m["l1d"]["hit_rate"].get<double>(), m["l1d"]["accesses"].get<unsigned long long>(),
      m["l1d"]["bank_conflicts"].get<unsigned long long>(), mode.c_str(),
      m["l2"].value("accesses", 0.0), m["stream"].value("accesses", 0.0), mode.c_str(),
      m["dram"]["bytes"].get<double>() * 1e-6, m["dram"]["bandwidth_gb_per_s"].get<double>(),
      m["dram"]["peak_gb_per_s"].get<double>(), mode.c_str(), e["total"].get<double>() * 1e-6,
      e["l1_data"].get<double>() * 1e-6, e["l2_and_stream"].get<double>() * 1e-6, e["dram"].get<double>() * 1e-6,
      e["instruction_fetch"].get<double>() * 1e-6, e["register_file"].get<double>() * 1e-6,
      e["xu"].get<double>() * 1e-6, mode.c_str(), s["wall_seconds"].get<double>(),
      s["instructions_per_second"].get<double>() * 1e-6, s["rays_per_second"].get<double>() * 1e-6);
  std::string text = buf;
  if (r.contains("sampling")) {
    const auto& sm = r["sampling"];
    const double timed = sm["timed_instructions"].get<double>();
    const double all = timed + sm["fast_forward_instructions"].get<double>();
    std::snprintf(buf, sizeof buf,
                  "sampling       %.1f%% of instructions timed (%u of every %u cycles, %u warm-up); memory "
                  "figures extrapolated x%.2f, XU x%.2f [sampled]\n",
                  all > 0 ? 100.0 * timed / all : 0.0, sm["detail_cycles"].get<unsigned>(),
                  sm["period_cycles"].get<unsigned>(), sm["warmup_cycles"].get<unsigned>(),
                  sm["memory_extrapolation_factor"].get<double>(), sm["extrapolation_factor"].get<double>());
    text += buf;
  }
  return text;
}

}  // namespace strata::chip
