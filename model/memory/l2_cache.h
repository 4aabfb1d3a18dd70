// The L2 shared by all TMs: banked by line (one access per bank per cycle), direct-mapped or
// set-associative with LRU (`ways`). Write-back with write-allocate: stores from the L1s'
// write-around traffic are absorbed here and reach DRAM only when a dirty line is evicted; a
// store that covers a whole line allocates it without fetching. Misses in flight are merged.
//
// Time: bank slot s >= request cycle; a hit completes at s + hit_latency; a miss asks DRAM at
// s + hit_latency (after writing back a dirty victim, posted) and completes with the fill,
// which then takes the bank for a cycle. Same code in both timing modes.
#pragma once

#include "model/memory/cache_core.h"
#include "model/memory/config.h"
#include "model/memory/downstream_port.h"
#include "model/memory/sparse_memory.h"
#include "model/memory/stats.h"
#include "model/memory/window_trace.h"
#include "tlm/clock.h"

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>

namespace strata::memory {

class L2Cache : public sc_core::sc_module {
 public:
  tlm_utils::simple_target_socket<L2Cache> target{"target"};        // from the interconnect
  tlm_utils::simple_initiator_socket<L2Cache> downstream{"downstream"};  // to DRAM

  struct Counters {
    uint64_t accesses = 0, loads = 0, stores = 0;
    uint64_t hits = 0, misses = 0, merged_misses = 0;
    uint64_t bank_conflicts = 0, conflict_cycles = 0;
    uint64_t fills = 0, writebacks = 0, bytes_read = 0, bytes_written = 0;
    uint64_t dram_requests = 0, dram_bytes = 0;
    uint64_t reordered = 0;  // LT only: answered as in precise order (see CacheCore)
    double energy_nj = 0.0;
  };

  L2Cache(sc_core::sc_module_name name, const L2Config& config, SparseMemory& backing);

  const Counters& counters() const { return counters_; }
  const StatGroup& stats() const { return stats_; }
  const CacheCore& core() const { return core_; }
  double energy_per_access_nj() const { return energy_per_access_; }
  void trace(sc_core::sc_trace_file* file, const TraceWindow& window);

 private:
  void b_transport(tlm::tlm_generic_payload& gp, sc_core::sc_time& delay);

  L2Config config_;
  double energy_per_access_;
  SparseMemory& backing_;
  transport::Clock clock_;
  CacheCore core_;
  DownstreamPort below_;
  Counters counters_;
  Counters uncounted_;  // where accesses the statistics leave out (sampled timing) are counted
  StatGroup stats_;
  WindowTrace trace_;
  std::size_t tr_accesses_, tr_misses_, tr_conflicts_;
};

}  // namespace strata::memory
