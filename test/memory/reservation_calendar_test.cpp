// The reservation calendar alone: out-of-order booking, capacity per cycle, recycling of
// the window and bookings beyond it.
#include "tlm/reservation_calendar.h"

#include <gtest/gtest.h>

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

}  // namespace
