#include "tlm/reservation_calendar.h"

#include <algorithm>
#include <stdexcept>

namespace strata::transport {

namespace {
// Checked first: a horizon above 2^31 would never be reached by doubling a uint32_t.
uint32_t round_up_pow2(uint32_t v) {
  if (v > (1u << 30)) throw std::invalid_argument("ReservationCalendar: horizon above 2^30 cycles");
  uint32_t p = 64;
  while (p < v) p <<= 1;
  return p;
}
}  // namespace

ReservationCalendar::ReservationCalendar(uint32_t units_per_cycle, uint32_t horizon_cycles)
    : capacity_(units_per_cycle), horizon_(round_up_pow2(horizon_cycles)), mask_(2 * horizon_ - 1) {
  if (capacity_ == 0 || capacity_ > 65535)
    throw std::invalid_argument("ReservationCalendar: units_per_cycle must be in [1, 65535]");
  if (horizon_cycles > (1u << 30)) throw std::invalid_argument("ReservationCalendar: horizon too large");
  // Twice the window's slots: a window not aligned to 64 cycles spans one block more than
  // it holds, and its first and last blocks must not share a word.
  words_.assign(2 * horizon_ / 64, Word{kNone, 0});  // no block: every slot reads as empty
  if (capacity_ > 1) used_.assign(2 * horizon_, 0);
}

Cycle ReservationCalendar::first_free(Cycle from) const {
  const Cycle end = base_ + horizon_;
  Cycle c = from;
  while (c < end) {
    if (c >= run_lo_ && c < run_hi_) c = run_hi_;  // a known full run: skip it whole
    if (c >= end) break;
    const uint32_t slot = static_cast<uint32_t>(c & mask_);
    const uint32_t bit = slot & 63;
    const uint64_t below = bit == 0 ? 0 : ((uint64_t{1} << bit) - 1);
    const uint64_t word = full_word(c) | below;
    if (word != ~uint64_t{0}) {
      const Cycle found = c + static_cast<Cycle>(__builtin_ctzll(~word) - bit);
      return found < end ? found : kNone;
    }
    c += 64 - bit;
  }
  return kNone;
}

Cycle ReservationCalendar::first_below(Cycle from, uint32_t limit, Cycle until) const {
  const Cycle end = std::min(base_ + horizon_, until);
  if (limit >= capacity_) {
    const Cycle f = first_free(std::max(from, base_));
    return f < end ? f : kNone;
  }
  Cycle c = std::max(from, base_);
  if (limit <= below_limit_ && c >= below_lo_ && c < below_hi_) c = below_hi_;
  while (c < end) {
    const uint32_t slot = static_cast<uint32_t>(c & mask_);
    const uint32_t bit = slot & 63;
    const Word& w = words_[slot >> 6];
    if (w.block != (c >> 6)) return c;  // a block nothing is booked in yet
    // Full cycles hold capacity_ >= limit units: skip them a word at a time.
    const uint64_t below = bit == 0 ? 0 : ((uint64_t{1} << bit) - 1);
    const uint64_t word = w.full | below;
    if (word == ~uint64_t{0}) {
      c += 64 - bit;
      continue;
    }
    const uint32_t skip = static_cast<uint32_t>(__builtin_ctzll(~word)) - bit;
    c += skip;
    if (c >= end) break;
    if (used_[static_cast<uint32_t>(c & mask_)] < limit) return c;
    ++c;
  }
  return kNone;
}

Cycle ReservationCalendar::book_below(Cycle earliest, uint32_t limit) {
  if (limit >= capacity_) {
    const Booking b = book(earliest, 1);
    return b.first < base_ + horizon_ ? b.first : kNone;
  }
  const Cycle asked = std::max(earliest, base_);
  const Cycle f = first_below(asked, limit);
  if (f == kNone) return kNone;
  // [asked, f) holds at least `limit` units in every cycle. Keep it as the skip if it joins
  // the remembered run (same limit) or is long enough to be worth remembering.
  if (f > asked) {
    if (limit == below_limit_ && asked <= below_hi_ && f >= below_lo_) {
      below_lo_ = std::min(below_lo_, asked);
      below_hi_ = std::max(below_hi_, f);
    } else if (f - asked >= 8 || limit != below_limit_) {
      below_limit_ = limit;
      below_lo_ = asked;
      below_hi_ = f;
    }
  }
  const uint32_t slot = claim(f);
  used_[slot] = static_cast<uint16_t>(used_[slot] + 1);
  if (used_[slot] == capacity_) words_[slot >> 6].full |= uint64_t{1} << (slot & 63);
  if (limit == below_limit_ && f == below_hi_ && used_[slot] >= limit) below_hi_ = f + 1;
  if (f == run_hi_ && used_[slot] == capacity_) run_hi_ = f + 1;  // book()'s full run grew too
  latest_end_ = std::max(latest_end_, f + 1);
  return f;
}

Cycle ReservationCalendar::first_full(Cycle from, Cycle to) const {
  for (Cycle c = from; c < to;) {
    const uint32_t bit = static_cast<uint32_t>(c & mask_) & 63;
    const uint64_t word = full_word(c) >> bit;
    if (word != 0) {
      const Cycle found = c + static_cast<Cycle>(__builtin_ctzll(word));
      return found < to ? found : kNone;
    }
    c += 64 - bit;
  }
  return kNone;
}

Cycle ReservationCalendar::first_gap(Cycle from, uint32_t length) const {
  const Cycle end = base_ + horizon_;
  Cycle c = first_free(std::max(from, base_));
  while (c != kNone) {
    if (c + length > end) return kNone;
    const Cycle blocked = first_full(c, c + length);
    if (blocked == kNone) return c;
    c = first_free(blocked + 1);
  }
  return kNone;
}

uint32_t ReservationCalendar::claim(Cycle c) {
  const uint32_t slot = static_cast<uint32_t>(c & mask_);
  const uint32_t w = slot >> 6;
  if (words_[w].block != (c >> 6)) {
    words_[w] = Word{c >> 6, 0};
    if (capacity_ > 1) std::fill_n(used_.begin() + (w << 6), 64, uint16_t{0});
  }
  return slot;
}

Booking ReservationCalendar::book(Cycle earliest, uint32_t units) {
  if (units == 0) units = 1;
  Cycle c = std::max(earliest, base_);
  // A saturated resource has a long run of full cycles ahead of the present, and every request
  // would scan it: skip the run remembered from the last search.
  if (c >= run_lo_ && c < run_hi_) c = run_hi_;
  const Cycle asked = c;
  Booking b;
  bool started = false;
  while (units > 0) {
    const Cycle f = first_free(c);
    if (!started && f != kNone) {
      // [asked, f) is full, and stays so (only retiring frees a cycle). Remember it if it
      // extends the run or is long enough to be worth skipping next time.
      if (asked == run_hi_ || f - asked >= 64) {
        if (asked != run_hi_) run_lo_ = asked;
        run_hi_ = f;
      }
    }
    if (f == kNone) {
      // Beyond the window: serve after everything already there, in arrival order.
      const Cycle start = std::max({c, base_ + horizon_, overflow_tail_});
      const Cycle cycles = (units + capacity_ - 1) / capacity_;
      if (overflow_tail_ <= overflow_head_) overflow_head_ = start;
      overflow_tail_ = start + cycles;
      if (!started) b.first = start;
      b.last = overflow_tail_ - 1;
      ++overflows_;
      break;
    }
    const uint32_t slot = claim(f);
    const uint64_t bit = uint64_t{1} << (slot & 63);
    uint32_t take = 1;
    uint64_t& full = words_[slot >> 6].full;
    if (capacity_ == 1) {
      full |= bit;
    } else {
      take = std::min(capacity_ - used_[slot], units);
      used_[slot] = static_cast<uint16_t>(used_[slot] + take);
      if (used_[slot] == capacity_) full |= bit;
    }
    units -= take;
    if (!started) {
      b.first = f;
      started = true;
    }
    if (f == run_hi_ && (full & bit)) run_hi_ = f + 1;  // the run grew by this cycle
    b.last = f;
    c = f + 1;
  }
  latest_end_ = std::max(latest_end_, b.end());
  return b;
}

void ReservationCalendar::expose(Cycle from, Cycle to) {
  const Cycle lo = std::max(from, overflow_head_);
  const Cycle hi = std::min(to, overflow_tail_);
  for (Cycle c = lo; c < hi; ++c) {
    const uint32_t slot = claim(c);
    words_[slot >> 6].full |= uint64_t{1} << (slot & 63);
    if (capacity_ > 1) used_[slot] = static_cast<uint16_t>(capacity_);
  }
  // The whole tail is inside the window now; later overflows start a new one.
  if (overflow_tail_ <= to) overflow_head_ = overflow_tail_ = 0;
}

}  // namespace strata::transport
