#include "model/memory/l2_cache.h"

#include <string>

namespace strata::memory {

using stats::Unit;
using transport::AccessClass;
using transport::ServedBy;

L2Cache::L2Cache(sc_core::sc_module_name name, const L2Config& config, SparseMemory& backing)
    : sc_core::sc_module(name),
      config_((config.validate(), config)),
      path_(CacheGeometry{config.size_bytes, config.banks, config.line_bytes, config.ways,
                          config.calendar_horizon_cycles, config.hash_banks},
            config.hit_latency_cycles, config.energy_per_access_nj(), backing, downstream, "accesses_per_cycle"),
      banks_(config.banks),
      stats_("l2", "The shared L2 (banked, write-back, write-allocate): the L1s' misses and write-arounds.",
             stats::Basis::kDataOps) {
  target.register_b_transport(this, &L2Cache::b_transport);
  path_.register_stats(stats_, "DRAM", true, true, "dram_requests", "dram_bytes");
  std::vector<const stats::Group*> each;
  for (uint32_t b = 0; b < config_.banks; ++b) {
    auto g = std::make_unique<stats::Group>("bank" + std::to_string(b), "The L2's banks.");
    g->count("accesses", &banks_[b].accesses, Unit::kCount, "Lookups this bank served.");
    g->count("misses", &banks_[b].misses, Unit::kCount, "Of those, misses to DRAM.");
    g->count("conflict_cycles", &banks_[b].conflict_cycles, Unit::kCycles, "Cycles lookups waited for this bank.");
    each.push_back(g.get());
    bank_stats_.push_back(std::move(g));
  }
  stats_.instances("banks", each, "l2-bank", "L2 bank", false);
}

void L2Cache::trace(sc_core::sc_trace_file* file, const TraceWindow& window) { path_.trace().open(file, name(), window); }

void L2Cache::b_transport(tlm::tlm_generic_payload& gp, sc_core::sc_time& delay) {
  auto* ext = gp.get_extension<transport::MemoryExtension>();
  const AccessClass access = transport::access_class_of(gp, ext);
  if (transport::is_warming(ext)) {  // write-back, write-allocate: both allocate; DRAM keeps no tags
    const uint64_t line = path_.core().line_of(gp.get_address());
    path_.core().warm(path_.core().set_of(line), line, gp.is_write(), true, transport::data_class_of(ext));
    gp.set_response_status(tlm::TLM_OK_RESPONSE);
    return;
  }
  CachePath::Request r;
  if (!path_.begin(gp, ext, delay, !transport::is_stream_access(access) && gp.get_command() != tlm::TLM_IGNORE_COMMAND, r))
    return;
  CacheCore& core = path_.core();
  CacheCounters& c = *r.c;
  CachePath::Result res{r.answer, ServedBy::kL2, true, false};
  const CacheCore::Lookup look = core.classify(r.set, r.line, r.slot, r.answer);
  // A store whose line was evicted by a later access (a shadow hit) finds the line gone.
  res.missed = look.outcome == CacheCore::Outcome::kMiss ||
               (look.outcome == CacheCore::Outcome::kShadowHit && r.store);
  if (!res.missed) {
    if (look.way != CacheCore::kMiss) {
      const auto way = static_cast<uint32_t>(look.way);
      core.touch(r.set, way);
      if (r.store) core.set_dirty(r.set, way);
    }
    path_.count_read_outcome(r, look.outcome);
    if (look.outcome == CacheCore::Outcome::kMerged || look.outcome == CacheCore::Outcome::kTimeShifted) {
      res.done = look.done;
      res.served = ServedBy::kL2Merged;
    }
  } else {
    path_.count_read_outcome(r, CacheCore::Outcome::kMiss);
    const uint32_t way = core.victim(r.set);
    if (core.valid(r.set, way) && core.dirty(r.set, way)) {
      ++c.writebacks;  // posted: the requester does not wait for it, DRAM still books it
      res.ok = path_.below()
                   .send(tlm::TLM_WRITE_COMMAND, core.line_base(core.line_at(r.set, way)), core.line_bytes(),
                         r.answer, r.ext, core.data_class(r.set, way))
                   .ok;
    }
    if (r.store && r.bytes == core.line_bytes()) {
      core.install(r.set, way, r.line, r.slot, r.answer, true, r.data);  // whole line written: nothing to fetch
    } else {
      const DownstreamResult d =
          path_.below().send(tlm::TLM_READ_COMMAND, core.line_base(r.line), core.line_bytes(), r.answer, r.ext, r.data);
      res.ok = res.ok && d.ok;
      res.done = d.done;
      res.served = d.served_by;
      core.install(r.set, way, r.line, r.slot, d.done, r.store, r.data);
      core.book_bank(r.bank, d.done, r.now);
      ++c.fills;
      c.energy_nj += path_.access_energy_nj();
    }
  }
  if (transport::counts(r.ext)) {
    BankCounters& b = banks_[r.bank];
    ++b.accesses;
    b.misses += res.missed ? 1 : 0;
    b.conflict_cycles += r.slot - r.t;
  }
  path_.finish(gp, delay, r, res);
}

}  // namespace strata::memory
