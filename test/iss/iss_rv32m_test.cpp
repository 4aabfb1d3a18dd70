// RV32M: multiply and divide, including the cases C leaves undefined.
#include "iss_test_support.h"

#include <gtest/gtest.h>

namespace strata::iss::testing {
namespace {

using namespace enc;

constexpr uint32_t kMin = 0x80000000u, kMinus1 = 0xFFFFFFFFu;

TEST(IssRv32m, Multiply) {
  EXPECT_EQ(run_rr(mul, 0x7FFFFFFFu, 2), 0xFFFFFFFEu);
  EXPECT_EQ(run_rr(mul, kMinus1, kMinus1), 1u);
  EXPECT_EQ(run_rr(mul, 0x12345678u, 0x9ABCDEF0u), 0x242D2080u);
  EXPECT_EQ(run_rr(mulh, kMin, kMin), 0x40000000u);
  EXPECT_EQ(run_rr(mulh, kMin, 1), kMinus1);
  EXPECT_EQ(run_rr(mulh, kMinus1, kMinus1), 0u);
  EXPECT_EQ(run_rr(mulh, 0x7FFFFFFFu, 0x7FFFFFFFu), 0x3FFFFFFFu);
  EXPECT_EQ(run_rr(mulhu, kMinus1, kMinus1), 0xFFFFFFFEu);
  EXPECT_EQ(run_rr(mulhu, kMin, 2), 1u);
  EXPECT_EQ(run_rr(mulhsu, kMinus1, kMinus1), kMinus1);  // -1 * (2^32 - 1)
  EXPECT_EQ(run_rr(mulhsu, kMin, kMinus1), kMin);
  EXPECT_EQ(run_rr(mulhsu, 1, kMinus1), 0u);
  EXPECT_EQ(run_rr(mulhsu, 2, kMin), 1u);
}

TEST(IssRv32m, DivideByZero) {
  EXPECT_EQ(run_rr(div, 7, 0), kMinus1);
  EXPECT_EQ(run_rr(div, kMin, 0), kMinus1);
  EXPECT_EQ(run_rr(divu, 7, 0), 0xFFFFFFFFu);
  EXPECT_EQ(run_rr(rem, 7, 0), 7u);
  EXPECT_EQ(run_rr(rem, kMin, 0), kMin);
  EXPECT_EQ(run_rr(remu, 0xFFFFFFF9u, 0), 0xFFFFFFF9u);
}

TEST(IssRv32m, SignedOverflow) {
  EXPECT_EQ(run_rr(div, kMin, kMinus1), kMin);
  EXPECT_EQ(run_rr(rem, kMin, kMinus1), 0u);
  EXPECT_EQ(run_rr(divu, kMin, kMinus1), 0u);
  EXPECT_EQ(run_rr(remu, kMin, kMinus1), kMin);
}

TEST(IssRv32m, RoundsTowardZero) {
  EXPECT_EQ(run_rr(div, static_cast<uint32_t>(-7), 2), static_cast<uint32_t>(-3));
  EXPECT_EQ(run_rr(rem, static_cast<uint32_t>(-7), 2), static_cast<uint32_t>(-1));
  EXPECT_EQ(run_rr(div, 7, static_cast<uint32_t>(-2)), static_cast<uint32_t>(-3));
  EXPECT_EQ(run_rr(rem, 7, static_cast<uint32_t>(-2)), 1u);
  EXPECT_EQ(run_rr(div, static_cast<uint32_t>(-7), static_cast<uint32_t>(-2)), 3u);
  EXPECT_EQ(run_rr(rem, static_cast<uint32_t>(-7), static_cast<uint32_t>(-2)), static_cast<uint32_t>(-1));
  EXPECT_EQ(run_rr(divu, 0xFFFFFFFEu, 3), 0x55555554u);
  EXPECT_EQ(run_rr(remu, 0xFFFFFFFEu, 3), 2u);
  EXPECT_EQ(run_rr(div, kMin, 2), 0xC0000000u);
}

}  // namespace
}  // namespace strata::iss::testing
