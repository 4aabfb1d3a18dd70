// The error target's plan (WindowSampler::spread_weight): how much spread the windows so far
// carry, in units of the spread the recent windows predict for the windows to come.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "model/sampling/window_sampler.h"

namespace {

using strata::sampling::WindowSampler;
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

using strata::stats::IntervalMethod;

// By successive differences the plan counts how much neighbouring windows differ: windows of
// one spread still plan as the sum of their squared weights.
TEST(WindowSampler, BySuccessiveDifferencesWindowsOfOneSpreadPlanAsTheirCount) {
  std::vector<Window> windows;
  add_windows(windows, 16, 1.0, 30.0);
  EXPECT_DOUBLE_EQ(WindowSampler::spread_weight(windows, 8, IntervalMethod::kSuccessiveDifferences), 16.0);
}

// A trend in the residuals (a STRaTA frame's DRAM bytes per instruction rise over the frame):
// the jackknife's plan reads the recent windows, far from the frame's ratio, as a spread far
// larger than the past's and plans for many more windows; successive differences see only the
// small steps between neighbours, the same in the past and recently.
TEST(WindowSampler, ATrendIsNotASpreadBySuccessiveDifferences) {
  std::vector<Window> windows;
  for (int i = 0; i < 32; ++i) windows.push_back({1.0, 1000.0 + 10.0 * i + (i % 2 ? 1.0 : -1.0), 1000.0});
  const double successive = WindowSampler::spread_weight(windows, 8, IntervalMethod::kSuccessiveDifferences);
  EXPECT_NEAR(successive, 32.0, 4.0);
  EXPECT_LT(WindowSampler::spread_weight(windows, 8, IntervalMethod::kJackknife), 0.6 * successive);
}

}  // namespace

namespace {

// The window the frame ends in stands for the cycles from its start to the frame's end.
// The plan's frame length: the pace so far, or the recent pace when pixels now finish faster
// than on average (a STRaTA frame's first paths take many bounces before any pixel is done);
// never longer than the pace so far.
TEST(WindowSampler, TheFrameIsPlannedAtTheRecentPaceWhenItIsFaster) {
  using History = std::vector<std::pair<double, double>>;
  // No history: the pace so far, 40% done at 400,000 cycles.
  EXPECT_DOUBLE_EQ(WindowSampler::planned_frame_cycles(400000, 0.4, {}), 1000000.0);
  // A steady pace: the same.
  EXPECT_DOUBLE_EQ(WindowSampler::planned_frame_cycles(400000, 0.4, History{{200000, 0.2}, {300000, 0.3}}), 1000000.0);
  // Nothing done until 200,000 cycles, then 10% per 50,000: the rest (60%) at the recent pace.
  const History late{{200000, 0.0}, {250000, 0.1}, {300000, 0.2}, {350000, 0.3}};
  EXPECT_DOUBLE_EQ(WindowSampler::planned_frame_cycles(400000, 0.4, late), 400000.0 + 0.6 / (0.4 / 200000));
  // The pace falling (a drain): the pace so far, the longer, is kept.
  const History slowing{{100000, 0.2}, {200000, 0.35}, {300000, 0.38}};
  EXPECT_DOUBLE_EQ(WindowSampler::planned_frame_cycles(400000, 0.4, slowing), 1000000.0);
  // No progress lately: the pace so far.
  EXPECT_DOUBLE_EQ(WindowSampler::planned_frame_cycles(400000, 0.4, History{{300000, 0.4}}), 1000000.0);
  // Only the last kRecentWindows entries set the recent pace.
  History many;
  for (int i = 0; i < 20; ++i) many.push_back({10000.0 * i, i < 12 ? 0.0 : 0.025 * (i - 11)});
  const auto& [then, done] = many[many.size() - WindowSampler::kRecentWindows];
  EXPECT_DOUBLE_EQ(WindowSampler::planned_frame_cycles(200000, 0.25, many),
                   200000.0 + 0.75 / ((0.25 - done) / (200000.0 - then)));
}

TEST(WindowSampler, TheTailWindowStandsForWhatIsLeftOfTheFrame) {
  strata::sampling::TimingConfig t;  // period 100,000 cycles
  strata::sampling::SamplingSchedule schedule(t);
  EXPECT_DOUBLE_EQ(WindowSampler::tail_weight(schedule, 250000, t.sample_period_cycles), 0.5);
  EXPECT_DOUBLE_EQ(WindowSampler::tail_weight(schedule, 299999, t.sample_period_cycles), 0.99999);
  schedule.change_period(300000, 1200000);  // the error target thinned the windows out
  EXPECT_DOUBLE_EQ(WindowSampler::tail_weight(schedule, 310000, t.sample_period_cycles), 0.1);
  EXPECT_DOUBLE_EQ(WindowSampler::tail_weight(schedule, 1499999, t.sample_period_cycles), 11.99999);
  EXPECT_DOUBLE_EQ(WindowSampler::tail_weight(schedule, 1600000, t.sample_period_cycles), 1.0);
}

}  // namespace

