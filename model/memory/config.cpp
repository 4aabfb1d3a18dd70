#include "model/memory/config.h"

#include "model/memory/energy_table.h"

#include <stdexcept>

namespace strata::memory {

namespace {
bool pow2(uint64_t v) { return v != 0 && (v & (v - 1)) == 0; }

[[noreturn]] void bad(const char* field, const std::string& why, uint64_t got) {
  throw std::invalid_argument(std::string(field) + ": " + why + " (got " + std::to_string(got) + ")");
}
void need_pow2(const char* field, uint64_t v) {
  if (!pow2(v)) bad(field, "must be a power of two", v);
}
void need_positive(const char* field, uint64_t v) {
  if (v == 0) bad(field, "must be > 0", v);
}
void need_at_most(const char* field, uint64_t v, uint64_t most, const char* unit) {
  if (v > most) bad(field, "must be at most " + std::to_string(most) + " " + unit, v);
}
// Calendars hold 2 x horizon slots each, one calendar per bank, port, link and channel.
void need_horizon(const char* field, uint64_t v) {
  need_positive(field, v);
  need_at_most(field, v, kMaxCalendarHorizonCycles, "cycles");
}
void need_latency(const char* field, uint64_t v) { need_at_most(field, v, kMaxLatencyCycles, "cycles"); }
void need_energy(const char* field, double nj) {
  // Bounded: 1e308 nJ per access would overflow the frame's energy sums to infinity.
  if (!(nj >= 0.0 && nj <= 1e6)) throw std::invalid_argument(std::string(field) + ": must be 0..1e6 nJ per access");
}
// An SRAM without a given energy takes it from the CACTI table, which covers only some sizes.
void need_table_energy(const char* field, uint64_t bytes) {
  try {
    (void)sram_access_energy_nj(bytes);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(field) + ": " + e.what());
  }
}
// Tags and banks use shifts and masks, so the geometry is in powers of two.
void cache_geometry(const char* cache, uint32_t size, uint32_t banks, uint32_t line, uint32_t ways) {
  const std::string p(cache);
  need_pow2((p + ".size_bytes").c_str(), size);
  need_pow2((p + ".banks").c_str(), banks);
  need_pow2((p + ".line_bytes").c_str(), line);
  need_pow2((p + ".ways").c_str(), ways);
  if (line < 16) bad((p + ".line_bytes").c_str(), "must be at least 16 (a ray's or an instruction's access must fit a line)", line);
  if (line > 4096) bad((p + ".line_bytes").c_str(), "must be at most 4096", line);
  if (uint64_t{line} * ways * banks > size)
    bad((p + ".size_bytes").c_str(), "must hold at least one set per bank", size);
}
}  // namespace

const char* to_string(SchedulingPolicy p) {
  return p == SchedulingPolicy::kRoundRobin ? "round-robin" : "fullest-first";
}

void L1DataCacheConfig::validate() const {
  cache_geometry("l1d", size_bytes, banks, line_bytes, 1);
  need_latency("l1d.hit_latency_cycles", hit_latency_cycles);
  need_horizon("l1d.calendar_horizon_cycles", calendar_horizon_cycles);
  need_energy("l1d.access_energy_nj", access_energy_nj);
}

void L1InstructionCacheConfig::validate() const {
  cache_geometry("l1i", size_bytes, banks, line_bytes, 1);
  need_latency("l1i.hit_latency_cycles", hit_latency_cycles);
  need_horizon("l1i.calendar_horizon_cycles", calendar_horizon_cycles);
  need_energy("l1i.access_energy_nj", access_energy_nj);
}

void L2Config::validate() const {
  cache_geometry("l2", size_bytes, banks, line_bytes, ways);
  need_latency("l2.hit_latency_cycles", hit_latency_cycles);
  need_horizon("l2.calendar_horizon_cycles", calendar_horizon_cycles);
  if (access_energy_nj) need_energy("l2.access_energy_nj", *access_energy_nj);
  else need_table_energy("l2.size_bytes", size_bytes);
}

double L2Config::energy_per_access_nj() const {
  return access_energy_nj ? *access_energy_nj : sram_access_energy_nj(size_bytes);
}

void StreamMemoryConfig::validate() const {
  need_positive("stream.treelets", treelets);
  need_positive("stream.threads", threads);
  need_positive("stream.tms", tms);
  need_positive("stream.banks", banks);
  if (banks > 1024) bad("stream.banks", "must be at most 1024", banks);
  need_positive("stream.ports", ports);
  if (ports > 65535) bad("stream.ports", "must be at most 65535", ports);
  need_horizon("stream.calendar_horizon_cycles", calendar_horizon_cycles);
  need_latency("stream.access_latency_cycles", access_latency_cycles);
  need_latency("stream.query_latency_cycles", query_latency_cycles);
  if (ray_bytes != 48 && ray_bytes != 64) bad("stream.ray_bytes", "must be 48 or 64", ray_bytes);
  if (access_energy_nj) need_energy("stream.access_energy_nj", *access_energy_nj);
  else need_table_energy("stream.size_bytes", size_bytes);
}

double StreamMemoryConfig::energy_per_access_nj() const {
  return access_energy_nj ? *access_energy_nj : sram_access_energy_nj(size_bytes);
}

const char* to_string(DramModel m) { return m == DramModel::kBanked ? "banked" : "channel"; }

void DramConfig::validate() const {
  need_positive("dram.channels", channels);
  need_positive("dram.bytes_per_cycle", bytes_per_cycle);
  if (bytes_per_cycle % channels != 0)
    bad("dram.bytes_per_cycle", "must split evenly over dram.channels", bytes_per_cycle);
  if (bytes_per_cycle / channels > 65535)
    bad("dram.bytes_per_cycle", "must be at most 65535 per channel (a channel's calendar counts bytes per cycle)",
        bytes_per_cycle);
  need_pow2("dram.interleave_bytes", interleave_bytes);
  need_pow2("dram.burst_bytes", burst_bytes);
  need_horizon("dram.calendar_horizon_cycles", calendar_horizon_cycles);
  need_latency("dram.latency_cycles", latency_cycles);
  need_energy("dram.access_energy_nj", access_energy_nj);
  if (model == DramModel::kBanked) banked.validate(channel_bytes_per_cycle());
}

void InterconnectConfig::validate() const {
  need_positive("interconnect.tm_ports", tm_ports);
  need_pow2("interconnect.l2_banks", l2_banks);
  need_pow2("interconnect.l2_line_bytes", l2_line_bytes);
  need_positive("interconnect.link_bytes_per_cycle", link_bytes_per_cycle);
  need_horizon("interconnect.calendar_horizon_cycles", calendar_horizon_cycles);
  need_latency("interconnect.hop_latency_cycles", hop_latency_cycles);
  need_energy("interconnect.transfer_energy_nj", transfer_energy_nj);
}

}  // namespace strata::memory
