// The ISS's binary32 arithmetic against the host FPU on a few hundred thousand operands:
// results and all five exception flags, in the four IEEE rounding modes the host has. Both
// the inline fast paths and the soft implementation are checked. RMM, which hosts lack, is
// checked against an exact tie test built from the host's other modes.
#include "iss_test_support.h"

#include "model/iss/fp_ops.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <random>

namespace strata::iss::testing {
namespace {

constexpr int kHostModes[4] = {FE_TONEAREST, FE_TOWARDZERO, FE_DOWNWARD, FE_UPWARD};  // rm 0..3
constexpr int kSamples = 60000;

uint32_t host_flags() {
  const int e = std::fetestexcept(FE_ALL_EXCEPT);
  return ((e & FE_INVALID) ? fp::kNV : 0u) | ((e & FE_DIVBYZERO) ? fp::kDZ : 0u) |
         ((e & FE_OVERFLOW) ? fp::kOF : 0u) | ((e & FE_UNDERFLOW) ? fp::kUF : 0u) |
         ((e & FE_INEXACT) ? fp::kNX : 0u);
}

struct Outcome {
  uint32_t bits;
  uint32_t flags;
  bool operator==(const Outcome& o) const { return bits == o.bits && flags == o.flags; }
};

std::ostream& operator<<(std::ostream& os, const Outcome& o) {
  return os << std::hex << "{0x" << o.bits << ", flags 0x" << o.flags << "}" << std::dec;
}

// Runs f under a host rounding mode. Operands pass through volatiles, so the operation
// happens at run time between fesetround and fetestexcept.
template <class F>
Outcome on_host(int mode, F f) {
  std::fesetround(mode);
  std::feclearexcept(FE_ALL_EXCEPT);
  const uint32_t r = f();
  const uint32_t flags = host_flags();
  std::fesetround(FE_TONEAREST);
  return {r, flags};
}

// RISC-V returns the canonical NaN where the host propagates an operand's payload.
Outcome canonical(Outcome o) {
  if ((o.bits & 0x7FFFFFFFu) > 0x7F800000u) o.bits = fp::kCanonicalNan;
  return o;
}

// Operands that exercise the corners: specials, subnormals, values near overflow, operand
// pairs with close exponents (cancellation, ties), few-bit mantissas (exact results).
class OperandSource {
 public:
  explicit OperandSource(uint32_t seed) : rng_(seed) {}

  uint32_t draw() { return static_cast<uint32_t>(rng_()); }

  uint32_t next() {
    static constexpr uint32_t kSpecial[] = {0x00000000u, 0x80000000u, 0x7F800000u, 0xFF800000u, 0x7FC00000u,
                                            0x7F800001u, 0xFFC00001u, 0x00000001u, 0x807FFFFFu, 0x00800000u,
                                            0x7F7FFFFFu, 0xFF7FFFFFu, 0x3F800000u, 0xBF800000u, 0x3F000000u,
                                            0x4F000000u, 0xCF000000u, 0x4F800000u, 0x3F7FFFFFu, 0x33800000u};
    const uint32_t pick = draw() % 8;
    const uint32_t sign = (draw() & 1u) << 31;
    switch (pick) {
      case 0: return kSpecial[draw() % (sizeof kSpecial / sizeof kSpecial[0])];
      case 1: return draw();  // any bit pattern
      case 2: return sign | (draw() & 0x007FFFFFu);  // subnormal
      case 3: return sign | ((250u + draw() % 5) << 23) | (draw() & 0x7FFFFFu);  // near overflow
      case 4: return sign | ((1u + draw() % 30) << 23) | (draw() & 0x7FFFFFu);   // near underflow
      case 5: return sign | ((120u + draw() % 16) << 23) | ((draw() & 0xFu) << 19);  // few mantissa bits
      default: return sign | ((100u + draw() % 56) << 23) | (draw() & 0x7FFFFFu);  // ordinary
    }
  }
  // A second operand close in exponent to a, so sums cancel and round at the last bit.
  uint32_t near(uint32_t a) {
    if (draw() % 2) return next();
    const uint32_t e = (a >> 23) & 0xFFu;
    if (e == 0 || e == 0xFF) return next();
    const int delta = static_cast<int>(draw() % 27) - 2;
    const int ne = std::clamp(static_cast<int>(e) - delta, 1, 254);
    return ((draw() & 1u) << 31) | (static_cast<uint32_t>(ne) << 23) | (draw() & 0x7FFFFFu);
  }
  uint32_t integer() {
    switch (draw() % 3) {
      case 0: return draw();
      case 1: return draw() >> (draw() % 32);
      default: return static_cast<uint32_t>(-static_cast<int32_t>(draw() >> (draw() % 32)));
    }
  }