namespace {

// The frame's head and drain as windows timed in full (sampling_schedule.h): the head is
// detailed and measured from cycle 0 with no warm-up, the drain from its window on until the
// frame ends; the measured cycles count both.
TEST(SamplingScheduleStrata, TheHeadAndTheDrainAreWindowsTimedInFull) {
  strata::sampling::TimingConfig t;  // period 100,000, detail 20,000, warm-up 8,000
  strata::sampling::SamplingSchedule s(t);
  WindowSampler::plan_head(t, s);  // 4 periods by default
  const uint64_t head = 4 * 100000, gap = WindowSampler::min_period(t) - t.sample_detail_cycles;
  ASSERT_TRUE(s.has_head());
  EXPECT_EQ(s.head_cycles(), head);
  EXPECT_EQ(s.window_of(0), 0u);
  EXPECT_EQ(s.warmup_at(0), 0u);
  EXPECT_TRUE(s.detailed(0));
  EXPECT_TRUE(s.detailed(head - 1));
  EXPECT_FALSE(s.detailed(head));
  EXPECT_EQ(s.next_window(0), head + gap);  // then the configured windows
  EXPECT_EQ(s.warmup_at(head + gap), 8000u);
  EXPECT_EQ(s.window_end(head + gap), head + gap + 19999);
  EXPECT_EQ(s.measured_cycles_before(head), head);
  EXPECT_EQ(s.measured_cycles_before(head + gap + 100000), head + 12000);
  EXPECT_EQ(s.changes(), 0u);

  const uint64_t drain = head + gap + 300000;
  s.change_period(head + gap + 200000, 50000);  // an error target's plan
  s.time_in_full(drain);
  EXPECT_EQ(s.changes(), 1u);
  EXPECT_TRUE(s.timed_in_full(drain + 123456789));
  EXPECT_TRUE(s.detailed(drain + 123456789));
  EXPECT_FALSE(s.timed_in_full(drain - 1));
  EXPECT_EQ(s.drain_from(), drain);
  EXPECT_EQ(s.sampled_period_at(drain + 5), 50000u);
  EXPECT_EQ(s.period_at(drain - 1), 50000u);
  const uint64_t before = s.measured_cycles_before(drain);
  EXPECT_EQ(s.measured_cycles_before(drain + 8000), before);  // its warm-up
  EXPECT_EQ(s.measured_cycles_before(drain + 1008000), before + 1000000);

  strata::sampling::TimingConfig none;
  none.sample_head_periods = 0;
  strata::sampling::SamplingSchedule plain(none);
  WindowSampler::plan_head(none, plain);
  EXPECT_FALSE(plain.has_head());
  EXPECT_EQ(plain.warmup_at(0), 8000u);
  EXPECT_EQ(plain.head_cycles(), 0u);
}

}  // namespace
