// The banked DRAM timing (memory.dram.model = banked): each channel holds ranks of bank
// groups of banks, each bank a row buffer, and every request becomes the commands a
// controller would issue (PRE, ACT, RD/WR; REF every tREFI), each at the earliest cycle the
// JEDEC constraints allow (dram_timing.h). Its data then takes the channel's data bus, a
// reservation calendar shared with nothing else, as in the channel model.
//
// Loosely timed like the rest of the project: nothing ticks. Per request the command times
// follow from per-bank state (the next cycle each constraint allows) and per-rank calendars
// (tlm/reservation_calendar.h): an ACT holds its rank's ACT calendar for tRRD_S and its bank
// group's for tRRD_L, and one of four units of a tFAW calendar for tFAW; a column command
// holds the rank's and the group's column calendars for tCCD_S and tCCD_L. A calendar, unlike
// a "next allowed" time, lets a request that arrives late in call order but early in time
// (temporal decoupling: another TM ran its quantum first) take an earlier gap, so LT stays
// close to precise timing. A bank's own state (its open row, tRC, tRAS, tRP, tRTP, tWR) is
// kept in call order: a bank serves its requests first come, first served in the order they
// arrive, except that a request earlier in time than the bank's latest ACT, whose own row
// cycle fits before it, is served there without touching that state. Refresh is applied
// lazily when a request reaches a refresh that fell due. Activates that had to wait are packed
// (packed_act) so that the gaps booking in arrival order leaves between them hold whole tRRD
// slots, as a controller with a queue fills them. A queue that reorders requests already
// answered (row hits first) cannot be modelled this way; docs/memory-system.md, "Banked DRAM".
//
// The class is plain C++ (no SystemC): Dram owns one and calls it from b_transport.
#pragma once

#include "model/memory/config.h"
#include "model/memory/dram_timing.h"
#include "model/stats/stat_group.h"
#include "tlm/clock.h"
#include "tlm/data_class.h"
#include "tlm/reservation_calendar.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace strata::memory {

class BankedDram {
 public:
  using Cycle = transport::Cycle;

  static constexpr unsigned kLatencyBuckets = 9;
  static constexpr uint64_t kFirstLatencyBucket = 16;
  struct ChannelCounters {
    uint64_t row_hits = 0;       // the request's row was open
    uint64_t row_misses = 0;     // its bank was closed (precharged): ACT only
    uint64_t row_conflicts = 0;  // another row was open: PRE, then ACT
    uint64_t activates = 0, precharges = 0, reads = 0, writes = 0;  // commands
    uint64_t refreshes = 0;
    uint64_t refresh_cycles = 0;  // tRFC per refresh of each rank: the rank can do nothing else
    uint64_t read_requests = 0;
    uint64_t read_latency_cycles = 0;  // request to last data, summed over read requests
    // Read latency in powers of two: bucket 0 below kFirstLatencyBucket cycles, then bucket b
    // holds kFirstLatencyBucket << (b - 1) to twice that, less one; the last has no upper end.
    std::array<uint64_t, kLatencyBuckets> read_latency_buckets{};
    // Cycles from each request's first command (PRE, ACT or its first column command) to its
    // last data, summed: over the frame's cycles, the banks busy at once.
    uint64_t busy_bank_cycles = 0;
  };
  static unsigned latency_bucket(uint64_t cycles) {
    unsigned b = 0;
    for (uint64_t from = kFirstLatencyBucket; cycles >= from && b + 1 < kLatencyBuckets; from <<= 1) ++b;
    return b;
  }
  // Row outcomes of the requests for each class of data (summed over channels).
  struct RowOutcomes {
    uint64_t hits = 0, misses = 0, conflicts = 0;
  };

  // `config` must have been validated. Times are converted at 1 GHz until set_clock_ghz.
  explicit BankedDram(const DramConfig& config);
  void set_clock_ghz(double ghz);

