// The stream memory's record of rays in flight: time-weighted means, the peak, and the steady
// span before the drain, on levels whose answers are known.
#include <gtest/gtest.h>

#include "model/memory/stream_occupancy.h"

namespace strata::memory {
namespace {

TEST(StreamOccupancy, TimeWeightsEachLevelUntilTheFramesEnd) {
  StreamOccupancy o;
  o.record(0, 100, 100, 1);
  o.record(1000, 100, 50, 2);
  o.record(2000, 10, 10, 1);
  const StreamOccupancy::Summary s = o.summary(4000);
  EXPECT_EQ(s.end, 4000u);
  EXPECT_DOUBLE_EQ(s.in_flight_mean, (100.0 * 2000 + 10.0 * 2000) / 4000);
  EXPECT_DOUBLE_EQ(s.stored_mean, (100.0 * 1000 + 50.0 * 1000 + 10.0 * 2000) / 4000);
  EXPECT_DOUBLE_EQ(s.nonempty_mean, (1.0 * 1000 + 2.0 * 1000 + 1.0 * 2000) / 4000);
  EXPECT_DOUBLE_EQ(s.rays_per_nonempty, 170000.0 / 5000.0);
  EXPECT_EQ(s.peak, 100u);
  // 2000 is a bin boundary at this length: the span is exact.
  EXPECT_EQ(s.steady_begin, 0u);
  EXPECT_EQ(s.steady_end, 2000u);
  EXPECT_DOUBLE_EQ(s.steady_mean, 100.0);
}

TEST(StreamOccupancy, SummaryLeavesTheRecordGoingOn) {
  StreamOccupancy o;
  o.record(0, 4, 4, 1);
  EXPECT_DOUBLE_EQ(o.summary(100).in_flight_mean, 4.0);
  o.record(200, 0, 0, 0);
  EXPECT_DOUBLE_EQ(o.summary(400).in_flight_mean, 2.0);
}

TEST(StreamOccupancy, FillAndDrainStayOutOfTheSteadyState) {
  StreamOccupancy o;
  for (uint32_t i = 1; i <= 100; ++i) o.record(i * 10, i, i, 1);  // fill over 1,000 cycles
  o.record(5000, 95, 95, 1);  // a dip inside the span, above 90%
  o.record(6000, 100, 100, 1);
  o.record(9000, 50, 50, 1);  // the drain
  o.record(9500, 0, 0, 0);
  const StreamOccupancy::Summary s = o.summary(10000);
  EXPECT_EQ(s.peak, 100u);
  // The level first reaches 90 at cycle 900 and is last at or above it until 9,000, to a bin.
  EXPECT_LE(s.steady_begin, 900u);
  EXPECT_GT(s.steady_begin, 900u - 16u);
  EXPECT_GE(s.steady_end, 9000u);
  EXPECT_LT(s.steady_end, 9000u + 16u);
  EXPECT_GT(s.steady_mean, 95.0);
  EXPECT_LT(s.steady_mean, 100.0);
  EXPECT_GT(s.steady_mean, s.in_flight_mean);
}

TEST(StreamOccupancy, ALongFrameKeepsABoundedHistory) {
  StreamOccupancy o;
  o.record(5'000'000, 8, 8, 1);
  const StreamOccupancy::Summary s = o.summary(10'000'000);
  EXPECT_DOUBLE_EQ(s.in_flight_mean, 4.0);
  EXPECT_EQ(s.peak, 8u);
  // The bins widened to 4,096 cycles: the span begins in the bin holding cycle 5,000,000.
  EXPECT_LE(s.steady_begin, 5'000'000u);
  EXPECT_GT(s.steady_begin, 5'000'000u - 10'000'000u / 2048);
  EXPECT_EQ(s.steady_end, 10'000'000u);
  EXPECT_GT(s.steady_mean, 8.0 * 0.999);
  EXPECT_LE(s.steady_mean, 8.0);
}

TEST(StreamOccupancy, AnOperationDeliveredLateCountsAtTheLatestCycleSeen) {
  StreamOccupancy o;
  o.record(100, 5, 5, 1);
  o.record(50, 7, 7, 1);  // loosely timed: arrived after the one at 100
  const StreamOccupancy::Summary s = o.summary(200);
  EXPECT_DOUBLE_EQ(s.in_flight_mean, 7.0 * 100 / 200);
  EXPECT_EQ(s.peak, 7u);
}

TEST(StreamOccupancy, NothingRecordedIsAllZero) {
  const StreamOccupancy::Summary s = StreamOccupancy().summary(1000);
  EXPECT_EQ(s.in_flight_mean, 0.0);
  EXPECT_EQ(s.peak, 0u);
  EXPECT_EQ(s.steady_mean, 0.0);
  EXPECT_EQ(s.rays_per_nonempty, 0.0);
}

}  // namespace
}  // namespace strata::memory
