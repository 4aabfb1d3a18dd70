// The error target's plan (WindowSampler::spread_weight): how much spread the windows so far
// carry, in units of the spread the recent windows predict for the windows to come.
#include <gtest/gtest.h>

#include <vector>

#include "model/chip/window_sampler.h"

namespace {

using strata::chip::WindowSampler;
using Window = WindowSampler::Window;

// Windows of `instructions` each whose cycles lie `residual` above and below the common ratio
// (2 cycles per instruction), alternating, so that the ratio stays exactly 2.
void add_windows(std::vector<Window>& windows, size_t count, double weight, double residual) {
  const double instructions = 1000;
  for (size_t i = 0; i < count; ++i)
    windows.push_back({weight, 2 * instructions + (i % 2 ? -residual : residual), instructions});
}

TEST(WindowSampler, WindowsOfOneSpreadPlanAsTheSumOfSquaredWeights) {
  std::vector<Window> windows;
  add_windows(windows, 16, 1.0, 30.0);
  EXPECT_DOUBLE_EQ(WindowSampler::spread_weight(windows, 8), 16.0);
  add_windows(windows, 4, 3.0, 30.0);  // sparser windows, each standing for 3 periods
  EXPECT_DOUBLE_EQ(WindowSampler::spread_weight(windows, 8), 16.0 + 4 * 9.0);
}

// The frame's start spreads ten times more than the rest: its variance is large, but the
// windows to come will add only the recent spread, so the plan may thin them out sooner.
TEST(WindowSampler, ASpreadThatHasFallenLetsTheWindowsThinOutSooner) {
  std::vector<Window> windows;
  add_windows(windows, 8, 1.0, 300.0);
  add_windows(windows, 8, 1.0, 30.0);
  // Past: 8 x 300^2 + 8 x 30^2, over the last 8 windows' 30^2.
  EXPECT_DOUBLE_EQ(WindowSampler::spread_weight(windows, 8), 8 * 100.0 + 8.0);
  // Counting the start among the recent windows plans as before the fall.
  EXPECT_DOUBLE_EQ(WindowSampler::spread_weight(windows, 16), 16.0);
  // And a spread that has risen plans denser windows than the old rule (16).
  std::vector<Window> rising;
  add_windows(rising, 8, 1.0, 30.0);
  add_windows(rising, 8, 1.0, 300.0);
  EXPECT_LT(WindowSampler::spread_weight(rising, 8), 16.0);
}

TEST(WindowSampler, RecentWindowsOnTheRatioPlanAsForEqualSpreads) {
  std::vector<Window> windows;
  add_windows(windows, 8, 2.0, 50.0);
  add_windows(windows, 8, 1.0, 0.0);
  EXPECT_DOUBLE_EQ(WindowSampler::spread_weight(windows, 8), 8 * 4.0 + 8 * 1.0);
  EXPECT_EQ(WindowSampler::spread_weight({}, 8), 0.0);
  // Fewer windows than `recent`: all of them are recent.
  std::vector<Window> few;
  add_windows(few, 4, 1.0, 10.0);
  EXPECT_DOUBLE_EQ(WindowSampler::spread_weight(few, 8), 4.0);
}

}  // namespace

namespace {

// The window the frame ends in stands for the cycles from its start to the frame's end.
TEST(WindowSampler, TheTailWindowStandsForWhatIsLeftOfTheFrame) {
  strata::chip::TimingConfig t;  // period 100,000 cycles
  strata::chip::SamplingSchedule schedule(t);
  EXPECT_DOUBLE_EQ(WindowSampler::tail_weight(schedule, 250000, t.sample_period_cycles), 0.5);
  EXPECT_DOUBLE_EQ(WindowSampler::tail_weight(schedule, 299999, t.sample_period_cycles), 0.99999);
  schedule.change_period(300000, 1200000);  // the error target thinned the windows out
  EXPECT_DOUBLE_EQ(WindowSampler::tail_weight(schedule, 310000, t.sample_period_cycles), 0.1);
  EXPECT_DOUBLE_EQ(WindowSampler::tail_weight(schedule, 1499999, t.sample_period_cycles), 11.99999);
  EXPECT_DOUBLE_EQ(WindowSampler::tail_weight(schedule, 1600000, t.sample_period_cycles), 1.0);
}

}  // namespace
