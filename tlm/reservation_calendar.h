// Books a shared resource's capacity in absolute cycles, so that decoupled (loosely timed)
// initiators see contention correctly even when their requests arrive out of time order.
//
// A "next free time" counter cannot do that: a request for cycle 100 that arrives after one
// for cycle 900 would be queued behind it. The calendar instead keeps, for every cycle of a
// sliding window [base, base + horizon), how many units are used (an access, a byte, a flit)
// and a bitmap of the cycles that are full. A booking takes the first cycles at or after the
// requested one that still have room, wherever later bookings already sit.
//
// Cost: the search skips 64 full cycles per word (count-trailing-zeros), so a booking costs
// O(1 + backlog/64); retiring the past clears whole words. Nothing allocates after
// construction. Slots are recycled as global time passes (retire_before).
//
// Bookings that do not fit in the window are not lost: they are served in arrival order
// after everything else in a tail beyond the window, whose extent counts as busy once the
// window reaches it. overflow_bookings() reports how often that happened; a horizon sized
// above the quantum plus the longest latency chain keeps it at zero.
#pragma once

#include "tlm/clock.h"

#include <cstdint>
#include <vector>

namespace strata::transport {

struct Booking {
  Cycle first = 0;  // cycle of the first unit booked
  Cycle last = 0;   // cycle of the last unit booked
  Cycle end() const { return last + 1; }
};

class ReservationCalendar {
 public:
  // units_per_cycle: the resource's capacity per cycle (1 for a bank, bytes for a channel).
  // horizon_cycles is rounded up to a power of two, at least 64.
  ReservationCalendar(uint32_t units_per_cycle, uint32_t horizon_cycles);

  // Books `units` (at least 1) in the earliest cycles >= `earliest` with room left. A booking
  // larger than one cycle's capacity spreads over as many cycles as it needs.
  Booking book(Cycle earliest, uint32_t units);

  // Global time has reached `now`: no request can be made for an earlier cycle any more.
  void retire_before(Cycle now);

  // Units booked in cycle c (0 outside the window). Inline: the XU crossbar asks per cycle.
  uint32_t used(Cycle c) const {
    if (c < base_ || c >= base_ + horizon_) return 0;
    const uint32_t slot = static_cast<uint32_t>(c & mask_);
    if (capacity_ > 1) return used_[slot];
    return static_cast<uint32_t>((full_[slot >> 6] >> (slot & 63)) & 1);
  }
  Cycle base() const { return base_; }
  uint32_t horizon() const { return horizon_; }
  uint32_t units_per_cycle() const { return capacity_; }
  Cycle backlog_end() const { return latest_end_; }  // one past the latest booked cycle
  uint64_t overflow_bookings() const { return overflows_; }

 private:
  static constexpr Cycle kNone = ~Cycle{0};
  Cycle first_free(Cycle from) const;
  void mark_full(uint32_t slot);
  void clear_range(Cycle from, Cycle count);
  void expose(Cycle from, Cycle to);  // cycles entering the window: busy if in the overflow tail

  uint32_t capacity_;
  uint32_t horizon_;
  uint32_t mask_;
  std::vector<uint64_t> full_;  // bit per slot: no capacity left
  std::vector<uint32_t> used_;  // units per slot; empty when capacity_ == 1 (the bit says it)
  Cycle base_ = 0;
  Cycle latest_end_ = 0;
  Cycle overflow_head_ = 0;  // [head, tail): hull of bookings placed beyond the window
  Cycle overflow_tail_ = 0;
  uint64_t overflows_ = 0;
};

}  // namespace strata::transport
