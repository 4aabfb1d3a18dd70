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
// O(1 + backlog/64). Retiring the past costs nothing: each 64-cycle block of slots is tagged
// with the absolute block it holds, and a block whose tag is stale reads as empty and is
// cleared only when something is booked in it again. So a calendar that sees no requests
// (an idle unit, most of the time) costs no work per simulated cycle. Nothing allocates
// after construction.
//
// Bookings that do not fit in the window are not lost: they are served in arrival order
// after everything else in a tail beyond the window, whose extent counts as busy once the
// window reaches it. overflow_bookings() reports how often that happened; a horizon sized
// above the quantum plus the longest latency chain keeps it at zero.
#pragma once

#include "tlm/clock.h"

#include <algorithm>
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

  // Books one unit in the earliest cycle >= `earliest` that has fewer than `limit` units used
  // (1 <= limit <= units_per_cycle): a resource some of whose units are lent elsewhere for a
  // while (the XU crossbar's reconfigurable FP units). kNone if no such cycle lies inside the
  // window; nothing is booked then. Like book(), it remembers the run of cycles its last
  // search found at the limit, so a backlog is scanned once, not once per request.
  Cycle book_below(Cycle earliest, uint32_t limit);
  // The cycle book_below would book, without booking it; kNone also if it lies at or past
  // `until`.
  Cycle first_below(Cycle from, uint32_t limit, Cycle until = ~Cycle{0}) const;
  // The earliest cycle c >= `from` such that every cycle of [c, c + length) still has room,
  // within the window; kNone if there is none. (A unit that is busy for `length` cycles.)
  Cycle first_gap(Cycle from, uint32_t length) const;
  static constexpr Cycle kNone = ~Cycle{0};

  // Global time has reached `now`: no request can be made for an earlier cycle any more.
  // Inline: every booking of a shared unit calls it first. The retired slots' blocks go
  // stale by themselves (claim()), so only an overflow tail needs work.
  void retire_before(Cycle now) {
    if (now <= base_) return;
    const Cycle old_end = base_ + horizon_;
    base_ = now;
    if (overflow_tail_ != 0) expose(std::max(old_end, now), now + horizon_);
  }

  // Units booked in cycle c (0 outside the window). Inline: the XU crossbar asks per cycle.
  uint32_t used(Cycle c) const {
    if (c < base_ || c >= base_ + horizon_) return 0;
    const uint32_t slot = static_cast<uint32_t>(c & mask_);
    const Word& w = words_[slot >> 6];
    if (w.block != (c >> 6)) return 0;
    if (capacity_ > 1) return used_[slot];
    return static_cast<uint32_t>((w.full >> (slot & 63)) & 1);
  }
  Cycle base() const { return base_; }
  uint32_t horizon() const { return horizon_; }
  uint32_t units_per_cycle() const { return capacity_; }
  Cycle backlog_end() const { return latest_end_; }  // one past the latest booked cycle
  uint64_t overflow_bookings() const { return overflows_; }

 private:
  Cycle first_free(Cycle from) const;
  Cycle first_full(Cycle from, Cycle to) const;  // the first full cycle in [from, to), or kNone
  // The full-bits word of c's block (0 if the block holds an older one).
  uint64_t full_word(Cycle c) const {
    const Word& w = words_[static_cast<uint32_t>(c & mask_) >> 6];
    return w.block == (c >> 6) ? w.full : 0;
  }
  // c's slot, after making its block hold c's block (clearing an older one's contents).
  uint32_t claim(Cycle c);
  void expose(Cycle from, Cycle to);  // cycles entering the window: busy if in the overflow tail

  uint32_t capacity_;
  uint32_t horizon_;
  uint32_t mask_;  // slot of cycle c: c & mask_ (the ring holds 2 * horizon_ slots)
  // Per 64 slots: the absolute block (cycle / 64) they hold, and a bit per slot with no
  // capacity left. Side by side, so a lookup after another TM ran misses one cache line, not two.
  struct Word {
    Cycle block;
    uint64_t full;
  };
  std::vector<Word> words_;
  std::vector<uint16_t> used_;  // units per slot; empty when capacity_ == 1 (the bit says it)
  Cycle base_ = 0;
  Cycle latest_end_ = 0;
  Cycle run_lo_ = 0, run_hi_ = 0;  // [lo, hi): cycles known to be full (a search's skip)
  // [lo, hi): cycles known to hold at least below_limit_ units (book_below's skip). Counts
  // only grow while a cycle is in the window, so a run stays valid for that limit and below.
  Cycle below_lo_ = 0, below_hi_ = 0;
  uint32_t below_limit_ = 0;
  Cycle overflow_head_ = 0;  // [head, tail): hull of bookings placed beyond the window
  Cycle overflow_tail_ = 0;
  uint64_t overflows_ = 0;
};

}  // namespace strata::transport
