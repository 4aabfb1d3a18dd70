// The crossbar between the TMs and the shared on-chip memories: every TM has a port (one
// request per cycle), every L2 bank and the stream memory have a link of link_bytes_per_cycle.
// A request crosses a hop, waits for its TM port and, carrying data, for its destination link
// (a store's data on the way in, a load's data on the way back), then crosses a hop back.
// Stream-memory operations go to the stream socket, everything else to the L2 socket; the L2
// bank is the one the L2 itself would pick (line-interleaved), so bank hot spots show here.
// All links are reservation calendars: contention is right in both timing modes.
#pragma once

#include "model/memory/bank_interleave.h"
#include "model/memory/config.h"
#include "model/memory/data_traffic.h"
#include "model/stats/stat_group.h"
#include "model/memory/window_trace.h"
#include "tlm/clock.h"
#include "tlm/memory_extension.h"
#include "tlm/reservation_calendar.h"

#include <systemc>
#include <tlm>
#include <tlm_utils/multi_passthrough_target_socket.h>
#include <tlm_utils/simple_initiator_socket.h>

#include <memory>
#include <vector>

namespace strata::memory {

class Interconnect : public sc_core::sc_module {
 public:
  // Bind each TM's initiator (its L1 data cache, I-cache, stream unit) here; the binding order
  // is the port index, and ports beyond tm_ports are an error.
  tlm_utils::multi_passthrough_target_socket<Interconnect> tm_side{"tm_side"};
  tlm_utils::simple_initiator_socket<Interconnect> l2_side{"l2_side"};
  tlm_utils::simple_initiator_socket<Interconnect> stream_side{"stream_side"};

  struct Counters {
    uint64_t transfers = 0, bytes = 0;
    uint64_t l2_transfers = 0, stream_transfers = 0;
    uint64_t port_conflicts = 0, link_conflicts = 0, conflict_cycles = 0;
    double energy_nj = 0.0;
    DataTraffic by_data{};
  };

  Interconnect(sc_core::sc_module_name name, const InterconnectConfig& config);

  uint32_t bank_of(uint64_t addr) const { return interleave_.bank(addr >> line_shift_); }
  // The chip's clock (default 1 GHz). Before sc_start: every module of a chip must count in
  // the same cycles as the TMs, or each latency in cycles stretches by the ratio of the clocks.
  void set_clock(const transport::Clock& clock) { clock_ = clock; }
  const Counters& counters() const { return counters_.counted; }
  const stats::Group& stats() const { return stats_; }
  uint64_t overflow_bookings() const;
  using sc_core::sc_object::trace;  // ours adds a window; the base's stays visible
  void trace(sc_core::sc_trace_file* file, const TraceWindow& window);

 private:
  void b_transport(int port, tlm::tlm_generic_payload& gp, sc_core::sc_time& delay);

  InterconnectConfig config_;
  BankInterleave interleave_;
  transport::Clock clock_;
  uint32_t line_shift_ = 0;
  std::vector<transport::ReservationCalendar> tm_ports_;
  std::vector<transport::ReservationCalendar> links_;  // L2 banks, then the stream memory
  transport::CountedPair<Counters> counters_;
  stats::Group stats_;
  std::unique_ptr<DataTrafficStats> by_data_stats_;
  WindowTrace trace_;
  std::size_t tr_bytes_, tr_conflicts_;
};

}  // namespace strata::memory
