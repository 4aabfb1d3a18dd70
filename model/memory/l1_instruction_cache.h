// A TM's L1 instruction cache: 4 KB, banked by line, direct-mapped, read-only. With
// model_misses off every fetch hits (the firmware fits, as TRaX assumed) and the level below
// is never asked; with it on, misses fetch the line through the downstream socket.
// Time as in the L1 data cache: bank slot at or after the request cycle, plus hit latency.
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

class L1InstructionCache : public sc_core::sc_module {
 public:
  tlm_utils::simple_target_socket<L1InstructionCache> target{"target"};
  // Must be bound even when misses are not modelled (bind it to the L2 side or a sink).
  tlm_utils::simple_initiator_socket<L1InstructionCache> downstream{"downstream"};

  using Counters = CacheCounters;

  L1InstructionCache(sc_core::sc_module_name name, const L1InstructionCacheConfig& config, SparseMemory& backing);

  // The chip's clock (default 1 GHz). Before sc_start: every module of a chip must count in
  // the same cycles as the TMs, or each latency in cycles stretches by the ratio of the clocks.
  void set_clock(const transport::Clock& clock) { path_.set_clock(clock); }
  const Counters& counters() const { return path_.counters(); }
  const stats::Group& stats() const { return stats_; }
  using sc_core::sc_object::trace;  // ours adds a window; the base's stays visible
  void trace(sc_core::sc_trace_file* file, const TraceWindow& window);

 private:
  void b_transport(tlm::tlm_generic_payload& gp, sc_core::sc_time& delay);

  L1InstructionCacheConfig config_;
  CachePath path_;
  stats::Group stats_;
};

}  // namespace strata::memory
