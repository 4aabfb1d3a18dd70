// The ray stream memory controller (STRaTA): a TLM target serving push, pop, size, assign
// and capacity (MemoryExtension::access) over the linked lists in StreamSram, and assigning
// treelet buffers to TMs with a StreamScheduler.
//
//   push     TLM write of one ray (layout().ray_bytes: 48, or 64 with the compact path state);
//            ext.treelet; status kOk, or kFull (nothing stored: retry).
//   pop      TLM read of one ray; ext.treelet, or kNoTreelet for the TM's assigned buffer;
//            status kOk, or kEmpty (buffer empty or none assigned).
//   size     ext.treelet; result = rays in it.
//   assign   ext.tm_id; result = the TM's treelet, or kNoTreelet when all are empty.
//   capacity result = rays the memory holds.
//   path read/write  up to a ray's width of on-chip path state (timing only: the TP moved the data);
//            refused unless the layout keeps path records (path_record_bytes).
// ext.result is also 1/0 for push and pop, as the strata.streampush/pop instructions return.
//
// Time: push and pop take one of `ports` SRAM ports for a cycle (a reservation calendar, so
// contention holds in both timing modes) and complete access_latency later; the queries
// read the head/count region and take query_latency. The lists change in arrival order.
#pragma once

#include "model/memory/config.h"
#include "model/memory/data_traffic.h"
#include "model/memory/memory_levels.h"
#include "model/stats/stat_group.h"
#include "model/memory/stream_occupancy.h"
#include "model/memory/stream_scheduler.h"
#include "model/memory/stream_sram.h"
#include "model/memory/window_trace.h"
#include "tlm/clock.h"
#include "tlm/reservation_calendar.h"

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_target_socket.h>

#include <memory>
#include <vector>

namespace strata::memory {

class StreamMemory : public sc_core::sc_module, public StreamLevel {
 public:
  tlm_utils::simple_target_socket<StreamMemory> target{"target"};
  tlm::tlm_target_socket<>& target_socket() override { return target; }

  struct Counters {
    uint64_t accesses = 0, pushes = 0, pops = 0, queries = 0;
    uint64_t full_rejections = 0, empty_pops = 0, assignments = 0, port_conflicts = 0, conflict_cycles = 0;
    uint64_t link_conflicts = 0, link_conflict_cycles = 0;  // the banks' links (when modelled here)
    uint64_t path_reads = 0, path_writes = 0;  // on-chip path state
    uint64_t bytes_read = 0, bytes_written = 0;
    double energy_nj = 0.0;
    DataTraffic by_data{};
  };

  StreamMemory(sc_core::sc_module_name name, const StreamMemoryConfig& config);

  uint32_t capacity() const override { return sram_.capacity(); }
  uint32_t stored() const override { return sram_.stored(); }
  uint32_t credits() const { return sram_.credits(); }  // rays held by threads that popped one
  // Rays in flight (stored + held), the buffers holding rays, over the frame.
  const StreamOccupancy& occupancy() const override { return occupancy_; }
  uint32_t size(uint32_t treelet) const { return sram_.size(treelet); }
  const StreamLayout& layout() const override { return sram_.layout(); }
  const StreamScheduler& scheduler() const { return scheduler_; }
  uint64_t overflow_bookings() const;
  // The chip's clock (default 1 GHz). Before sc_start: every module of a chip must count in
  // the same cycles as the TMs, or each latency in cycles stretches by the ratio of the clocks.
  void set_clock(const transport::Clock& clock) override { clock_ = clock; }
  const Counters& counters() const { return counters_.counted; }
  const stats::Group& stats() const override { return stats_; }
  double energy_per_access_nj() const { return energy_per_access_; }
  // VCD: rays stored, pushes and pops per cycle, rejected pushes per cycle.
  using sc_core::sc_object::trace;  // ours adds a window; the base's stays visible
  void trace(sc_core::sc_trace_file* file, const TraceWindow& window) override;

 private:
  void b_transport(tlm::tlm_generic_payload& gp, sc_core::sc_time& delay);

  StreamMemoryConfig config_;
  double energy_per_access_;
  transport::Clock clock_;
  StreamSram sram_;
  StreamScheduler scheduler_;
  struct Bank {
    transport::ReservationCalendar ports;
    transport::ReservationCalendar link;  // flits per cycle (1), if links are modelled here
    uint64_t accesses = 0, conflict_cycles = 0;  // counted accesses only
  };
  uint32_t bank_of_entry(uint32_t entry) const { return entry % config_.banks; }
  std::vector<Bank> banks_;  // never resized (the stats point into it)
  std::vector<std::unique_ptr<stats::Group>> bank_stats_;
  transport::CountedPair<Counters> counters_;
  // Rays stored and taken over the whole frame, fast-forward included: the rays fix them, so
  // they are exact in every timing mode. Only refused pushes and empty pops depend on timing.
  uint64_t rays_pushed_ = 0, rays_popped_ = 0;
  // Pushes, pops, size queries and assignments dated before one already served: the ray
  // schedule changed out of time order (whole frame, fast-forward included; a fidelity check).
  uint64_t schedule_ops_out_of_order_ = 0;
  transport::Cycle latest_schedule_op_ = 0;
  StreamOccupancy occupancy_;  // every push and pop, fast-forward included: levels are never scaled
  stats::Group stats_;
  std::unique_ptr<DataTrafficStats> by_data_stats_;
  WindowTrace trace_;
  std::size_t tr_stored_, tr_pushes_, tr_pops_, tr_full_;
};

}  // namespace strata::memory