  enum class RowOutcome : uint8_t { kHit, kMiss, kConflict };
  struct Result {
    Cycle end = 0;     // one past the request's last data cycle
    Cycle queued = 0;  // cycles its data waited for the bus beyond the commands' timing
    RowOutcome row = RowOutcome::kMiss;
  };
  // Serves one request of `bytes` at `addr` (channel `channel`, already chosen by the
  // caller's channel hash) arriving at cycle `t`; its data is booked on `bus`. `count`: add to
  // the statistics (sampled timing counts its detailed windows only).
  // `now`: global time, before which nothing can be requested any more. `data`: what the
  // bytes hold (row outcomes by class).
  Result access(uint32_t channel, uint64_t addr, uint32_t bytes, bool write, Cycle t, Cycle now,
                transport::ReservationCalendar& bus, bool count,
                transport::DataClass data = transport::DataClass::kOther);
  // Fidelity: command bookings beyond a calendar's horizon (placed without the rank-level
  // constraints); must be 0.
  uint64_t overflow_bookings() const;

  const ChannelCounters& channel(uint32_t c) const { return counters_[c]; }
  const RowOutcomes& by_data(transport::DataClass c) const { return by_data_[static_cast<unsigned>(c)]; }
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
    Cycle next_act = 0;  // tRC after its ACT, tRP after its PRE
    Cycle next_pre = 0;  // tRAS after its ACT, tRTP after a RD, tWR after write data
    Cycle next_col = 0;  // tRCD after its ACT
  };
  // A command that holds its rank (or bank group) for a spacing: tRRD, tCCD. Capacity 1: an
  // ACT at a books [a, a + spacing), so any two are at least the spacing apart, in any order.
  using Calendar = transport::ReservationCalendar;
  struct Rank {
    Calendar acts, columns;             // tRRD_S, tCCD_S
    std::vector<Calendar> group_acts;   // tRRD_L, per bank group
    std::vector<Calendar> group_columns;  // tCCD_L, per bank group
    Calendar window;                    // tFAW: 4 units, an ACT holds one for tFAW cycles
    Cycle last_write = kNever;          // the latest WR command (call order)
    Cycle write_data_end = 0;           // its data's end: tWTR before a later RD
    Cycle next_refresh = 0;
    // The latest refresh: no ACT in [from, to). An interval, not a "next ACT" time, so a
    // request that arrives after it in call order but is earlier in time still goes before it.
    Cycle refresh_from = 0, refresh_to = 0;
    Rank(uint32_t groups, uint32_t horizon);
  };
  struct Channel {
    std::vector<Bank> banks;  // ranks x groups x banks_per_group
    std::vector<Rank> ranks;
  };

  void refresh_until(Channel& ch, uint32_t rank, Cycle until, ChannelCounters& k);
  // The first cycle >= from at which the rank's calendars allow an ACT of bank group `group`,
  // and its booking; `pack`: packed as well (packed_act). kNever: beyond a calendar's horizon
  // (the caller then ignores them).
  Cycle act_slot(const Rank& r, uint32_t group, Cycle from, bool pack) const;
  // `b`, or a later cycle if an ACT at b would leave a gap before it that is not a whole number
  // of tRRD slots (see the .cpp).
  Cycle packed_act(const Rank& r, Cycle b) const;
  void book_act(Rank& r, uint32_t group, Cycle at);
  // The same for a column command whose data starts `lead` cycles after it on `bus`.
  Cycle column_slot(const Rank& r, uint32_t group, Cycle from, Cycle lead, const Calendar& bus) const;
  void book_column(Rank& r, uint32_t group, Cycle at);
  Result issue_columns(Rank& rank, Bank* bank, uint32_t group, Cycle col_ready, uint32_t bytes, bool write,
                       transport::ReservationCalendar& bus, ChannelCounters& k);

  DramConfig config_;
  DramTiming timing_;
  uint32_t interleave_shift_ = 0, column_shift_ = 0, bank_bits_ = 0;
  std::vector<Channel> channels_;
  std::vector<ChannelCounters> counters_;  // never resized: the statistics point into it
  std::array<RowOutcomes, transport::kDataClassCount> by_data_{};
  // Counts one request's outcome and, for a read, its latency; `first`: its first command.
  void count_request(ChannelCounters& k, bool count, transport::DataClass data, RowOutcome row, bool write, Cycle t,
                     Cycle first, Cycle end);
  uint64_t overflows_ = 0;
  stats::Group stats_;
  std::vector<std::unique_ptr<stats::Group>> channel_stats_;
  std::vector<std::unique_ptr<stats::Group>> owned_groups_;  // histograms and data classes
};

}  // namespace strata::memory
