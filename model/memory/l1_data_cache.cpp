#include "model/memory/l1_data_cache.h"

namespace strata::memory {

using transport::AccessClass;
using transport::Cycle;
using transport::MemoryExtension;
using transport::ServedBy;

L1DataCache::L1DataCache(sc_core::sc_module_name name, const L1DataCacheConfig& config, SparseMemory& backing)
    : sc_core::sc_module(name),
      config_((config.validate(), config)),
      backing_(backing),
      core_(CacheGeometry{config.size_bytes, config.banks, config.line_bytes, 1, config.calendar_horizon_cycles}),
      below_(downstream, config.line_bytes),
      stats_(basename()) {
  target.register_b_transport(this, &L1DataCache::b_transport);
  Counters& c = counters_;
  stats_.add({{"accesses", &c.accesses}, {"loads", &c.loads}, {"stores", &c.stores},
                      {"hits", &c.hits}, {"misses", &c.misses}, {"merged_misses", &c.merged_misses},
                      {"bank_conflicts", &c.bank_conflicts}, {"conflict_cycles", &c.conflict_cycles},
                      {"fills", &c.fills}, {"bytes_read", &c.bytes_read}, {"bytes_written", &c.bytes_written},
                      {"downstream_requests", &c.downstream_requests}, {"downstream_bytes", &c.downstream_bytes}});
  stats_.add("reordered", &c.reordered);
  stats_.add("energy_nj", &c.energy_nj);
  tr_accesses_ = trace_.add_rate("accesses_per_cycle");
  tr_misses_ = trace_.add_rate("misses_per_cycle");
  tr_conflicts_ = trace_.add_rate("bank_conflicts_per_cycle");
}

void L1DataCache::trace(sc_core::sc_trace_file* file, const TraceWindow& window) { trace_.open(file, name(), window); }

void L1DataCache::b_transport(tlm::tlm_generic_payload& gp, sc_core::sc_time& delay) {
  MemoryExtension* ext = gp.get_extension<MemoryExtension>();
  const AccessClass access = transport::access_class_of(gp, ext);
  const uint64_t addr = gp.get_address();
  const uint32_t bytes = gp.get_data_length();
  if (access != AccessClass::kDataLoad && access != AccessClass::kDataStore) {
    gp.set_response_status(tlm::TLM_COMMAND_ERROR_RESPONSE);
    return;
  }
  if (core_.crosses_line(addr, bytes)) {
    gp.set_response_status(tlm::TLM_BURST_ERROR_RESPONSE);
    return;
  }
  const bool store = access == AccessClass::kDataStore;
  // Data path: the one backing store, in arrival order. Caches hold no data to go stale.
  if (ext == nullptr || !ext->timing_only) {
    if (store) backing_.write(addr, gp.get_data_ptr(), bytes);
    else backing_.read(addr, gp.get_data_ptr(), bytes);
  }

  const Cycle now = clock_.now();
  const Cycle t = clock_.request_cycle(delay);
  const uint64_t line = core_.line_of(addr);
  const uint32_t set = core_.set_of(line);
  const uint32_t bank = core_.bank_of(line);
  const Cycle slot = core_.book_bank(bank, t, now);
  const Cycle answer = slot + config_.hit_latency_cycles;
  Counters& c = transport::counts(ext) ? counters_ : uncounted_;  // sampled: warm-up and fast-forward
  ++c.accesses;
  c.energy_nj += config_.access_energy_nj;
  if (slot > t) {
    ++c.bank_conflicts;
    c.conflict_cycles += slot - t;
  }

  Cycle done = answer;
  ServedBy served = ServedBy::kL1;
  bool ok = true;
  if (store) {
    ++c.stores;
    c.bytes_written += bytes;
    // Write-around: the store goes on to the next level; the TP does not wait for it.
    const DownstreamResult r = below_.send(tlm::TLM_WRITE_COMMAND, addr, bytes, answer, ext);
    ok = r.ok;
  } else {
    ++c.loads;
    c.bytes_read += bytes;
    const CacheCore::Lookup look = core_.classify(set, line, slot, answer);
    switch (look.outcome) {
      case CacheCore::Outcome::kShadowHit:
        ++c.reordered;
        [[fallthrough]];
      case CacheCore::Outcome::kHit:
        ++c.hits;
        break;
      case CacheCore::Outcome::kTimeShifted:
        ++c.reordered;
        [[fallthrough]];
      case CacheCore::Outcome::kMerged:
        ++c.merged_misses;  // the line is on its way: wait for that fill
        done = look.done;
        served = ServedBy::kL1Merged;
        break;
      case CacheCore::Outcome::kMiss: {
        ++c.misses;
        const DownstreamResult r =
            below_.send(tlm::TLM_READ_COMMAND, core_.line_base(line), config_.line_bytes, answer, ext);
        ok = r.ok;
        done = r.done;
        served = r.served_by;
        core_.install(set, 0, line, slot, done, false);
        core_.book_bank(bank, done, now);  // writing the fill takes the bank for a cycle
        ++c.fills;
        c.energy_nj += config_.access_energy_nj;
        break;
      }
    }
  }
  c.downstream_requests = below_.requests();
  c.downstream_bytes = below_.bytes();

  if (trace_.enabled()) {
    trace_.count(tr_accesses_, 1, now);
    trace_.count(tr_misses_, (!store && served != ServedBy::kL1) ? 1 : 0, now);
    trace_.count(tr_conflicts_, slot > t ? 1 : 0, now);
  }
  if (ext != nullptr) ext->served_by = served;
  gp.set_response_status(ok ? tlm::TLM_OK_RESPONSE : tlm::TLM_GENERIC_ERROR_RESPONSE);
  delay = clock_.delay_until(done);
}

}  // namespace strata::memory
