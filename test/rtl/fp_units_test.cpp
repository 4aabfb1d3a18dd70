// The verilated IEEE-754 binary32 units (rtl/fp/) against the host's float arithmetic, bit for
// bit: 100,000 deterministic random operand pairs per unit, and every edge class enumerated
// (rtl/cosim/fp_units.h). scripts/rtl-campaign runs millions.
#include <gtest/gtest.h>

#include <cstring>

#include "rtl/cosim/fp_units.h"

namespace strata::rtl {
namespace {

constexpr uint64_t kRandomPairs = 100000;
constexpr uint64_t kSeed = 15;

class RtlFpUnit : public ::testing::TestWithParam<FpOp> {};

TEST_P(RtlFpUnit, RandomOperandsMatchHostBitForBit) {
  const FpCompareResult r = compare_fp_unit(GetParam(), random_operands(GetParam(), kRandomPairs, kSeed));
  EXPECT_EQ(r.vectors, kRandomPairs);
  EXPECT_EQ(r.mismatches, 0u) << describe(r, GetParam());
}

TEST_P(RtlFpUnit, EdgeCasesMatchHostBitForBit) {
  const std::vector<OperandPair> pairs = edge_operands(GetParam());
  const FpCompareResult r = compare_fp_unit(GetParam(), pairs);
  EXPECT_EQ(r.vectors, pairs.size());
  EXPECT_GT(r.vectors, 70u * 70u);  // at least all pairs of the special values
  EXPECT_EQ(r.mismatches, 0u) << describe(r, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Units, RtlFpUnit,
                         ::testing::Values(FpOp::kMul, FpOp::kAdd, FpOp::kSub, FpOp::kCmp, FpOp::kMinMax),
                         [](const ::testing::TestParamInfo<FpOp>& p) { return std::string(fp_op_name(p.param)); });

float f(uint32_t u) {
  float x;
  std::memcpy(&x, &u, sizeof x);
  return x;
}

// The comparison rule itself: one ulp off, a number for a NaN or a NaN for a number is a
// mismatch; any NaN for a NaN is not.
TEST(RtlFpHarness, ComparisonRuleRejectsWrongResults) {
  EXPECT_TRUE(fp_results_agree(0x3F800000u, 0x3F800000u));
  EXPECT_FALSE(fp_results_agree(0x3F800001u, 0x3F800000u));
  EXPECT_FALSE(fp_results_agree(0x80000000u, 0x00000000u));  // -0 is not +0
  EXPECT_FALSE(fp_results_agree(0x7FC00000u, 0x7F800000u));  // NaN for inf
  EXPECT_FALSE(fp_results_agree(0x7F800000u, 0xFFC00000u));  // inf for NaN
  EXPECT_TRUE(fp_results_agree(0x7FC00000u, 0xFFC00000u));   // the host's default NaN
  EXPECT_TRUE(fp_results_agree(0x7FC00000u, 0x7F800001u));
}

// Hand-checked results through the units: ties to even, NaN classes, underflow to zero.
TEST(RtlFpHarness, KnownResults) {
  // (1 + 2^-23)^2 = 1 + 2^-22 + 2^-46 rounds to 1 + 2^-22.
  EXPECT_EQ(f(0x3F800001u) * f(0x3F800001u), f(0x3F800002u));
  EXPECT_EQ(compare_fp_unit(FpOp::kMul, {{0x3F800001u, 0x3F800001u}}).mismatches, 0u);
  // 1 + 2^-24 is a tie between 1 and 1 + 2^-23: even is 1.
  EXPECT_EQ(f(0x3F800000u) + f(0x33800000u), 1.0f);
  EXPECT_EQ(compare_fp_unit(FpOp::kAdd, {{0x3F800000u, 0x33800000u}}).mismatches, 0u);
  // inf - inf and 0 * inf are NaNs on both sides.
  EXPECT_EQ(compare_fp_unit(FpOp::kSub, {{0x7F800000u, 0x7F800000u}}).mismatches, 0u);
  EXPECT_EQ(compare_fp_unit(FpOp::kMul, {{0x00000000u, 0xFF800000u}}).mismatches, 0u);
  // Smallest subnormal times 0.5 is a tie that rounds to even: +0.
  EXPECT_EQ(f(0x00000001u) * f(0x3F000000u), 0.0f);
  EXPECT_EQ(compare_fp_unit(FpOp::kMul, {{0x00000001u, 0x3F000000u}}).mismatches, 0u);
}

}  // namespace
}  // namespace strata::rtl
