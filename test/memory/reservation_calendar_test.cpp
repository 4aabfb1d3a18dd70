// The reservation calendar alone: out-of-order booking, capacity per cycle, recycling of
// the window, bookings beyond it, and booking below a lowered capacity.
#include "tlm/reservation_calendar.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>

namespace {

using strata::transport::Booking;
using strata::transport::ReservationCalendar;

TEST(ReservationCalendar, EarlierRequestArrivingLaterGetsItsOwnEarlierSlot) {
  ReservationCalendar cal(1, 1024);
  EXPECT_EQ(cal.book(900, 1).first, 900u);
  // A decoupled initiator that is behind asks later for an earlier cycle: it is not queued
  // behind cycle 900, as a "next free time" counter would do.
  EXPECT_EQ(cal.book(100, 1).first, 100u);
  EXPECT_EQ(cal.book(100, 1).first, 101u);  // cycle 100 is taken now: one cycle later
  EXPECT_EQ(cal.book(899, 2).last, 901u);   // 899, then 900 is busy, so 901
  EXPECT_EQ(cal.used(900), 1u);
  EXPECT_EQ(cal.used(902), 0u);
}

TEST(ReservationCalendar, CapacityPerCycleSpreadsLargeBookings) {
  ReservationCalendar cal(32, 1024);  // e.g. a DRAM channel moving 32 B per cycle
  Booking a = cal.book(10, 64);
  EXPECT_EQ(a.first, 10u);
  EXPECT_EQ(a.last, 11u);
  Booking b = cal.book(10, 16);
  EXPECT_EQ(b.first, 12u);
  EXPECT_EQ(b.last, 12u);
  Booking c = cal.book(10, 32);  // the 16 B left in cycle 12, then 16 B in cycle 13
  EXPECT_EQ(c.first, 12u);
  EXPECT_EQ(c.last, 13u);
  EXPECT_EQ(cal.used(12), 32u);
  EXPECT_EQ(cal.used(13), 16u);
  EXPECT_EQ(cal.backlog_end(), 14u);
}

TEST(ReservationCalendar, SearchSkipsLongRunsOfFullCycles) {
  ReservationCalendar cal(1, 16384);
  for (int i = 0; i < 10000; ++i) cal.book(0, 1);
  EXPECT_EQ(cal.book(0, 1).first, 10000u);
  EXPECT_EQ(cal.book(5000, 3).last, 10003u);
  EXPECT_EQ(cal.overflow_bookings(), 0u);
}

TEST(ReservationCalendar, RetiredCyclesAreRecycledForLaterTime) {
  ReservationCalendar cal(1, 64);
  for (int i = 0; i < 64; ++i) EXPECT_EQ(cal.book(0, 1).first, static_cast<uint64_t>(i));
  cal.retire_before(64);
  EXPECT_EQ(cal.base(), 64u);
  EXPECT_EQ(cal.book(64, 1).first, 64u);     // slot 0 reused for cycle 64: it was cleared
  EXPECT_EQ(cal.book(0, 1).first, 65u);      // the past is gone: served from now on
  cal.retire_before(1000000);                // a long jump clears everything
  EXPECT_EQ(cal.book(1000000, 1).first, 1000000u);
  EXPECT_EQ(cal.overflow_bookings(), 0u);
}

TEST(ReservationCalendar, BookingsBeyondTheHorizonAreKeptAndStayBusy) {
  ReservationCalendar cal(1, 64);
  const Booking b = cal.book(0, 100);  // 64 cycles fit, 36 go beyond the window
  EXPECT_EQ(b.first, 0u);
  EXPECT_EQ(b.last, 99u);
  EXPECT_EQ(cal.overflow_bookings(), 1u);
  EXPECT_EQ(cal.book(70, 1).first, 100u);  // beyond the window: after the tail, in order
  cal.retire_before(64);
  // Cycles 64..100 entered the window and remain booked.
  EXPECT_EQ(cal.book(64, 1).first, 101u);
}

}  // namespace

