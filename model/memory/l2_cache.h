// The L2 shared by all TMs: banked by line (one access per bank per cycle), direct-mapped or
// set-associative with LRU (`ways`). Write-back with write-allocate: stores from the L1s'
// write-around traffic are absorbed here and reach DRAM only when a dirty line is evicted; a
// store that covers a whole line allocates it without fetching. Misses in flight are merged.
//
// Time: bank slot s >= request cycle; a hit completes at s + hit_latency; a miss asks DRAM at
// s + hit_latency (after writing back a dirty victim, posted) and completes with the fill,
// which then takes the bank for a cycle. Same code in both timing modes.
#pragma once

#include "model/memory/cache_path.h"
#include "model/memory/config.h"
#include "model/memory/memory_levels.h"
#include "model/memory/sparse_memory.h"
#include "model/memory/window_trace.h"
#include "model/stats/stat_group.h"

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>

#include <memory>
#include <vector>

namespace strata::memory {

class L2Cache : public sc_core::sc_module, public L2Level {
 public:
  tlm_utils::simple_target_socket<L2Cache> target{"target"};        // from the interconnect
  tlm_utils::simple_initiator_socket<L2Cache> downstream{"downstream"};  // to DRAM
  tlm::tlm_target_socket<>& target_socket() override { return target; }
  tlm::tlm_initiator_socket<>& downstream_socket() override { return downstream; }

  using Counters = CacheCounters;
  struct BankCounters {
    uint64_t accesses = 0, misses = 0, conflict_cycles = 0;
  };

  L2Cache(sc_core::sc_module_name name, const L2Config& config, SparseMemory& backing);

  // The chip's clock (default 1 GHz). Before sc_start: every module of a chip must count in
  // the same cycles as the TMs, or each latency in cycles stretches by the ratio of the clocks.
  void set_clock(const transport::Clock& clock) override { path_.set_clock(clock); }
  const Counters& counters() const { return path_.counters(); }
  const BankCounters& bank(uint32_t b) const { return banks_[b]; }
  const stats::Group& stats() const override { return stats_; }
  const CacheCore& core() const { return path_.core(); }
  double energy_per_access_nj() const { return path_.access_energy_nj(); }
  using sc_core::sc_object::trace;  // ours adds a window; the base's stays visible
  void trace(sc_core::sc_trace_file* file, const TraceWindow& window) override;

 private:
  void b_transport(tlm::tlm_generic_payload& gp, sc_core::sc_time& delay);

  L2Config config_;
  CachePath path_;
  std::vector<BankCounters> banks_;  // counted accesses only; never resized (the stats point into it)
  stats::Group stats_;
  std::vector<std::unique_ptr<stats::Group>> bank_stats_;
};

}  // namespace strata::memory
