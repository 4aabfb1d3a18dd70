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

void CachePath::warm_read_allocate(tlm::tlm_generic_payload& gp, const transport::MemoryExtension* ext) {
  gp.set_response_status(tlm::TLM_OK_RESPONSE);
  const uint64_t line = core_.line_of(gp.get_address());
  const transport::DataClass data = transport::data_class_of(ext);
  if (gp.is_write()) {  // write-around: the store changes the level below only
    below_.warm(tlm::TLM_WRITE_COMMAND, gp.get_address(), ext, data);
  } else if (!core_.warm(core_.set_of(line), line, false, true, data)) {
    below_.warm(tlm::TLM_READ_COMMAND, core_.line_base(line), ext, data);
  }
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
  g.count_probe(requests_name, [this] { return below_.requests(); }, Unit::kCount, req.c_str());
  g.count_probe(bytes_name, [this] { return below_.bytes(); }, Unit::kBytes, "Bytes of those requests.");
  g.count("reordered", &c.reordered, Unit::kCount,
          "Fidelity: lookups that arrived out of time order and were answered as time order would (a shadow "
          "hit or a time-shifted miss). Loosely timed makes them by design; in precise mode only lookups the "
          "level above sends ahead of global time.");
  g.level("calendar_overflow_bookings", [this] { return core_.overflow_bookings(); }, Unit::kCount,
          "Fidelity: bank bookings beyond the calendar horizon, served late in arrival order. Nonzero means "
          "calendar_horizon_cycles is too small for the quantum and latencies; must be 0.");
  g.count("energy_nj", &c.energy_nj, Unit::kNanojoules, "Energy of the lookups and fills.");
  by_data_stats_ = std::make_unique<DataTrafficStats>(c.by_data, true, "Lookups of data of this class.",
                                                      "Bytes the lookups of this class asked for or carried.");
  g.child(&by_data_stats_->group());
}

}  // namespace strata::memory
