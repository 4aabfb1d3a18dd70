// What the L1 caches and the L2 share: line/bank/set arithmetic, one reservation calendar
// per bank (one access per bank per cycle), and a tag array. Timing and state only; the
// data lives in the SparseMemory backing store.
//
// A line is installed when its miss is handled, with `ready` = the cycle its data arrives.
// An access that finds the line present but not yet ready is a merged miss: it waits for the
// same fill instead of sending another request (an MSHR with unlimited entries).
//
// Tags change in arrival order. Under temporal decoupling a request can arrive after one that
// is later in simulated time, so the core keeps what is needed to answer it as the precise
// order would (classify()):
//   - each line remembers the bank slot of the miss that requested it: an access with an
//     earlier slot would have been that miss itself, so it gets the same fill latency from
//     its own slot, not a wait for the future fill ("time-shifted miss");
//   - each set remembers the line it last evicted and the slot of the access that evicted
//     it: an earlier access to that line would still have hit ("shadow hit").
// In precise mode requests to a bank arrive in slot order, so neither case can occur and the
// behaviour is exactly that of an ordinary cache.
#pragma once

#include "model/memory/bank_interleave.h"
#include "tlm/clock.h"
#include "tlm/data_class.h"
#include "tlm/reservation_calendar.h"

#include <cstdint>
#include <vector>

namespace strata::memory {

struct CacheGeometry {
  uint32_t size_bytes;
  uint32_t banks;
  uint32_t line_bytes;
  uint32_t ways;  // 1: direct-mapped
  uint32_t horizon_cycles;
  bool hash_banks = false;  // BankInterleave: XOR-folded bank index
};

class CacheCore {
 public:
  using Cycle = transport::Cycle;
  static constexpr int kMiss = -1;

  explicit CacheCore(const CacheGeometry& g);

  uint64_t line_of(uint64_t addr) const { return addr >> line_shift_; }
  uint64_t line_base(uint64_t line) const { return line << line_shift_; }
  // Lines are interleaved over banks; a bank's lines map to the sets whose low bits name it.
  // With a hashed bank index the set takes the hashed bits in place of the line's low bits:
  // for a fixed tag that is still a one-to-one map of lines onto sets, so capacity is intact.
  uint32_t bank_of(uint64_t line) const { return interleave_.bank(line); }
  uint32_t set_of(uint64_t line) const {
    return (static_cast<uint32_t>(line) & (sets_ - 1) & ~(banks_ - 1)) | interleave_.bank(line);
  }
  bool crosses_line(uint64_t addr, uint32_t bytes) const {
    return bytes == 0 || (addr & (line_bytes_ - 1)) + bytes > line_bytes_;
  }

  // Takes the bank's first free cycle at or after `at`; `now` lets the calendar recycle.
  Cycle book_bank(uint32_t bank, Cycle at, Cycle now) {
    transport::ReservationCalendar& cal = bank_calendars_[bank];
    cal.retire_before(now);
    return cal.book(at, 1).first;
  }

  int find(uint32_t set, uint64_t line) const {
    const uint32_t base = set * ways_;
    for (uint32_t w = 0; w < ways_; ++w)
      if (tag_[base + w] == line + 1) return static_cast<int>(w);
    return kMiss;
  }
  enum class Outcome : uint8_t { kHit, kShadowHit, kMerged, kTimeShifted, kMiss };
  struct Lookup {
    Outcome outcome;
    int way;     // the way holding the line (kMiss if absent)
    Cycle done;  // completion for hits and merged or time-shifted misses
  };
  // Classifies a read at bank slot `slot` answering at `answer` = slot + hit latency. A
  // time-shifted miss also moves the line's fill earlier, as the precise order would have.
  Lookup classify(uint32_t set, uint64_t line, Cycle slot, Cycle answer);

  // Functional warming (sampled timing): the access's effect on the tags alone. A hit is
  // touched (and made dirty by a store); a miss, if `allocate`, takes the victim's way, ready
  // at once. Returns whether the line was present. Books nothing, leaves no shadow entry.
  bool warm(uint32_t set, uint64_t line, bool store, bool allocate, transport::DataClass data);

  // An invalid way if there is one, else the least recently used.
  uint32_t victim(uint32_t set) const;
  void touch(uint32_t set, uint32_t way) { lru_[set * ways_ + way] = ++use_clock_; }
  // `slot`: bank slot of the access that requested the line (and evicted the old one);
  // `data`: what the line holds, so that its write-back is counted as that.
  void install(uint32_t set, uint32_t way, uint64_t line, Cycle slot, Cycle ready, bool dirty,
               transport::DataClass data);

  bool valid(uint32_t set, uint32_t way) const { return tag_[set * ways_ + way] != 0; }
  uint64_t line_at(uint32_t set, uint32_t way) const { return tag_[set * ways_ + way] - 1; }
  Cycle ready(uint32_t set, uint32_t way) const { return ready_[set * ways_ + way]; }
  bool dirty(uint32_t set, uint32_t way) const { return dirty_[set * ways_ + way] != 0; }
  void set_dirty(uint32_t set, uint32_t way) { dirty_[set * ways_ + way] = 1; }
  transport::DataClass data_class(uint32_t set, uint32_t way) const { return data_[set * ways_ + way]; }

  uint32_t sets() const { return sets_; }
  uint32_t ways() const { return ways_; }
  uint32_t banks() const { return banks_; }
  uint32_t line_bytes() const { return line_bytes_; }
  const transport::ReservationCalendar& bank_calendar(uint32_t bank) const { return bank_calendars_[bank]; }
  uint64_t overflow_bookings() const;

 private:
  uint32_t banks_;
  uint32_t line_bytes_;
  uint32_t line_shift_ = 0;
  uint32_t ways_;
  uint32_t sets_;
  BankInterleave interleave_;
  std::vector<uint64_t> tag_;  // line index + 1; 0 = invalid
  std::vector<Cycle> ready_;
  std::vector<Cycle> requested_;      // bank slot of the miss that fetched the line
  std::vector<uint64_t> shadow_line_;  // per set: last evicted line + 1
  std::vector<Cycle> shadow_until_;    // per set: slot of the access that evicted it
  std::vector<uint64_t> lru_;
  std::vector<uint8_t> dirty_;
  std::vector<transport::DataClass> data_;
  uint64_t use_clock_ = 0;  // LRU order is arrival order, which is what the tags see
  std::vector<transport::ReservationCalendar> bank_calendars_;
};

}  // namespace strata::memory
