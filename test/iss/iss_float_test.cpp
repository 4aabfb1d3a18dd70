// The F extension through instructions: rounding modes, flags, NaN and signed-zero rules.
#include "iss_test_support.h"

#include "model/iss/fp_ops.h"

#include <gtest/gtest.h>

namespace strata::iss::testing {
namespace {

using namespace enc;
using fp::kDZ;
using fp::kNV;
using fp::kNX;
using fp::kOF;
using fp::kUF;

constexpr uint32_t kOne = 0x3F800000u, kTwo = 0x40000000u, kHalf = 0x3F000000u;
constexpr uint32_t kPosZero = 0, kNegZero = 0x80000000u;
constexpr uint32_t kPosInf = 0x7F800000u, kNegInf = 0xFF800000u;
constexpr uint32_t kQNaN = 0x7FC00000u, kSNaN = 0x7F800001u, kNaNPayload = 0xFFC12345u;
constexpr uint32_t kMaxFloat = 0x7F7FFFFFu, kMinNormal = 0x00800000u, kMinSubnormal = 0x00000001u;
constexpr uint32_t kTwoPowMinus24 = 0x33800000u;
constexpr uint32_t kRne = 0, kRtz = 1, kRdn = 2, kRup = 3, kRmm = 4, kDyn = 7;

TEST(IssFloat, NeedsFsEnabled) {
  for (uint32_t w : {fadd(4, 1, 2), flw(4, 1, 0), fsw(1, 2, 0), fmv_x_w(4, 1), fcvt_s_w(4, 1)}) {
    Machine m({w});
    const RunResult r = m.run();
    EXPECT_EQ(r.reason, StopReason::kTrap) << std::hex << w;
    EXPECT_EQ(r.cause, cause::kIllegalInstruction);
  }
}

TEST(IssFloat, AddRoundsTiesInEveryMode) {
  // 1 + 2^-24 lies exactly halfway between 1 and the next float.
  const struct {
    uint32_t rm, expected_pos, expected_neg;
  } cases[] = {{kRne, 0x3F800000u, 0xBF800000u},
               {kRtz, 0x3F800000u, 0xBF800000u},
               {kRdn, 0x3F800000u, 0xBF800001u},
               {kRup, 0x3F800001u, 0xBF800000u},
               {kRmm, 0x3F800001u, 0xBF800001u}};
  for (const auto& c : cases) {
    FpOutcome pos = run_fp(fadd(4, 1, 2, c.rm), kOne, kTwoPowMinus24);
    EXPECT_EQ(pos.result, c.expected_pos) << "rm " << c.rm;
    EXPECT_EQ(pos.flags, kNX);
    FpOutcome neg = run_fp(fadd(4, 1, 2, c.rm), kOne | fp::kSign, kTwoPowMinus24 | fp::kSign);
    EXPECT_EQ(neg.result, c.expected_neg) << "rm " << c.rm;
    // the same through frm
    FpOutcome dyn = run_fp(fadd(4, 1, 2, kDyn), kOne, kTwoPowMinus24, 0, c.rm);
    EXPECT_EQ(dyn.result, c.expected_pos) << "frm " << c.rm;
  }
  // 1 + 3 * 2^-25 is above the tie: nearest modes round up, RTZ down.
  EXPECT_EQ(run_fp(fadd(4, 1, 2, kRne), kOne, 0x33C00000u).result, 0x3F800001u);
  EXPECT_EQ(run_fp(fadd(4, 1, 2, kRmm), kOne, 0x33C00000u).result, 0x3F800001u);
  EXPECT_EQ(run_fp(fadd(4, 1, 2, kRtz), kOne, 0x33C00000u).result, 0x3F800000u);
}

TEST(IssFloat, InvalidDynamicRoundingModeIsIllegal) {
  for (uint32_t frm : {5u, 6u, 7u}) {
    FpOutcome o = run_fp(fadd(4, 1, 2, kDyn), kOne, kOne, 0, frm);
    EXPECT_EQ(o.run.reason, StopReason::kTrap) << frm;
    EXPECT_EQ(o.run.cause, cause::kIllegalInstruction);
  }
}

TEST(IssFloat, ExactZeroSumSign) {
  EXPECT_EQ(run_fp(fsub(4, 1, 2, kRne), kOne, kOne).result, kPosZero);
  EXPECT_EQ(run_fp(fsub(4, 1, 2, kRup), kOne, kOne).result, kPosZero);
  EXPECT_EQ(run_fp(fsub(4, 1, 2, kRdn), kOne, kOne).result, kNegZero);
  EXPECT_EQ(run_fp(fadd(4, 1, 2, kRne), kNegZero, kNegZero).result, kNegZero);
  EXPECT_EQ(run_fp(fadd(4, 1, 2, kRne), kNegZero, kPosZero).result, kPosZero);
  EXPECT_EQ(run_fp(fadd(4, 1, 2, kRdn), kNegZero, kPosZero).result, kNegZero);
  EXPECT_EQ(run_fp(fmul(4, 1, 2, kRne), kNegZero, kOne).result, kNegZero);
}

TEST(IssFloat, CanonicalNaNResults) {
  struct Case {
    uint32_t insn, a, b, flags;
  };
  const Case cases[] = {
      {fadd(4, 1, 2), kPosInf, kNegInf, kNV},         {fsub(4, 1, 2), kPosInf, kPosInf, kNV},
      {fmul(4, 1, 2), kPosInf, kPosZero, kNV},        {fdiv(4, 1, 2), kPosZero, kNegZero, kNV},
      {fdiv(4, 1, 2), kPosInf, kNegInf, kNV},         {fsqrt(4, 1), 0xBF800000u, 0, kNV},
      {fsqrt(4, 1), kNegInf, 0, kNV},                 {fadd(4, 1, 2), kNaNPayload, kOne, 0},
      {fmul(4, 1, 2), kOne, kSNaN, kNV},              {fdiv(4, 1, 2), kQNaN, kQNaN, 0},
      {fsqrt(4, 1), kNaNPayload, 0, 0},
  };
  for (const Case& c : cases) {
    FpOutcome o = run_fp(c.insn, c.a, c.b);
    EXPECT_EQ(o.result, fp::kCanonicalNan) << std::hex << c.insn << " " << c.a << " " << c.b;
    EXPECT_EQ(o.flags, c.flags) << std::hex << c.insn << " " << c.a << " " << c.b;
  }
}

TEST(IssFloat, ExceptionFlags) {
  FpOutcome o = run_fp(fdiv(4, 1, 2), kOne, kNegZero);
  EXPECT_EQ(o.result, kNegInf);
  EXPECT_EQ(o.flags, kDZ);
  EXPECT_EQ(run_fp(fdiv(4, 1, 2), kPosInf, kPosZero).flags, 0u);  // inf / 0 is exact
  o = run_fp(fmul(4, 1, 2), kMaxFloat, kTwo);
  EXPECT_EQ(o.result, kPosInf);
  EXPECT_EQ(o.flags, kOF | kNX);
  o = run_fp(fmul(4, 1, 2, kRtz), kMaxFloat, kTwo);
  EXPECT_EQ(o.result, kMaxFloat);  // overflow rounds to the largest finite toward zero
  EXPECT_EQ(o.flags, kOF | kNX);
  o = run_fp(fmul(4, 1, 2, kRdn), kMaxFloat, kTwo);
  EXPECT_EQ(o.result, kMaxFloat);
  o = run_fp(fmul(4, 1, 2, kRdn), kMaxFloat | fp::kSign, kTwo);
  EXPECT_EQ(o.result, kNegInf);
  o = run_fp(fmul(4, 1, 2), kMinNormal, kHalf);
  EXPECT_EQ(o.result, 0x00400000u);  // exact subnormal: no underflow flag
  EXPECT_EQ(o.flags, 0u);
  o = run_fp(fmul(4, 1, 2), 0x00800001u, kHalf);  // inexact subnormal
  EXPECT_EQ(o.result, 0x00400000u);  // tie, to even
  EXPECT_EQ(o.flags, kUF | kNX);
  o = run_fp(fmul(4, 1, 2, kRup), kMinSubnormal, kHalf);
  EXPECT_EQ(o.result, kMinSubnormal);
  EXPECT_EQ(o.flags, kUF | kNX);
  o = run_fp(fmul(4, 1, 2, kRne), kMinSubnormal, kHalf);
  EXPECT_EQ(o.result, kPosZero);
  EXPECT_EQ(o.flags, kUF | kNX);
  // Tininess after rounding: (1 - 2^-23)(2^-126 + 2^-149) = 2^-126 (1 - 2^-46) lies below the
  // normal range but rounds to 2^-126 at full precision, so it is not tiny: no underflow.
  o = run_fp(fmul(4, 1, 2), 0x3F7FFFFEu, 0x00800001u);
  EXPECT_EQ(o.result, kMinNormal);
  EXPECT_EQ(o.flags, kNX);
  // Rounding toward zero it stays below 2^-126: tiny, so underflow.
  o = run_fp(fmul(4, 1, 2, kRtz), 0x3F7FFFFEu, 0x00800001u);
  EXPECT_EQ(o.result, 0x007FFFFFu);
  EXPECT_EQ(o.flags, kUF | kNX);
  // (1 - 2^-24) 2^-126 is exact at full precision, hence tiny; it rounds up to 2^-126.
  o = run_fp(fmul(4, 1, 2), 0x3F7FFFFFu, kMinNormal);
  EXPECT_EQ(o.result, kMinNormal);
  EXPECT_EQ(o.flags, kUF | kNX);
  o = run_fp(fdiv(4, 1, 2), kOne, 0x40400000u);
  EXPECT_EQ(o.result, 0x3EAAAAABu);
  EXPECT_EQ(o.flags, kNX);
  o = run_fp(fsqrt(4, 1), kTwo);
  EXPECT_EQ(o.result, 0x3FB504F3u);
  EXPECT_EQ(o.flags, kNX);
  o = run_fp(fsqrt(4, 1), kNegZero);
  EXPECT_EQ(o.result, kNegZero);
  EXPECT_EQ(o.flags, 0u);
  o = run_fp(fsqrt(4, 1), kMinSubnormal);
  EXPECT_EQ(o.result, 0x1A3504F3u);  // sqrt(2^-149)
  // Flags accrue: an exact operation leaves earlier flags set.
  Machine m({fdiv(4, 1, 2), fadd(5, 1, 1)});
  m.enable_fp();
  m.hart.set_f(1, kOne);
  m.hart.set_f(2, 0x40400000u);
  m.run();
  EXPECT_EQ(m.csr(csr::kFflags), kNX);
}

TEST(IssFloat, FusedMultiplyAddRoundsOnce) {
  // (1 + 2^-12)^2 - (1 + 2^-11) = 2^-24 exactly; rounding the product first would give 0.
  const uint32_t a = 0x3F800800u, c = 0xBF801000u;
  FpOutcome o = run_fp(fmadd(4, 1, 2, 3), a, a, c);
  EXPECT_EQ(o.result, kTwoPowMinus24);
  EXPECT_EQ(o.flags, 0u);
  EXPECT_EQ(run_fp(fmsub(4, 1, 2, 3), a, a, c ^ fp::kSign).result, kTwoPowMinus24);
  EXPECT_EQ(run_fp(fnmsub(4, 1, 2, 3), a, a, c ^ fp::kSign).result, kTwoPowMinus24 | fp::kSign);
  EXPECT_EQ(run_fp(fnmadd(4, 1, 2, 3), a, a, c).result, kTwoPowMinus24 | fp::kSign);
  // signs: fmsub = a*b - c, fnmsub = -(a*b) + c, fnmadd = -(a*b) - c
  EXPECT_EQ(run_fp(fmsub(4, 1, 2, 3), kTwo, kTwo, kOne).result, 0x40400000u);    // 3
  EXPECT_EQ(run_fp(fnmsub(4, 1, 2, 3), kTwo, kTwo, kOne).result, 0xC0400000u);   // -3
  EXPECT_EQ(run_fp(fnmadd(4, 1, 2, 3), kTwo, kTwo, kOne).result, 0xC0A00000u);   // -5
  // inf * 0 + qNaN is invalid even though the addend is a quiet NaN.
  o = run_fp(fmadd(4, 1, 2, 3), kPosInf, kPosZero, kQNaN);
  EXPECT_EQ(o.result, fp::kCanonicalNan);
  EXPECT_EQ(o.flags, kNV);
  o = run_fp(fmadd(4, 1, 2, 3), kPosInf, kOne, kNegInf);
  EXPECT_EQ(o.result, fp::kCanonicalNan);
  EXPECT_EQ(o.flags, kNV);
  // exact zero: -0 only when rounding down
  EXPECT_EQ(run_fp(fmadd(4, 1, 2, 3, kRne), kOne, kOne, kOne | fp::kSign).result, kPosZero);
  EXPECT_EQ(run_fp(fmadd(4, 1, 2, 3, kRdn), kOne, kOne, kOne | fp::kSign).result, kNegZero);
  EXPECT_EQ(run_fp(fmadd(4, 1, 2, 3, kRne), kNegZero, kOne, kNegZero).result, kNegZero);
}

TEST(IssFloat, ConvertToIntegerInEveryMode) {
  struct Case {
    float in;
    int32_t rne, rtz, rdn, rup, rmm;
  };
  const Case cases[] = {
      {2.5f, 2, 2, 2, 3, 3},      {-2.5f, -2, -2, -3, -2, -3},   {3.5f, 4, 3, 3, 4, 4},
      {0.5f, 0, 0, 0, 1, 1},      {-0.5f, 0, 0, -1, 0, -1},      {1.25f, 1, 1, 1, 2, 1},
      {-1.75f, -2, -1, -2, -1, -2}, {7.0f, 7, 7, 7, 7, 7},       {-0.0f, 0, 0, 0, 0, 0},
      {1e-30f, 0, 0, 0, 1, 0},
  };
  for (const Case& c : cases) {
    const int32_t expected[5] = {c.rne, c.rtz, c.rdn, c.rup, c.rmm};
    for (uint32_t rm = 0; rm < 5; ++rm) {
      FpOutcome o = run_fp(fcvt_w_s(4, 1, rm), bits(c.in), 0, 0, 0, true);
      EXPECT_EQ(static_cast<int32_t>(o.result), expected[rm]) << c.in << " rm " << rm;
      EXPECT_EQ(o.flags, static_cast<float>(static_cast<int32_t>(c.in)) == c.in ? 0u : kNX) << c.in;
      FpOutcome dyn = run_fp(fcvt_w_s(4, 1, kDyn), bits(c.in), 0, 0, rm, true);
      EXPECT_EQ(static_cast<int32_t>(dyn.result), expected[rm]) << c.in << " frm " << rm;
    }
  }
}

TEST(IssFloat, ConvertToIntegerSaturates) {
  struct Case {
    uint32_t in;
    uint32_t w, wu;
    uint32_t w_flags, wu_flags;
  };
  const Case cases[] = {
      {kQNaN, 0x7FFFFFFFu, 0xFFFFFFFFu, kNV, kNV},
      {kNaNPayload, 0x7FFFFFFFu, 0xFFFFFFFFu, kNV, kNV},  // sign of a NaN does not matter
      {kPosInf, 0x7FFFFFFFu, 0xFFFFFFFFu, kNV, kNV},
      {kNegInf, 0x80000000u, 0, kNV, kNV},
      {0x4F000000u, 0x7FFFFFFFu, 0x80000000u, kNV, 0},  // 2^31
      {0xCF000000u, 0x80000000u, 0, 0, kNV},             // -2^31
      {0x4F800000u, 0x7FFFFFFFu, 0xFFFFFFFFu, kNV, kNV},  // 2^32
      {0x4F7FFFFFu, 0x7FFFFFFFu, 0xFFFFFF00u, kNV, 0},    // largest float below 2^32
      {0xBF800000u, 0xFFFFFFFFu, 0, 0, kNV},             // -1
      {0xBE800000u, 0, 0, kNX, kNX},                     // -0.25 truncates to 0: valid
  };
  for (const Case& c : cases) {
    FpOutcome w = run_fp(fcvt_w_s(4, 1, kRtz), c.in, 0, 0, 0, true);
    EXPECT_EQ(w.result, c.w) << std::hex << c.in;
    EXPECT_EQ(w.flags, c.w_flags) << std::hex << c.in;
    FpOutcome wu = run_fp(fcvt_wu_s(4, 1, kRtz), c.in, 0, 0, 0, true);
    EXPECT_EQ(wu.result, c.wu) << std::hex << c.in;
    EXPECT_EQ(wu.flags, c.wu_flags) << std::hex << c.in;
  }
  // Rounding decides validity: -0.5 rounds to -1 downward, which is out of range for wu.
  EXPECT_EQ(run_fp(fcvt_wu_s(4, 1, kRdn), 0xBF000000u, 0, 0, 0, true).flags, kNV);
  EXPECT_EQ(run_fp(fcvt_wu_s(4, 1, kRup), 0xBF000000u, 0, 0, 0, true).flags, kNX);
}

TEST(IssFloat, ConvertFromInteger) {
  EXPECT_EQ(run_fp(fcvt_s_w(4, 1, kRne), 16777217u).result, 0x4B800000u);
  EXPECT_EQ(run_fp(fcvt_s_w(4, 1, kRup), 16777217u).result, 0x4B800001u);
  EXPECT_EQ(run_fp(fcvt_s_w(4, 1, kRne), 16777219u).result, 0x4B800002u);  // tie to even (up)
  EXPECT_EQ(run_fp(fcvt_s_w(4, 1, kRmm), 16777217u).result, 0x4B800001u);
  EXPECT_EQ(run_fp(fcvt_s_w(4, 1, kRtz), 16777219u).result, 0x4B800001u);
  EXPECT_EQ(run_fp(fcvt_s_w(4, 1, kRne), 0x80000000u).result, 0xCF000000u);
  EXPECT_EQ(run_fp(fcvt_s_w(4, 1, kRne), 0xFFFFFFFFu).result, 0xBF800000u);
  EXPECT_EQ(run_fp(fcvt_s_w(4, 1, kRdn), 0xFEFFFFFFu).result, 0xCB800001u);  // -16777217 down
  EXPECT_EQ(run_fp(fcvt_s_w(4, 1, kRne), 0).result, kPosZero);
  EXPECT_EQ(run_fp(fcvt_s_w(4, 1, kRdn), 0).result, kPosZero);
  EXPECT_EQ(run_fp(fcvt_s_wu(4, 1, kRne), 0xFFFFFFFFu).result, 0x4F800000u);
  EXPECT_EQ(run_fp(fcvt_s_wu(4, 1, kRtz), 0xFFFFFFFFu).result, 0x4F7FFFFFu);
  FpOutcome o = run_fp(fcvt_s_w(4, 1, kRne), 16777217u);
  EXPECT_EQ(o.flags, kNX);
  EXPECT_EQ(run_fp(fcvt_s_w(4, 1, kRne), 16777216u).flags, 0u);
}

TEST(IssFloat, MinMaxSignedZerosAndNaNs) {
  EXPECT_EQ(run_fp(fmin(4, 1, 2), kPosZero, kNegZero).result, kNegZero);
  EXPECT_EQ(run_fp(fmin(4, 1, 2), kNegZero, kPosZero).result, kNegZero);
  EXPECT_EQ(run_fp(fmax(4, 1, 2), kNegZero, kPosZero).result, kPosZero);
  EXPECT_EQ(run_fp(fmax(4, 1, 2), kPosZero, kNegZero).result, kPosZero);
  FpOutcome o = run_fp(fmin(4, 1, 2), kQNaN, kTwo);
  EXPECT_EQ(o.result, kTwo);
  EXPECT_EQ(o.flags, 0u);
  o = run_fp(fmax(4, 1, 2), kTwo, kSNaN);
  EXPECT_EQ(o.result, kTwo);
  EXPECT_EQ(o.flags, kNV);
  o = run_fp(fmin(4, 1, 2), kNaNPayload, kSNaN);
  EXPECT_EQ(o.result, fp::kCanonicalNan);
  EXPECT_EQ(o.flags, kNV);
  EXPECT_EQ(run_fp(fmin(4, 1, 2), kNegInf, kOne).result, kNegInf);
  EXPECT_EQ(run_fp(fmax(4, 1, 2), 0xC0000000u, 0xBF800000u).result, 0xBF800000u);
}

TEST(IssFloat, ComparisonsSignalingRules) {
  struct Case {
    uint32_t a, b;
    uint32_t eq, lt, le;
    uint32_t eq_flags, lt_flags;
  };
  const Case cases[] = {
      {kOne, kTwo, 0, 1, 1, 0, 0},         {kTwo, kOne, 0, 0, 0, 0, 0},
      {kNegZero, kPosZero, 1, 0, 1, 0, 0}, {kQNaN, kOne, 0, 0, 0, 0, kNV},
      {kOne, kQNaN, 0, 0, 0, 0, kNV},      {kSNaN, kOne, 0, 0, 0, kNV, kNV},
      {kNegInf, kPosInf, 0, 1, 1, 0, 0},
  };
  for (const Case& c : cases) {
    FpOutcome eq = run_fp(feq(4, 1, 2), c.a, c.b, 0, 0, true);
    FpOutcome lt = run_fp(flt(4, 1, 2), c.a, c.b, 0, 0, true);
    FpOutcome le = run_fp(fle(4, 1, 2), c.a, c.b, 0, 0, true);
    EXPECT_EQ(eq.result, c.eq) << std::hex << c.a << " " << c.b;
    EXPECT_EQ(lt.result, c.lt) << std::hex << c.a << " " << c.b;
    EXPECT_EQ(le.result, c.le) << std::hex << c.a << " " << c.b;
    EXPECT_EQ(eq.flags, c.eq_flags) << std::hex << c.a << " " << c.b;
    EXPECT_EQ(lt.flags, c.lt_flags) << std::hex << c.a << " " << c.b;
    EXPECT_EQ(le.flags, c.lt_flags) << std::hex << c.a << " " << c.b;
  }
}

TEST(IssFloat, ClassifyEveryCategory) {
  const std::pair<uint32_t, uint32_t> cases[] = {
      {kNegInf, 1u << 0}, {0xBF800000u, 1u << 1}, {0x80000001u, 1u << 2}, {kNegZero, 1u << 3},
      {kPosZero, 1u << 4}, {kMinSubnormal, 1u << 5}, {kOne, 1u << 6}, {kPosInf, 1u << 7},
      {kSNaN, 1u << 8}, {kQNaN, 1u << 9}, {kNaNPayload, 1u << 9}, {0xFF800001u, 1u << 8}};
  for (const auto& [in, expected] : cases) {
    FpOutcome o = run_fp(fclass(4, 1), in, 0, 0, 0, true);
    EXPECT_EQ(o.result, expected) << std::hex << in;
    EXPECT_EQ(o.flags, 0u);
  }
}

TEST(IssFloat, SignInjectionAndMovesKeepNaNPayloads) {
  EXPECT_EQ(run_fp(fsgnj(4, 1, 2), kOne, 0x80000000u).result, 0xBF800000u);
  EXPECT_EQ(run_fp(fsgnjn(4, 1, 2), kOne, 0x80000000u).result, kOne);
  EXPECT_EQ(run_fp(fsgnjn(4, 1, 1), kOne).result, 0xBF800000u);  // fneg
  EXPECT_EQ(run_fp(fsgnjx(4, 1, 2), 0xBF800000u, 0x80000000u).result, kOne);
  EXPECT_EQ(run_fp(fsgnjx(4, 1, 1), 0xBF800000u).result, kOne);  // fabs
  FpOutcome o = run_fp(fsgnj(4, 1, 2), kSNaN, 0x80000000u);
  EXPECT_EQ(o.result, kSNaN | fp::kSign);  // not canonicalized, no flags
  EXPECT_EQ(o.flags, 0u);
  EXPECT_EQ(run_fp(fmv_x_w(4, 1), kNaNPayload, 0, 0, 0, true).result, kNaNPayload);
  EXPECT_EQ(run_fp(fmv_w_x(4, 1), kSNaN).result, kSNaN);

  Machine m({flw(4, 1, 0), fsw(4, 1, 4)});
  m.enable_fp();
  m.hart.set_x(1, Machine::kDataBase);
  m.memory.write32(Machine::kDataBase, kSNaN);
  ASSERT_EQ(m.run().reason, StopReason::kHalt);
  EXPECT_EQ(m.hart.f(4), kSNaN);
  EXPECT_EQ(m.memory.read32(Machine::kDataBase + 4), kSNaN);
  EXPECT_EQ(m.csr(csr::kFflags), 0u);
}

TEST(IssFloat, FloatLoadStoreFaults) {
  Machine m({flw(4, 1, 2)});
  m.enable_fp();
  m.hart.set_x(1, Machine::kDataBase);
  const RunResult r = m.run();
  EXPECT_EQ(r.cause, cause::kLoadMisaligned);
  EXPECT_EQ(r.tval, Machine::kDataBase + 2);
}

}  // namespace
}  // namespace strata::iss::testing