namespace {

using strata::transport::ReservationCalendar;

// A window that does not start on a 64-cycle boundary spans one block more than it holds:
// bookings at its far end must not evict those at its near end.
TEST(ReservationCalendar, UnalignedWindowKeepsBothEndsApart) {
  ReservationCalendar cal(4, 128);
  cal.retire_before(10);
  for (uint64_t c = 10; c < 64; ++c) EXPECT_EQ(cal.book(c, 4).first, c);  // fill 10..63
  EXPECT_EQ(cal.book(130, 2).first, 130u);  // the far end of [10, 138)
  for (uint64_t c = 10; c < 64; ++c) EXPECT_EQ(cal.used(c), 4u) << "cycle " << c;
  EXPECT_EQ(cal.book(10, 1).first, 64u);  // 10..63 are still full
  EXPECT_EQ(cal.used(130), 2u);
}

// Retiring costs nothing: old contents vanish when their slots are reused, not before, and
// stale contents never show through.
TEST(ReservationCalendar, StaleSlotsReadAsEmptyAfterTheWindowMoves) {
  ReservationCalendar cal(3, 64);
  for (uint64_t c = 0; c < 64; ++c) cal.book(c, 3);
  cal.retire_before(100);  // cycles 100..163 reuse the slots of 36..63 and 0..35
  for (uint64_t c = 100; c < 164; ++c) EXPECT_EQ(cal.used(c), 0u) << "cycle " << c;
  EXPECT_EQ(cal.book(100, 3).first, 100u);
  EXPECT_EQ(cal.book(127, 1).first, 127u);
  EXPECT_EQ(cal.used(128), 0u);
  EXPECT_EQ(cal.used(127), 1u);
  EXPECT_EQ(cal.used(99), 0u);  // before the window
}

// book_below: a resource with some units lent away books in the first cycle under the limit.
TEST(ReservationCalendar, BookBelowTakesTheFirstCycleUnderTheLimit) {
  ReservationCalendar cal(8, 1024);  // 8 FP multipliers, 6 of them in the box pipeline
  for (int i = 0; i < 2; ++i) EXPECT_EQ(cal.book_below(10, 2), 10u);
  EXPECT_EQ(cal.book_below(10, 2), 11u);  // cycle 10 holds 2: at the limit
  EXPECT_EQ(cal.book(10, 1).first, 10u);  // the full capacity still has room there
  EXPECT_EQ(cal.used(10), 3u);
  for (int i = 0; i < 100; ++i) cal.book_below(20, 2);  // a backlog of 50 cycles at the limit
  EXPECT_EQ(cal.book_below(20, 2), 70u);
  EXPECT_EQ(cal.book_below(30, 2), 70u);  // inside the remembered run: straight past it
  EXPECT_EQ(cal.book_below(30, 3), 30u);  // a higher limit is not held back by that run
  EXPECT_EQ(cal.book_below(30, 8), 30u);  // the full capacity: book()'s own search
  EXPECT_EQ(cal.used(30), 4u);
  EXPECT_EQ(cal.book_below(2000, 2), ReservationCalendar::kNone);  // beyond the window
  EXPECT_EQ(cal.first_below(71, 2), 71u);
  EXPECT_EQ(cal.overflow_bookings(), 0u);
}

// Against a plain map of units per cycle, through random bookings at random limits, both
// kinds of booking and a moving window: the remembered runs never change an answer, and
// first_gap finds the first stretch with room.
TEST(ReservationCalendar, BookBelowMatchesAReferenceModel) {
  constexpr uint32_t kCapacity = 8;
  ReservationCalendar cal(kCapacity, 512);
  std::map<uint64_t, uint32_t> used;
  uint64_t base = 0;
  std::mt19937_64 rng(20261202);
  for (int i = 0; i < 20000; ++i) {
    if (i % 100 == 99) {  // about 2.5 units a cycle: a backlog that stays inside the window
      base += 40;
      cal.retire_before(base);
    }
    const uint64_t earliest = base + rng() % 64;
    if (rng() % 4 == 0) {
      const uint32_t units = 1 + static_cast<uint32_t>(rng() % 3);
      const auto b = cal.book(earliest, units);
      uint32_t left = units;
      for (uint64_t c = earliest; left > 0; ++c) {
        const uint32_t take = std::min(kCapacity - used[c], left);
        if (take > 0 && left == units) {
          ASSERT_EQ(b.first, c);
        }
        used[c] += take;
        left -= take;
      }
    } else {
      const uint32_t limit = 1 + static_cast<uint32_t>(rng() % 3) * 2;  // 1, 3 or 5
      uint64_t expect = earliest;
      while (used[expect] >= limit) ++expect;
      ASSERT_EQ(cal.book_below(earliest, limit), expect) << "booking " << i;
      ++used[expect];
    }
    // first_gap: the first start whose `length` cycles all have room (a non-pipelined unit).
    const uint32_t length = 1 + static_cast<uint32_t>(rng() % 20);
    uint64_t gap = earliest;
    for (uint64_t c = gap; c < gap + length; ++c)
      if (used[c] >= kCapacity) gap = c + 1;
    ASSERT_EQ(cal.first_gap(earliest, length), gap) << "gap " << i;
  }
  for (uint64_t c = base; c < base + 512; ++c) ASSERT_EQ(cal.used(c), used[c]) << "cycle " << c;
  EXPECT_EQ(cal.overflow_bookings(), 0u);
}

}  // namespace