 private:
  std::mt19937 rng_;
};

using Binary = uint32_t (*)(uint32_t, uint32_t, unsigned, uint32_t&);

void check_binary(const char* name, Binary fast, Binary soft, float (*host)(float, float)) {
  OperandSource src(1234);
  for (int i = 0; i < kSamples; ++i) {
    const uint32_t a = src.next(), b = src.near(a);
    for (unsigned rm = 0; rm < 4; ++rm) {
      const Outcome expected = canonical(on_host(kHostModes[rm], [&] {
        volatile float va = value(a), vb = value(b);
        volatile float r = host(va, vb);
        return bits(r);
      }));
      Outcome got{0, 0};
      got.bits = fast(a, b, rm, got.flags);
      ASSERT_EQ(got, expected) << name << std::hex << " a=0x" << a << " b=0x" << b << " rm " << rm;
      Outcome got_soft{0, 0};
      got_soft.bits = soft(a, b, rm, got_soft.flags);
      ASSERT_EQ(got_soft, expected) << "soft " << name << std::hex << " a=0x" << a << " b=0x" << b << " rm " << rm;
    }
  }
}

TEST(IssFpReference, AddMatchesHost) {
  check_binary("add", fp::add, fp::soft::add, [](float x, float y) { return x + y; });
}
TEST(IssFpReference, SubMatchesHost) {
  check_binary("sub", fp::sub, fp::soft::sub, [](float x, float y) { return x - y; });
}
TEST(IssFpReference, MulMatchesHost) {
  check_binary("mul", fp::mul, fp::soft::mul, [](float x, float y) { return x * y; });
}
TEST(IssFpReference, DivMatchesHost) {
  check_binary("div", fp::div, fp::soft::div, [](float x, float y) { return x / y; });
}

TEST(IssFpReference, SqrtMatchesHost) {
  OperandSource src(99);
  for (int i = 0; i < kSamples; ++i) {
    const uint32_t a = src.next() & ((i % 4) ? 0x7FFFFFFFu : 0xFFFFFFFFu);  // mostly non-negative
    for (unsigned rm = 0; rm < 4; ++rm) {
      const Outcome expected = canonical(on_host(kHostModes[rm], [&] {
        volatile float va = value(a);
        volatile float r = std::sqrt(static_cast<float>(va));
        return bits(r);
      }));
      Outcome got{0, 0}, got_soft{0, 0};
      got.bits = fp::sqrt(a, rm, got.flags);
      got_soft.bits = fp::soft::sqrt(a, rm, got_soft.flags);
      ASSERT_EQ(got, expected) << std::hex << "sqrt a=0x" << a << " rm " << rm;
      ASSERT_EQ(got_soft, expected) << std::hex << "soft sqrt a=0x" << a << " rm " << rm;
    }
  }
}

TEST(IssFpReference, FusedMultiplyAddMatchesHost) {
  OperandSource src(7);
  for (int i = 0; i < kSamples; ++i) {
    const uint32_t a = src.next(), b = src.next();
    // an addend near the product, so the sum cancels
    const uint32_t c = (i % 2) ? src.near(bits(value(a) * value(b))) : src.next();
    for (unsigned rm = 0; rm < 4; ++rm) {
      const Outcome expected = canonical(on_host(kHostModes[rm], [&] {
        volatile float va = value(a), vb = value(b), vc = value(c);
        volatile float r = std::fma(static_cast<float>(va), static_cast<float>(vb), static_cast<float>(vc));
        return bits(r);
      }));
      Outcome got{0, 0};
      got.bits = fp::fma(a, b, c, rm, got.flags);
      // The host reports NV for inf*0 + qNaN only on some paths; the spec requires it.
      const bool inf_times_zero = ((a & 0x7FFFFFFFu) == 0x7F800000u && (b & 0x7FFFFFFFu) == 0) ||
                                  ((b & 0x7FFFFFFFu) == 0x7F800000u && (a & 0x7FFFFFFFu) == 0);
      Outcome want = expected;
      if (inf_times_zero) want.flags |= fp::kNV;
      ASSERT_EQ(got, want) << std::hex << "fma a=0x" << a << " b=0x" << b << " c=0x" << c << " rm " << rm;
    }
  }
}

TEST(IssFpReference, IntegerToFloatMatchesHost) {
  OperandSource src(5);
  for (int i = 0; i < kSamples; ++i) {
    const uint32_t v = src.integer();
    for (unsigned rm = 0; rm < 4; ++rm) {
      const Outcome signed_expected = on_host(kHostModes[rm], [&] {
        volatile int32_t vv = static_cast<int32_t>(v);
        volatile float r = static_cast<float>(vv);
        return bits(r);
      });
      const Outcome unsigned_expected = on_host(kHostModes[rm], [&] {
        volatile uint32_t vv = v;
        volatile float r = static_cast<float>(vv);
        return bits(r);
      });
      Outcome got{0, 0}, got_u{0, 0};
      got.bits = fp::from_int32(v, rm, got.flags);
      got_u.bits = fp::from_uint32(v, rm, got_u.flags);
      ASSERT_EQ(got, signed_expected) << std::hex << "fcvt.s.w 0x" << v << " rm " << rm;
      ASSERT_EQ(got_u, unsigned_expected) << std::hex << "fcvt.s.wu 0x" << v << " rm " << rm;
    }
  }
}

// RISC-V conversions saturate; the reference rounds with the host's nearbyint in the same mode.
Outcome reference_to_int(uint32_t a, int mode, bool is_unsigned) {
  const double lo = is_unsigned ? 0.0 : -2147483648.0, hi = is_unsigned ? 4294967295.0 : 2147483647.0;
  const uint32_t max = is_unsigned ? 0xFFFFFFFFu : 0x7FFFFFFFu, min = is_unsigned ? 0u : 0x80000000u;
  const float f = value(a);
  if (std::isnan(f)) return {max, fp::kNV};
  std::fesetround(mode);
  const double r = std::nearbyint(static_cast<double>(f));
  std::fesetround(FE_TONEAREST);
  if (r > hi) return {max, fp::kNV};
  if (r < lo) return {min, fp::kNV};
  const uint32_t bits_out =
      is_unsigned ? static_cast<uint32_t>(r) : static_cast<uint32_t>(static_cast<int32_t>(r));
  return {bits_out, r != static_cast<double>(f) ? fp::kNX : 0u};
}

TEST(IssFpReference, FloatToIntegerMatchesReference) {
  OperandSource src(11);
  for (int i = 0; i < kSamples; ++i) {
    uint32_t a = src.next();
    if (i % 3 == 0) a = bits(static_cast<float>(static_cast<int32_t>(src.integer()) % 100000) / 8.0f);  // halves, ties
    for (unsigned rm = 0; rm < 4; ++rm) {
      Outcome got{0, 0}, got_u{0, 0};
      got.bits = fp::to_int32(a, rm, got.flags);
      got_u.bits = fp::to_uint32(a, rm, got_u.flags);
      ASSERT_EQ(got, reference_to_int(a, kHostModes[rm], false)) << std::hex << "fcvt.w.s 0x" << a << " rm " << rm;
      ASSERT_EQ(got_u, reference_to_int(a, kHostModes[rm], true)) << std::hex << "fcvt.wu.s 0x" << a << " rm " << rm;
    }
    // RMM: std::round rounds halfway cases away from zero.
    const float f = value(a);
    if (!std::isnan(f) && std::fabs(f) < 2.0e9f) {
      uint32_t flags = 0;
      const double r = std::round(static_cast<double>(f));
      EXPECT_EQ(fp::to_int32(a, fp::kRmm, flags), static_cast<uint32_t>(static_cast<int32_t>(r))) << f;
      EXPECT_EQ(flags, r != static_cast<double>(f) ? fp::kNX : 0u) << f;
    }
  }
}

// v is an exact value; RMM differs from RNE only when v lies exactly halfway between floats.
Outcome reference_rmm(double v) {
  const Outcome nearest = on_host(FE_TONEAREST, [&] {
    volatile double vv = v;
    volatile float r = static_cast<float>(vv);
    return bits(r);
  });
  std::fesetround(FE_TOWARDZERO);
  volatile double vv = v;
  const float toward_zero = static_cast<float>(vv);
  std::fesetround(FE_TONEAREST);
  if (std::isinf(toward_zero) || std::fabs(toward_zero) == 3.4028234663852886e38f) return nearest;
  const float away = std::nextafter(toward_zero, std::copysign(INFINITY, static_cast<float>(v)));
  const double midpoint = (static_cast<double>(toward_zero) + static_cast<double>(away)) / 2.0;
  if (v != midpoint) return nearest;
  Outcome tie = nearest;
  tie.bits = bits(away);
  return tie;
}

TEST(IssFpReference, RoundToNearestMaxMagnitude) {
  OperandSource src(21);
  int ties = 0;
  for (int i = 0; i < kSamples; ++i) {
    const uint32_t a = src.next(), b = src.near(a);
    const float x = value(a), y = value(b);
    if (!std::isfinite(x) || !std::isfinite(y)) continue;
    // products of binary32 values are exact in binary64
    const double product = static_cast<double>(x) * static_cast<double>(y);
    if (product != 0.0) {
      Outcome got{0, 0};
      got.bits = fp::mul(a, b, fp::kRmm, got.flags);
      const Outcome want = reference_rmm(product);
      ASSERT_EQ(got.bits, want.bits) << std::hex << "mul rmm a=0x" << a << " b=0x" << b;
      if (got.bits == bits(static_cast<float>(product))) {
        ASSERT_EQ(got.flags, want.flags) << std::hex << "mul rmm a=0x" << a << " b=0x" << b;
      }
      ties += want.bits != on_host(FE_TONEAREST, [&] { return bits(static_cast<float>(product)); }).bits;
    }
    const double dx = x, dy = y, sum = dx + dy, back = sum - dx;
    const double sum_error = (dx - (sum - back)) + (dy - back);  // TwoSum
    if (sum != 0.0 && sum_error == 0.0) {  // the sum is exact in binary64
      Outcome got{0, 0};
      got.bits = fp::add(a, b, fp::kRmm, got.flags);
      ASSERT_EQ(got.bits, reference_rmm(sum).bits) << std::hex << "add rmm a=0x" << a << " b=0x" << b;
    }
    // Quotients and roots of binary32 values are never exactly halfway at normal results.
    Outcome ne{0, 0}, mm{0, 0};
    ne.bits = fp::div(a, b, fp::kRne, ne.flags);
    mm.bits = fp::div(a, b, fp::kRmm, mm.flags);
    if ((ne.bits & 0x7F800000u) != 0) {
      ASSERT_EQ(mm, ne) << std::hex << "div rmm a=0x" << a << " b=0x" << b;
    }
  }
  EXPECT_GT(ties, 10);  // the operand source does produce ties
}

}  // namespace
}  // namespace strata::iss::testing
