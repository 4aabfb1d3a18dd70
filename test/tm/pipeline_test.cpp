// The fused box and triangle pipelines, the general units they leave, and reconfiguration:
// its cost, the drain of the units that change, and requests that arrive out of time order.
#include "model/tm/xu_crossbar.h"
#include "test/tm/tm_test_support.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace strata::tm {
namespace {

using testing::instant_switch;
using ::testing::HasSubstr;

TEST(PipelineBox, TenTestsAtCycleZeroStartOneCycleApartAndTakeEight) {
  XuCrossbar xus{instant_switch()};
  EXPECT_EQ(xus.configure(PipelineMode::kBox, 0), 0u);
  for (Cycle i = 0; i < 10; ++i) {
    const Cycle start = xus.issue_box_test(0);  // ten TPs, all at cycle 0
    EXPECT_EQ(start, i);
    EXPECT_EQ(start + xus.box_latency(), 8 + i);
  }
  EXPECT_EQ(xus.stats(20).box_tests, 10u);
}

TEST(PipelineBox, TestsWaitUntilTheSwitchIsDone) {
  XuCrossbar xus{TmConfig{}};  // reconfigure_cycles = 4
  EXPECT_EQ(xus.configure(PipelineMode::kBox, 0), 4u);
  EXPECT_EQ(xus.issue_box_test(0), 4u);
  EXPECT_EQ(xus.issue_box_test(1), 5u);
  EXPECT_EQ(xus.issue_box_test(20), 20u);
}

TEST(PipelineBox, LeavesTwoMultipliersAndTwoAddersForGeneralUse) {
  XuCrossbar xus{instant_switch()};
  xus.configure(PipelineMode::kBox, 0);
  EXPECT_EQ(xus.general_units(XuClass::kFpMul, 10), 2u);
  EXPECT_EQ(xus.general_units(XuClass::kFpAdd, 10), 2u);
  EXPECT_EQ(xus.issue_general(XuClass::kFpMul, 10), 10u);
  EXPECT_EQ(xus.issue_general(XuClass::kFpMul, 10), 10u);
  EXPECT_EQ(xus.issue_general(XuClass::kFpMul, 10), 11u);
  EXPECT_EQ(xus.issue_general(XuClass::kFpAdd, 10), 10u);
  EXPECT_EQ(xus.issue_general(XuClass::kFpAdd, 10), 10u);
  EXPECT_EQ(xus.issue_general(XuClass::kFpAdd, 10), 11u);
  // The fused multiply-add needs one of each, the product arriving 2 cycles later.
  EXPECT_EQ(xus.issue_fused_multiply_add(10), 11u);  // mul at 11 (one left), add at 13
  // Units that no pipeline uses are unaffected.
  for (int i = 0; i < 8; ++i) EXPECT_EQ(xus.issue_general(XuClass::kFpCmp, 10), 10u);
  const XuStats s = xus.stats(20);
  EXPECT_EQ(s.in(PipelineMode::kBox, XuClass::kFpMul).ops, 4u);
  EXPECT_EQ(s.in(PipelineMode::kGeneral, XuClass::kFpMul).ops, 0u);
}

TEST(PipelineTriangle, TwoTestsPerInitiationIntervalOf18WithLatency31) {
  XuCrossbar xus{instant_switch()};
  EXPECT_EQ(xus.configure(PipelineMode::kTriangle, 0), 0u);
  EXPECT_EQ(xus.issue_triangle_test(0), 0u);
  EXPECT_EQ(xus.issue_triangle_test(0), 0u);
  EXPECT_EQ(xus.issue_triangle_test(0), 18u);  // both lanes busy until 18
  EXPECT_EQ(xus.triangle_latency(), 31u);      // so complete at 31, 31 and 49
  EXPECT_EQ(xus.issue_triangle_test(5), 18u);  // the other lane
  EXPECT_EQ(xus.issue_triangle_test(0), 36u);
  EXPECT_EQ(xus.stats(40).triangle_tests, 5u);
  EXPECT_EQ(xus.stats(40).triangle_busy_cycles, 5u * 18u);
}

TEST(PipelineTriangle, LanesAreIndependent) {
  XuCrossbar xus{instant_switch()};
  xus.configure(PipelineMode::kTriangle, 0);
  EXPECT_EQ(xus.issue_triangle_test(0), 0u);   // lane A [0, 18)
  EXPECT_EQ(xus.issue_triangle_test(7), 7u);   // lane B [7, 25)
  EXPECT_EQ(xus.issue_triangle_test(7), 18u);  // lane A again
}

TEST(PipelineTriangle, LeavesFourMultipliersAndSixAdders) {
  XuCrossbar xus{instant_switch()};
  xus.configure(PipelineMode::kTriangle, 0);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(xus.issue_general(XuClass::kFpMul, 0), 0u);
  EXPECT_EQ(xus.issue_general(XuClass::kFpMul, 0), 1u);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(xus.issue_general(XuClass::kFpAdd, 0), 0u);
  EXPECT_EQ(xus.issue_general(XuClass::kFpAdd, 0), 1u);
}

TEST(PipelineTriangle, DivideRunsOnTheSharedDivider) {
  XuCrossbar xus{instant_switch()};
  xus.configure(PipelineMode::kTriangle, 0);
  EXPECT_EQ(xus.issue_triangle_divide(0), 0u);
  EXPECT_EQ(xus.triangle_divide_latency(), 16u);
  EXPECT_EQ(xus.issue_general(XuClass::kFpDiv, 0), 16u);  // an fdiv waits for it
  EXPECT_EQ(xus.issue_triangle_divide(0), 32u);
  const XuStats s = xus.stats(50);
  EXPECT_EQ(s.triangle_divides, 2u);
  EXPECT_EQ(s.in(PipelineMode::kTriangle, XuClass::kFpDiv).ops, 3u);
}

TEST(PipelineReconfigure, WaitsForGeneralOpsOnTheChangingUnitsToDrain) {
  XuCrossbar xus{TmConfig{}};  // reconfigure_cycles = 4
  // All eight multipliers take an op in each of cycles 0..3; the last leave at 3 + 2 = 5.
  for (Cycle c = 0; c < 4; ++c)
    for (int i = 0; i < 8; ++i) EXPECT_EQ(xus.issue_general(XuClass::kFpMul, c), c);
  EXPECT_EQ(xus.configure(PipelineMode::kBox, 1), 5u + 4u);
  EXPECT_EQ(xus.mode_usable_at(), 9u);
  EXPECT_EQ(xus.issue_box_test(1), 9u);
  // During the switch only the two units the box pipeline leaves are general.
  EXPECT_EQ(xus.general_units(XuClass::kFpMul, 6), 2u);
  EXPECT_EQ(xus.general_units(XuClass::kFpMul, 4), 8u);
}

TEST(PipelineReconfigure, OpsThatFitOnTheUnitsThatStayDoNotDelayIt) {
  XuCrossbar xus{TmConfig{}};
  for (int i = 0; i < 8; ++i) xus.issue_general(XuClass::kFpMul, 0);  // gone by cycle 2
  for (int i = 0; i < 2; ++i) xus.issue_general(XuClass::kFpAdd, 3);  // two adders stay general
  EXPECT_EQ(xus.configure(PipelineMode::kBox, 3), 7u);
}

TEST(PipelineReconfigure, GeneralOpsIssuedDuringTheSwitchWaitForIt) {
  XuCrossbar xus{TmConfig{}};
  EXPECT_EQ(xus.configure(PipelineMode::kBox, 0), 4u);
  EXPECT_EQ(xus.configure(PipelineMode::kGeneral, 20), 24u);  // no box test in flight
  // Ten multiplies at 22: 2 units while switching (22, 23), all 8 from 24.
  const Cycle expected[10] = {22, 22, 23, 23, 24, 24, 24, 24, 24, 24};
  for (Cycle e : expected) EXPECT_EQ(xus.issue_general(XuClass::kFpMul, 22), e);
}

TEST(PipelineReconfigure, FusedOpsInFlightDelayTheSwitchBack) {
  XuCrossbar xus{TmConfig{}};
  EXPECT_EQ(xus.configure(PipelineMode::kBox, 0), 4u);
  EXPECT_EQ(xus.issue_box_test(4), 4u);  // in the pipeline until 12
  EXPECT_EQ(xus.configure(PipelineMode::kGeneral, 5), 12u + 4u);
}

TEST(PipelineReconfigure, BoxToTriangleSwitchesDirectly) {
  XuCrossbar xus{TmConfig{}};
  xus.configure(PipelineMode::kBox, 0);                         // usable at 4
  xus.issue_box_test(4);                                        // done at 12
  EXPECT_EQ(xus.configure(PipelineMode::kTriangle, 5), 16u);   // switch [12, 16)
  EXPECT_EQ(xus.issue_triangle_test(0), 16u);
  // While switching, the units of the larger (box) pipeline are out of general use.
  EXPECT_EQ(xus.general_units(XuClass::kFpMul, 13), 2u);
  EXPECT_EQ(xus.general_units(XuClass::kFpAdd, 13), 2u);
  EXPECT_EQ(xus.general_units(XuClass::kFpMul, 16), 4u);
  EXPECT_EQ(xus.general_units(XuClass::kFpAdd, 16), 6u);
}

TEST(PipelineReconfigure, AskingForTheCurrentModeIsFreeAndNotCounted) {
  XuCrossbar xus{TmConfig{}};
  EXPECT_EQ(xus.configure(PipelineMode::kGeneral, 3), 3u);  // already general
  EXPECT_EQ(xus.configure(PipelineMode::kBox, 0), 4u);
  EXPECT_EQ(xus.configure(PipelineMode::kBox, 2), 4u);  // another TP asks for it too
  EXPECT_EQ(xus.configure(PipelineMode::kBox, 10), 10u);
  EXPECT_EQ(xus.stats(20).reconfigurations, 1u);
}

TEST(PipelineReconfigure, LateGeneralRequestSeesTheModeOfItsCycles) {
  // Loosely timed: a TP that ran ahead switched to box mode at 100; one that lags behind
  // then asks for multipliers just before. Ops that leave the unit by 100 get all eight;
  // ops still in flight at 100 only get the two units that stay general.
  XuCrossbar xus{TmConfig{}};
  EXPECT_EQ(xus.configure(PipelineMode::kBox, 100), 104u);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(xus.issue_general(XuClass::kFpMul, 98), 98u);
  const Cycle expected[8] = {99, 99, 100, 100, 101, 101, 102, 102};
  for (Cycle e : expected) EXPECT_EQ(xus.issue_general(XuClass::kFpMul, 99), e);
  EXPECT_EQ(xus.stats(200).in(PipelineMode::kGeneral, XuClass::kFpMul).ops, 10u);
  EXPECT_EQ(xus.stats(200).in(PipelineMode::kBox, XuClass::kFpMul).ops, 6u);  // started at 100..102
}

TEST(PipelineMisuse, FusedOpsOutsideTheirModeAreRejected) {
  XuCrossbar xus{TmConfig{}};
  try {
    xus.issue_box_test(0);
    FAIL() << "box test in general mode was accepted";
  } catch (const std::logic_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("strata.boxtest"));
    EXPECT_THAT(e.what(), HasSubstr("general mode"));
  }
  EXPECT_THROW(xus.issue_triangle_test(0), std::logic_error);
  EXPECT_THROW(xus.issue_triangle_divide(0), std::logic_error);
  xus.configure(PipelineMode::kBox, 0);
  EXPECT_THROW(xus.issue_triangle_test(0), std::logic_error);
  EXPECT_THROW(xus.issue_triangle_divide(0), std::logic_error);
  xus.configure(PipelineMode::kTriangle, 0);
  EXPECT_THROW(xus.issue_box_test(0), std::logic_error);
  EXPECT_NO_THROW(xus.issue_triangle_test(0));
  EXPECT_EQ(xus.stats(100).box_tests, 0u);
}

TEST(PipelineStats, CountsModeCyclesAndReconfigurations) {
  XuCrossbar xus{TmConfig{}};
  EXPECT_EQ(xus.configure(PipelineMode::kBox, 10), 14u);
  xus.issue_box_test(14);                                     // done at 22
  EXPECT_EQ(xus.configure(PipelineMode::kGeneral, 30), 34u);
  const XuStats s = xus.stats(100);
  EXPECT_EQ(s.reconfigurations, 2u);
  EXPECT_EQ(s.reconfiguring_cycles, 8u);
  EXPECT_EQ(s.mode_cycles[static_cast<unsigned>(PipelineMode::kGeneral)], 10u + 66u);
  EXPECT_EQ(s.mode_cycles[static_cast<unsigned>(PipelineMode::kBox)], 16u);
  EXPECT_EQ(s.mode_cycles[static_cast<unsigned>(PipelineMode::kTriangle)], 0u);
  EXPECT_EQ(s.box_tests, 1u);
  EXPECT_EQ(s.box_busy_cycles, 1u);
}

}  // namespace
}  // namespace strata::tm
