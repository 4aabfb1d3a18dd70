#include "model/memory/l2_cache.h"

namespace strata::memory {

using transport::AccessClass;
using transport::Cycle;
using transport::MemoryExtension;
using transport::ServedBy;

L2Cache::L2Cache(sc_core::sc_module_name name, const L2Config& config, SparseMemory& backing)
    : sc_core::sc_module(name),
      config_((config.validate(), config)),
      energy_per_access_(config.energy_per_access_nj()),
      backing_(backing),
      core_(CacheGeometry{config.size_bytes, config.banks, config.line_bytes, config.ways,
                          config.calendar_horizon_cycles}),
      below_(downstream, config.line_bytes),
      stats_(basename()) {
  target.register_b_transport(this, &L2Cache::b_transport);
  Counters& c = counters_;
  stats_.add({{"accesses", &c.accesses}, {"loads", &c.loads}, {"stores", &c.stores}, {"hits", &c.hits},
              {"misses", &c.misses}, {"merged_misses", &c.merged_misses}, {"bank_conflicts", &c.bank_conflicts},
              {"conflict_cycles", &c.conflict_cycles}, {"fills", &c.fills}, {"writebacks", &c.writebacks},
              {"bytes_read", &c.bytes_read}, {"bytes_written", &c.bytes_written},
              {"dram_requests", &c.dram_requests}, {"dram_bytes", &c.dram_bytes}});
  stats_.add("reordered", &c.reordered);
  stats_.add("energy_nj", &c.energy_nj);
  tr_accesses_ = trace_.add_rate("accesses_per_cycle");
  tr_misses_ = trace_.add_rate("misses_per_cycle");
  tr_conflicts_ = trace_.add_rate("bank_conflicts_per_cycle");
}

void L2Cache::trace(sc_core::sc_trace_file* file, const TraceWindow& window) { trace_.open(file, name(), window); }

void L2Cache::b_transport(tlm::tlm_generic_payload& gp, sc_core::sc_time& delay) {
  MemoryExtension* ext = gp.get_extension<MemoryExtension>();
  const AccessClass access = transport::access_class_of(gp, ext);
  const uint64_t addr = gp.get_address();
  const uint32_t bytes = gp.get_data_length();
  if (transport::is_stream_access(access) || gp.get_command() == tlm::TLM_IGNORE_COMMAND) {
    gp.set_response_status(tlm::TLM_COMMAND_ERROR_RESPONSE);
    return;
  }
  if (core_.crosses_line(addr, bytes)) {
    gp.set_response_status(tlm::TLM_BURST_ERROR_RESPONSE);
    return;
  }
  const bool store = gp.is_write();
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
  c.energy_nj += energy_per_access_;
  if (slot > t) {
    ++c.bank_conflicts;
    c.conflict_cycles += slot - t;
  }
  if (store) {
    ++c.stores;
    c.bytes_written += bytes;
  } else {
    ++c.loads;
    c.bytes_read += bytes;
  }

  Cycle done = answer;
  ServedBy served = ServedBy::kL2;
  bool ok = true;
  const CacheCore::Lookup look = core_.classify(set, line, slot, answer);
  const bool missed = look.outcome == CacheCore::Outcome::kMiss ||
                      (look.outcome == CacheCore::Outcome::kShadowHit && store);  // the line is gone
  if (!missed) {
    if (look.way != CacheCore::kMiss) {
      const auto way = static_cast<uint32_t>(look.way);
      core_.touch(set, way);
      if (store) core_.set_dirty(set, way);
    }
    if (look.outcome == CacheCore::Outcome::kShadowHit || look.outcome == CacheCore::Outcome::kTimeShifted)
      ++c.reordered;
    if (look.outcome == CacheCore::Outcome::kHit || look.outcome == CacheCore::Outcome::kShadowHit) {
      ++c.hits;
    } else {
      ++c.merged_misses;
      done = look.done;
      served = ServedBy::kL2Merged;
    }
  } else {
    ++c.misses;
    const uint32_t way = core_.victim(set);
    if (core_.valid(set, way) && core_.dirty(set, way)) {
      ++c.writebacks;  // posted: the requester does not wait for it, DRAM still books it
      ok = below_.send(tlm::TLM_WRITE_COMMAND, core_.line_base(core_.line_at(set, way)), config_.line_bytes,
                       answer, ext).ok;
    }
    if (store && bytes == config_.line_bytes) {
      core_.install(set, way, line, slot, answer, true);  // whole line written: nothing to fetch
    } else {
      const DownstreamResult r = below_.send(tlm::TLM_READ_COMMAND, core_.line_base(line), config_.line_bytes, answer, ext);
      ok = ok && r.ok;
      done = r.done;
      served = r.served_by;
      core_.install(set, way, line, slot, done, store);
      core_.book_bank(bank, done, now);
      ++c.fills;
      c.energy_nj += energy_per_access_;
    }
  }
  c.dram_requests = below_.requests();
  c.dram_bytes = below_.bytes();

  if (trace_.enabled()) {
    trace_.count(tr_accesses_, 1, now);
    trace_.count(tr_misses_, missed ? 1 : 0, now);
    trace_.count(tr_conflicts_, slot > t ? 1 : 0, now);
  }
  if (ext != nullptr) ext->served_by = served;
  gp.set_response_status(ok ? tlm::TLM_OK_RESPONSE : tlm::TLM_GENERIC_ERROR_RESPONSE);
  delay = clock_.delay_until(done);
}

}  // namespace strata::memory
