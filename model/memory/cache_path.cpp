#include "model/memory/cache_path.h"

namespace strata::memory {

using stats::Unit;
using transport::AccessClass;
using transport::ServedBy;

CachePath::CachePath(const CacheGeometry& geometry, uint32_t hit_latency_cycles, double access_energy_nj,
                     SparseMemory& backing, tlm::tlm_initiator_socket<>& downstream, const char* accesses_trace)
    : core_(geometry),
      hit_latency_(hit_latency_cycles),
      energy_(access_energy_nj),
      backing_(backing),
      below_(downstream, geometry.line_bytes) {
  tr_accesses_ = trace_.add_rate(accesses_trace);
  tr_misses_ = trace_.add_rate("misses_per_cycle");
  tr_conflicts_ = trace_.add_rate("bank_conflicts_per_cycle");
}

bool CachePath::begin(tlm::tlm_generic_payload& gp, sc_core::sc_time& delay, bool accepted, Request& r) {
  r.ext = gp.get_extension<transport::MemoryExtension>();
  r.addr = gp.get_address();
  r.bytes = gp.get_data_length();
  if (!accepted) {
    gp.set_response_status(tlm::TLM_COMMAND_ERROR_RESPONSE);
    return false;
  }
  if (core_.crosses_line(r.addr, r.bytes)) {
    gp.set_response_status(tlm::TLM_BURST_ERROR_RESPONSE);
    return false;
  }
  r.store = gp.is_write();
  r.data = transport::data_class_of(r.ext);
  // Data path: the one backing store, in arrival order.
  if (r.ext == nullptr || !r.ext->timing_only) {
    if (r.store) backing_.write(r.addr, gp.get_data_ptr(), r.bytes);
    else backing_.read(r.addr, gp.get_data_ptr(), r.bytes);
  }

  r.now = clock_.now();
  r.t = clock_.request_cycle(delay);
  r.line = core_.line_of(r.addr);
  r.set = core_.set_of(r.line);
  r.bank = core_.bank_of(r.line);
  r.slot = core_.book_bank(r.bank, r.t, r.now);
  r.answer = r.slot + hit_latency_;
  CacheCounters& c = counters_.of(r.ext);  // sampled timing: warm-up and fast-forward go apart
  r.c = &c;
  ++c.accesses;
  c.energy_nj += energy_;
  if (r.slot > r.t) {
    ++c.bank_conflicts;
    c.conflict_cycles += r.slot - r.t;
  }
  if (r.store) {
    ++c.stores;
    c.bytes_written += r.bytes;
  } else {
    ++c.loads;
    c.bytes_read += r.bytes;
  }
  ClassTraffic& k = traffic(c.by_data, r.data);
  ++k.accesses;
  k.bytes += r.bytes;
  return true;
}

void CachePath::count_read_outcome(const Request& r, CacheCore::Outcome o) {
  CacheCounters& c = *r.c;
  switch (o) {
    case CacheCore::Outcome::kShadowHit: ++c.reordered; [[fallthrough]];
    case CacheCore::Outcome::kHit: ++c.hits; break;
    case CacheCore::Outcome::kTimeShifted: ++c.reordered; [[fallthrough]];
    case CacheCore::Outcome::kMerged: ++c.merged_misses; break;
    case CacheCore::Outcome::kMiss:
      ++c.misses;
      ++traffic(c.by_data, r.data).misses;
      break;
  }
}

CachePath::Result CachePath::read_allocate(Request& r, bool model_misses, ServedBy hit_level, ServedBy merged_level) {
  Result res{r.answer, hit_level, true, false};
  const CacheCore::Lookup look = model_misses ? core_.classify(r.set, r.line, r.slot, r.answer)
                                              : CacheCore::Lookup{CacheCore::Outcome::kHit, 0, r.answer};
  count_read_outcome(r, look.outcome);
  switch (look.outcome) {
    case CacheCore::Outcome::kShadowHit:
    case CacheCore::Outcome::kHit: break;
    case CacheCore::Outcome::kTimeShifted:
    case CacheCore::Outcome::kMerged:  // the line is on its way: wait for that fill
      res.done = look.done;
      res.served = merged_level;
      break;
    case CacheCore::Outcome::kMiss: {
      const DownstreamResult d =
          below_.send(tlm::TLM_READ_COMMAND, core_.line_base(r.line), core_.line_bytes(), r.answer, r.ext, r.data);
      res.ok = d.ok;
      res.done = d.done;
      res.served = d.served_by;
      res.missed = true;
      core_.install(r.set, 0, r.line, r.slot, d.done, false, r.data);
      core_.book_bank(r.bank, d.done, r.now);  // writing the fill takes the bank for a cycle
      ++r.c->fills;
      r.c->energy_nj += energy_;
      break;
    }
  }
  return res;
}

void CachePath::finish(tlm::tlm_generic_payload& gp, sc_core::sc_time& delay, const Request& r, const Result& res) {
  counters_.counted.downstream_requests = below_.requests();
  counters_.counted.downstream_bytes = below_.bytes();
  if (trace_.enabled()) {
    trace_.count(tr_accesses_, 1, r.now);
    trace_.count(tr_misses_, res.missed ? 1 : 0, r.now);
    trace_.count(tr_conflicts_, r.slot > r.t ? 1 : 0, r.now);
  }
  if (r.ext != nullptr) r.ext->served_by = res.served;
  gp.set_response_status(res.ok ? tlm::TLM_OK_RESPONSE : tlm::TLM_GENERIC_ERROR_RESPONSE);
  delay = clock_.delay_until(res.done);
}

void CachePath::register_stats(stats::Group& g, const char* below, bool stores, bool writebacks,
                               const char* requests_name, const char* bytes_name) {
  const CacheCounters& c = counters_.counted;
  g.count("accesses", &c.accesses, Unit::kCount, stores ? "Lookups: loads and stores." : "Lookups.");
  if (stores) {
    g.count("loads", &c.loads, Unit::kCount, "Read lookups.");
    g.count("stores", &c.stores, Unit::kCount, "Write lookups.");
  }
  g.count("hits", &c.hits, Unit::kCount, "Lookups that found their line present and filled (an L1 store neither hits nor misses).");
  g.count("misses", &c.misses, Unit::kCount, "Lookups that missed and asked the level below for the line.");
  g.count("merged_misses", &c.merged_misses, Unit::kCount,
          "Lookups that found their line already on its way and waited for that fill (no new request).");
  g.ratio("hit_rate", "hits", {"hits", "misses"}, "hits / (hits + misses); merged misses are in neither.");
  g.count("bank_conflicts", &c.bank_conflicts, Unit::kCount, "Lookups that found their bank busy and waited.");
  g.count("conflict_cycles", &c.conflict_cycles, Unit::kCycles, "Cycles lookups waited for their bank.");
  g.count("fills", &c.fills, Unit::kCount, "Lines written into the cache from the level below.");
  if (writebacks) g.count("writebacks", &c.writebacks, Unit::kCount, "Dirty lines written back on eviction.");
  g.count("bytes_read", &c.bytes_read, Unit::kBytes, "Bytes the reads asked for.");
  if (stores) g.count("bytes_written", &c.bytes_written, Unit::kBytes, "Bytes the stores carried.");
  const std::string req = std::string("Requests sent to ") + below + " (fills, write-throughs, write-backs).";
  g.count(requests_name, &c.downstream_requests, Unit::kCount, req.c_str());
  g.count(bytes_name, &c.downstream_bytes, Unit::kBytes, "Bytes of those requests.");
  g.count("reordered", &c.reordered, Unit::kCount,
          "Fidelity: lookups that arrived out of time order (loosely timed) and were answered as the precise "
          "order would (a shadow hit or a time-shifted miss). Always 0 in precise mode.",
          stats::Basis::kExact);
  g.level("calendar_overflow_bookings", [this] { return core_.overflow_bookings(); }, Unit::kCount,
          "Fidelity: bank bookings beyond the calendar horizon, served late in arrival order. Nonzero means "
          "calendar_horizon_cycles is too small for the quantum and latencies; must be 0.");
  g.count("energy_nj", &c.energy_nj, Unit::kNanojoules, "Energy of the lookups and fills.");
  by_data_stats_ = std::make_unique<DataTrafficStats>(c.by_data, true, "Lookups of data of this class.",
                                                      "Bytes the lookups of this class asked for or carried.");
  g.child(&by_data_stats_->group());
}

}  // namespace strata::memory
