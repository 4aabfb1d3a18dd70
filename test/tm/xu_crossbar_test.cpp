// The XU crossbar in general mode: contention between TPs for pipelined and non-pipelined
// units, out-of-order requests, the fused multiply-add and the counters.
#include "model/tm/xu_crossbar.h"
#include "test/tm/tm_test_support.h"

#include <gtest/gtest.h>

#include <vector>

namespace strata::tm {
namespace {

TEST(XuCrossbar, NinthMultiplyAtCycleZeroStartsAtCycleOne) {
  XuCrossbar xus{TmConfig{}};
  for (int tp = 0; tp < 8; ++tp) EXPECT_EQ(xus.issue_general(XuClass::kFpMul, 0), 0u) << "tp " << tp;
  EXPECT_EQ(xus.issue_general(XuClass::kFpMul, 0), 1u);
  EXPECT_EQ(xus.latency(XuClass::kFpMul), 2u);
  // The adders are a separate class with their own 8 units.
  EXPECT_EQ(xus.issue_general(XuClass::kFpAdd, 0), 0u);
}

TEST(XuCrossbar, NonPipelinedDividerSerialisesDivides16CyclesApart) {
  XuCrossbar xus{TmConfig{}};
  EXPECT_EQ(xus.issue_general(XuClass::kFpDiv, 0), 0u);
  EXPECT_EQ(xus.issue_general(XuClass::kFpDiv, 0), 16u);
  EXPECT_EQ(xus.issue_general(XuClass::kFpDiv, 0), 32u);
  EXPECT_EQ(xus.latency(XuClass::kFpDiv), 16u);
  // The square root unit is separate and behaves the same way.
  EXPECT_EQ(xus.issue_general(XuClass::kFpInvSqrt, 3), 3u);
  EXPECT_EQ(xus.issue_general(XuClass::kFpInvSqrt, 3), 19u);
}

TEST(XuCrossbar, DivideArrivingLateTakesAnEarlierGapOnlyIfItFitsWhole) {
  XuCrossbar xus{TmConfig{}};
  EXPECT_EQ(xus.issue_general(XuClass::kFpDiv, 100), 100u);  // [100, 116)
  EXPECT_EQ(xus.issue_general(XuClass::kFpDiv, 90), 116u);   // [90, 106) would overlap it
  EXPECT_EQ(xus.issue_general(XuClass::kFpDiv, 60), 60u);    // [60, 76) is free
  EXPECT_EQ(xus.issue_general(XuClass::kFpDiv, 76), 76u);    // [76, 92) too
  EXPECT_EQ(xus.issue_general(XuClass::kFpDiv, 84), 132u);   // no 16-cycle gap before 132
}

TEST(XuCrossbar, EarlierRequestArrivingLaterKeepsItsEarlierSlot) {
  XuCrossbar xus{TmConfig{}};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(xus.issue_general(XuClass::kFpMul, 50), 50u);
  EXPECT_EQ(xus.issue_general(XuClass::kFpMul, 10), 10u);  // not queued behind cycle 50
  EXPECT_EQ(xus.issue_general(XuClass::kFpMul, 50), 51u);
}

TEST(XuCrossbar, ComparatorsAndIntegerUnitsHaveTheirOwnCounts) {
  XuCrossbar xus{TmConfig{}};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(xus.issue_general(XuClass::kFpCmp, 0), 0u);
  EXPECT_EQ(xus.issue_general(XuClass::kFpCmp, 0), 1u);
  EXPECT_EQ(xus.latency(XuClass::kFpCmp), 1u);
  EXPECT_EQ(xus.issue_general(XuClass::kIntMul, 0), 0u);
  EXPECT_EQ(xus.issue_general(XuClass::kIntMul, 0), 0u);
  EXPECT_EQ(xus.issue_general(XuClass::kIntMul, 0), 1u);  // two integer multipliers
  EXPECT_EQ(xus.issue_general(XuClass::kIntDiv, 0), 0u);
  EXPECT_EQ(xus.issue_general(XuClass::kIntDiv, 0), 16u);
}

TEST(XuCrossbar, FusedMultiplyAddNeedsAnAdderWhenTheProductArrives) {
  XuCrossbar xus{TmConfig{}};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(xus.issue_general(XuClass::kFpAdd, 2), 2u);
  // A multiply at 0 would reach the adders at 2, which are full: start at 1, add at 3.
  EXPECT_EQ(xus.issue_fused_multiply_add(0), 1u);
  EXPECT_EQ(xus.fused_multiply_add_latency(), 4u);
  EXPECT_EQ(xus.issue_general(XuClass::kFpMul, 1), 1u);  // one multiplier taken at 1, seven left
  const XuStats s = xus.stats(10);
  EXPECT_EQ(s.fused_multiply_adds, 1u);
  EXPECT_EQ(s.total(XuClass::kFpMul).ops, 2u);
  EXPECT_EQ(s.total(XuClass::kFpAdd).ops, 9u);
}

TEST(XuCrossbar, CountsOpsAndBusyUnitCyclesByClassAndMode) {
  XuCrossbar xus{TmConfig{}};
  for (int i = 0; i < 3; ++i) xus.issue_general(XuClass::kFpMul, 0);
  for (int i = 0; i < 2; ++i) xus.issue_general(XuClass::kFpDiv, 0);
  const XuStats s = xus.stats(40);
  EXPECT_EQ(s.in(PipelineMode::kGeneral, XuClass::kFpMul).ops, 3u);
  EXPECT_EQ(s.in(PipelineMode::kGeneral, XuClass::kFpMul).busy_unit_cycles, 3u);  // pipelined: 1 each
  EXPECT_EQ(s.in(PipelineMode::kGeneral, XuClass::kFpDiv).ops, 2u);
  EXPECT_EQ(s.in(PipelineMode::kGeneral, XuClass::kFpDiv).busy_unit_cycles, 32u);  // 16 each
  EXPECT_EQ(s.total(XuClass::kFpAdd).ops, 0u);
  EXPECT_EQ(s.mode_cycles[static_cast<unsigned>(PipelineMode::kGeneral)], 40u);
  EXPECT_EQ(s.late_requests, 0u);
}

TEST(XuCrossbar, WindowFollowsTheRequestsAndReportsOnesTooLate) {
  TmConfig config;
  XuCrossbar xus{config};
  EXPECT_EQ(xus.issue_general(XuClass::kFpDiv, 1'000'000), 1'000'000u);
  // Within xu_history_cycles behind the newest request: still exact.
  EXPECT_EQ(xus.issue_general(XuClass::kFpDiv, 1'000'000 - 100), 1'000'000u - 100);
  EXPECT_EQ(xus.stats(0).late_requests, 0u);
  // Far behind: served from the oldest remembered cycle and reported.
  const Cycle start = xus.issue_general(XuClass::kFpMul, 5);
  EXPECT_EQ(start, 1'000'000u - config.xu_history_cycles);
  EXPECT_EQ(xus.stats(0).late_requests, 1u);
}

TEST(XuCrossbar, RetiringThePastKeepsBookingsAhead) {
  XuCrossbar xus{TmConfig{}};
  EXPECT_EQ(xus.issue_general(XuClass::kFpDiv, 100), 100u);  // busy [100, 116)
  xus.retire_before(110);
  EXPECT_EQ(xus.issue_general(XuClass::kFpDiv, 110), 116u);
}

// retire_before slides the window in steps of xu_history_cycles (it touches every calendar):
// a request behind the last step is served where it asks, one behind the window is late.
TEST(XuCrossbar, RetiresInStepsOfTheHistory) {
  TmConfig config;
  XuCrossbar xus{config};
  const Cycle step = config.xu_history_cycles;
  xus.retire_before(step - 1);  // less than a step: nothing retired
  EXPECT_EQ(xus.issue_general(XuClass::kFpMul, 10), 10u);
  EXPECT_EQ(xus.stats(0).late_requests, 0u);
  xus.retire_before(4 * step);  // a step or more: retired up to it
  EXPECT_EQ(xus.issue_general(XuClass::kFpMul, 4 * step - 10), 4 * step);
  EXPECT_EQ(xus.stats(0).late_requests, 1u);
  xus.retire_before(4 * step + 100);  // within a step of the base: not moved
  EXPECT_EQ(xus.issue_general(XuClass::kFpMul, 4 * step + 50), 4 * step + 50);
  EXPECT_EQ(xus.stats(0).late_requests, 1u);
}

}  // namespace
}  // namespace strata::tm
