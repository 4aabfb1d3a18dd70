// The banked DRAM timing (memory.dram.model = banked): each channel holds ranks of bank
// groups of banks, each bank a row buffer, and every request becomes the commands a
// controller would issue (PRE, ACT, RD/WR; REF every tREFI), each at the earliest cycle the
// JEDEC constraints allow (dram_timing.h). Its data then takes the channel's data bus, a
// reservation calendar shared with nothing else, as in the channel model.
//
// Loosely timed like the rest of the project: nothing ticks. Per request the command times
// follow from per-bank and per-rank state (the next cycle each constraint allows, the last
// four ACTs for tFAW), and refreshes that fell due are applied lazily before it. Scheduling is
// first come, first served in the order requests arrive (call order, which under temporal
// decoupling is not quite time order): a request's commands are never placed before those of
// an earlier one in the same rank. FR-FCFS over a bounded queue (row hits first) is not done
// yet; docs/memory-system.md, "Banked DRAM".
//
// The class is plain C++ (no SystemC): Dram owns one and calls it from b_transport.
#pragma once

#include "model/memory/config.h"
#include "model/memory/dram_timing.h"
#include "model/stats/stat_group.h"
#include "tlm/clock.h"
#include "tlm/reservation_calendar.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace strata::memory {

class BankedDram {
 public:
  using Cycle = transport::Cycle;

  struct ChannelCounters {
    uint64_t row_hits = 0;       // the request's row was open
    uint64_t row_misses = 0;     // its bank was closed (precharged): ACT only
    uint64_t row_conflicts = 0;  // another row was open: PRE, then ACT
    uint64_t activates = 0, precharges = 0, reads = 0, writes = 0;  // commands
    uint64_t refreshes = 0;
    uint64_t refresh_cycles = 0;  // tRFC per refresh of each rank: the rank can do nothing else
    uint64_t read_requests = 0;
    uint64_t read_latency_cycles = 0;  // request to last data, summed over read requests
  };

  // `config` must have been validated. Times are converted at 1 GHz until set_clock_ghz.
  explicit BankedDram(const DramConfig& config);
  void set_clock_ghz(double ghz);

  struct Result {
    Cycle end = 0;     // one past the request's last data cycle
    Cycle queued = 0;  // cycles its data waited for the bus beyond the commands' timing
  };
  // Serves one request of `bytes` at `addr` (channel `channel`, already chosen by the
  // caller's channel hash) arriving at cycle `t`; its data is booked on `bus`. `count`: add to
  // the statistics (sampled timing counts its detailed windows only).
  Result access(uint32_t channel, uint64_t addr, uint32_t bytes, bool write, Cycle t,
                transport::ReservationCalendar& bus, bool count);

  const ChannelCounters& channel(uint32_t c) const { return counters_[c]; }
  const stats::Group& stats() const { return stats_; }
  const DramTiming& timing() const { return timing_; }

  // Where an address lives inside its channel (row:bank:column:channel, bank bits hashed).
  struct Location {
    uint32_t rank = 0, group = 0, bank = 0;  // bank: flat index over the channel's banks
    uint64_t row = 0;
  };
  Location locate(uint64_t addr) const;

 private:
  static constexpr Cycle kNever = ~Cycle{0};
  struct Bank {
    bool open = false;
    uint64_t row = 0;
    Cycle last_act = kNever;
    Cycle next_act = 0;  // tRC after its ACT, tRP after its PRE, tRFC after a refresh
    Cycle next_pre = 0;  // tRAS after its ACT, tRTP after a RD, tWR after write data
    Cycle next_col = 0;  // tRCD after its ACT
  };
  struct Rank {
    std::array<Cycle, 4> acts{kNever, kNever, kNever, kNever};  // the last four ACTs (tFAW)
    uint32_t act_slot = 0;  // the oldest of them
    Cycle last_act = kNever;
    uint32_t last_act_group = 0;
    Cycle last_col = kNever;
    uint32_t last_col_group = 0;
    Cycle write_data_end = 0;  // tWTR before a RD
    Cycle next_refresh = 0;
  };
  struct Channel {
    std::vector<Bank> banks;  // ranks x groups x banks_per_group
    std::vector<Rank> ranks;
  };

  void refresh_until(Channel& ch, uint32_t rank, Cycle until, ChannelCounters& k);
  Cycle earliest_act(const Channel& ch, const Location& at, Cycle from) const;

  DramConfig config_;
  DramTiming timing_;
  uint32_t interleave_shift_ = 0, column_shift_ = 0, bank_bits_ = 0;
  std::vector<Channel> channels_;
  std::vector<ChannelCounters> counters_;  // never resized: the statistics point into it
  stats::Group stats_;
  std::vector<std::unique_ptr<stats::Group>> channel_stats_;
};

}  // namespace strata::memory
