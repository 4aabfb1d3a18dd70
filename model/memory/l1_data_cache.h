// A TM's L1 data cache: direct-mapped, N banks interleaved by line, one access per bank per
// cycle (a second access to a busy bank waits a cycle: a bank conflict). Write-around: a store
// goes through to the next level and never allocates (docs/memory-system.md says why).
// Misses to a line already on its way are merged with that fill.
//
// Time: the request's absolute cycle t (global time + annotated delay) books the bank at the
// first free cycle s >= t; a hit completes at s + hit_latency; a miss asks the level below at
// s + hit_latency and completes when the line arrives, and the fill then takes a bank cycle.
// The same code serves both timing modes; only the arrival order of requests differs.
#pragma once

#include "model/memory/cache_path.h"
#include "model/memory/config.h"
#include "model/memory/sparse_memory.h"
#include "model/memory/window_trace.h"
#include "model/stats/stat_group.h"

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>

namespace strata::memory {

class L1DataCache : public sc_core::sc_module {
 public:
  tlm_utils::simple_target_socket<L1DataCache> target{"target"};              // from the TPs
  tlm_utils::simple_initiator_socket<L1DataCache> downstream{"downstream"};  // to the L2 side

  using Counters = CacheCounters;

  L1DataCache(sc_core::sc_module_name name, const L1DataCacheConfig& config, SparseMemory& backing);

  // The chip's clock (default 1 GHz). Before sc_start: every module of a chip must count in
  // the same cycles as the TMs, or each latency in cycles stretches by the ratio of the clocks.
  void set_clock(const transport::Clock& clock) { path_.set_clock(clock); }
  const Counters& counters() const { return path_.counters(); }
  const stats::Group& stats() const { return stats_; }
  const CacheCore& core() const { return path_.core(); }
  // VCD: accesses, misses and bank conflicts per cycle over each window. Before sc_start.
  using sc_core::sc_object::trace;  // ours adds a window; the base's stays visible
  void trace(sc_core::sc_trace_file* file, const TraceWindow& window);

 private:
  void b_transport(tlm::tlm_generic_payload& gp, sc_core::sc_time& delay);

  L1DataCacheConfig config_;
  CachePath path_;
  stats::Group stats_;
};

}  // namespace strata::memory
