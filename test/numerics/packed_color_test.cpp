// The compact path state's packed RGB (firmware/kernels/packed_color.h): exact where the value
// is representable, within 2^-13 of the largest channel otherwise, idempotent (a value that
// went through a ray once goes through again unchanged), and bounded on hostile values.
#include "firmware/kernels/packed_color.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace strata::kernels {
namespace {

bool same_bits(Vec3f a, Vec3f b) { return std::memcmp(&a, &b, sizeof a) == 0; }

float largest(Vec3f v) { return std::max(v.x, std::max(v.y, v.z)); }

// Random non-negative triples over the whole float range, with channels of very different
// magnitudes in one triple, subnormals and exact zeros among them.
Vec3f random_color(std::mt19937& rng) {
  std::uniform_int_distribution<uint32_t> bits(0, 0x7F7FFFFFu);
  std::uniform_int_distribution<int> kind(0, 9);
  auto channel = [&] {
    switch (kind(rng)) {
      case 0: return 0.0f;
      case 1: return bits_float(bits(rng) & 0x7FFFFFu);  // subnormal
      case 2: return std::ldexp(1.0f, int(bits(rng) % 40) - 20);
      default: return bits_float(bits(rng));
    }
  };
  return {channel(), channel(), channel()};
}

TEST(PackedColor, RepresentableValuesAreExact) {
  for (const Vec3f v : {Vec3f{0.0f, 0.0f, 0.0f}, Vec3f{1.0f, 1.0f, 1.0f}, Vec3f{1.0f, 0.5f, 0.25f},
                        Vec3f{8191.0f, 1.0f, 0.0f}, Vec3f{0.75f, 0.125f, 0.001953125f},
                        Vec3f{std::ldexp(1.0f, -138), 0.0f, std::ldexp(3.0f, -138)},  // subnormal
                        Vec3f{std::ldexp(4097.0f, 100), std::ldexp(1.0f, 100), 0.0f}})
    EXPECT_TRUE(same_bits(quantize_color(v), v)) << v.x << " " << v.y << " " << v.z;
}

TEST(PackedColor, ErrorIsWithinHalfAUnitOfTheLargestChannel) {
  std::mt19937 rng(12345);
  for (int i = 0; i < 200000; ++i) {
    const Vec3f v = random_color(rng);
    const Vec3f q = quantize_color(v);
    const float m = largest(v);
    if (m >= std::ldexp(8191.5f, 115)) continue;  // saturates (HostileValuesStayBounded...)
    // Half a unit of a 13-bit mantissa whose top bit is at m's exponent, or one above it when
    // the largest channel rounds up to the next power of two: 2^(e - 12) for m in [2^e, 2^(e+1)).
    const double bound = m == 0.0f ? 0.0 : std::ldexp(1.0, std::ilogb(std::max(m, std::ldexp(1.0f, -126))) - 12);
    for (const auto& [a, b] : {std::pair{v.x, q.x}, std::pair{v.y, q.y}, std::pair{v.z, q.z}})
      ASSERT_LE(std::fabs(double(a) - double(b)), bound) << a << " -> " << b << " (largest " << m << ")";
  }
}

TEST(PackedColor, QuantizingTwiceChangesNothing) {
  std::mt19937 rng(777);
  for (int i = 0; i < 200000; ++i) {
    const Vec3f q = quantize_color(random_color(rng));
    const Vec3f qq = quantize_color(q);
    ASSERT_TRUE(same_bits(q, qq)) << q.x << " " << q.y << " " << q.z;
  }
}

TEST(PackedColor, RoundingUpToTheNextPowerOfTwoTakesTheNextExponent) {
  const float just_below_two = bits_float(0x3FFFFFFFu);  // 1.99999988
  const Vec3f q = quantize_color({just_below_two, 1.0f, 0.0f});
  EXPECT_EQ(q.x, 2.0f);
  EXPECT_EQ(q.y, 1.0f);
  EXPECT_TRUE(same_bits(quantize_color(q), q));
}

TEST(PackedColor, HostileValuesStayBoundedAndNonNegative) {
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Vec3f q = quantize_color({-1.0f, nan, inf});
  EXPECT_EQ(q.x, 0.0f);
  EXPECT_EQ(q.y, 0.0f);
  EXPECT_TRUE(std::isfinite(q.z));
  EXPECT_EQ(q.z, std::ldexp(8191.0f, 115));  // the largest encodable value
  EXPECT_FALSE(std::signbit(quantize_color({-0.0f, 0.0f, 0.0f}).x));
  const Vec3f big = quantize_color({std::numeric_limits<float>::max(), 1.0f, 0.0f});
  EXPECT_TRUE(std::isfinite(big.x));
  EXPECT_EQ(big.y, 0.0f);  // far below half a unit of the largest channel
}

// pack(unpack(pack(v))) == pack(v): a colour copied or repacked keeps its bits.
TEST(PackedColor, PackingADecodedColourGivesTheSameBits) {
  std::mt19937 rng(4242);
  for (int i = 0; i < 200000; ++i) {
    const PackedColor p = pack_color(random_color(rng));
    const PackedColor q = pack_color(unpack_color(p));
    ASSERT_TRUE(p.w[0] == q.w[0] && p.w[1] == q.w[1] && p.w[2] == q.w[2]);
  }
  const PackedColor tiny = pack_color({bits_float(1u), 0.0f, 0.0f});  // rounds to zero
  EXPECT_EQ(tiny.w[0] | tiny.w[1] | tiny.w[2], 0);
}

TEST(PackedColor, TheLayoutUsesFortySevenBits) {
  std::mt19937 rng(99);
  for (int i = 0; i < 10000; ++i) {
    const PackedColor p = pack_color(random_color(rng));
    ASSERT_EQ(p.w[2] & 0x8000u, 0u);  // bit 47 stays zero
  }
  static_assert(sizeof(PackedColor) == 6, "48 bits");
}

}  // namespace
}  // namespace strata::kernels
