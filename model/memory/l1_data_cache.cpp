#include "model/memory/l1_data_cache.h"

namespace strata::memory {

using transport::AccessClass;
using transport::ServedBy;

L1DataCache::L1DataCache(sc_core::sc_module_name name, const L1DataCacheConfig& config, SparseMemory& backing)
    : sc_core::sc_module(name),
      config_((config.validate(), config)),
      path_(CacheGeometry{config.size_bytes, config.banks, config.line_bytes, 1, config.calendar_horizon_cycles},
            config.hit_latency_cycles, config.access_energy_nj, backing, downstream, "accesses_per_cycle"),
      stats_("l1d", "The TMs' L1 data caches (direct-mapped, banked, write-around).", stats::Basis::kDataOps) {
  target.register_b_transport(this, &L1DataCache::b_transport);
  path_.register_stats(stats_, "the L2 side", true, false, "downstream_requests", "downstream_bytes");
}

void L1DataCache::trace(sc_core::sc_trace_file* file, const TraceWindow& window) {
  path_.trace().open(file, name(), window);
}

void L1DataCache::b_transport(tlm::tlm_generic_payload& gp, sc_core::sc_time& delay) {
  auto* ext = gp.get_extension<transport::MemoryExtension>();
  const AccessClass access = transport::access_class_of(gp, ext);
  if (transport::is_warming(ext)) return path_.warm_read_allocate(gp, ext);
  CachePath::Request r;
  if (!path_.begin(gp, ext, delay, access == AccessClass::kDataLoad || access == AccessClass::kDataStore, r)) return;
  CachePath::Result res{r.answer, ServedBy::kL1, true, false};
  if (r.store) {
    // Write-around: the store goes on to the next level; the TP does not wait for it.
    res.ok = path_.below().send(tlm::TLM_WRITE_COMMAND, r.addr, r.bytes, r.answer, r.ext, r.data).ok;
  } else {
    res = path_.read_allocate(r, true, ServedBy::kL1, ServedBy::kL1Merged);
  }
  path_.finish(gp, delay, r, res);
}

}  // namespace strata::memory
