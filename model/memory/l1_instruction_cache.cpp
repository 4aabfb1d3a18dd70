#include "model/memory/l1_instruction_cache.h"

namespace strata::memory {

using transport::AccessClass;
using transport::ServedBy;

L1InstructionCache::L1InstructionCache(sc_core::sc_module_name name, const L1InstructionCacheConfig& config,
                                       SparseMemory& backing)
    : sc_core::sc_module(name),
      config_((config.validate(), config)),
      path_(CacheGeometry{config.size_bytes, config.banks, config.line_bytes, 1, config.calendar_horizon_cycles},
            config.hit_latency_cycles, config.access_energy_nj, backing, downstream, "fetches_per_cycle"),
      stats_("l1i",
             "The TMs' L1 instruction caches (direct-mapped, banked). A TP asks only when its fetch moves to "
             "another line.",
             stats::Basis::kMeasuredInstructions) {
  target.register_b_transport(this, &L1InstructionCache::b_transport);
  path_.register_stats(stats_, "the L2 side", false, false, "downstream_requests", "downstream_bytes");
}

void L1InstructionCache::trace(sc_core::sc_trace_file* file, const TraceWindow& window) {
  path_.trace().open(file, name(), window);
}

void L1InstructionCache::b_transport(tlm::tlm_generic_payload& gp, sc_core::sc_time& delay) {
  auto* ext = gp.get_extension<transport::MemoryExtension>();
  const AccessClass access = transport::access_class_of(gp, ext);
  CachePath::Request r;
  const bool accepted =
      !gp.is_write() && (access == AccessClass::kInstructionFetch || access == AccessClass::kDataLoad);
  if (!path_.begin(gp, ext, delay, accepted, r)) return;
  const CachePath::Result res = path_.read_allocate(r, config_.model_misses, ServedBy::kL1, ServedBy::kL1Merged);
  path_.finish(gp, delay, r, res);
}

}  // namespace strata::memory
