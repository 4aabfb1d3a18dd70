// A non-negative RGB triple in 48 bits: one shared 8-bit exponent and three 13-bit mantissas.
// The compact path state (streams_compact_kernel.h) keeps a path's throughput and radiance in
// its ray in this form, so that a ray with everything its path needs fits 64 bytes.
//
//   value of channel i = m_i * 2^(E - 139)   (E = 0: all channels 0)
//   bits: m0 0..12, m1 13..25, m2 26..38, E 39..46, bit 47 zero; stored as three 16-bit words
//
// Encoding: E is the biased float exponent of the largest channel (1 if it is subnormal), so the
// largest mantissa lies in [2^12, 2^13); every mantissa is its channel scaled by 2^(139 - E) and
// rounded half up, in integer arithmetic on the float's bits (bit-identical on RV32 and the
// host). A largest mantissa that rounds to 2^13 takes E + 1, and all are rounded again from the
// floats, so each is rounded once. Decoding multiplies a 13-bit integer by a power of two, which
// is exact. Hence quantize(quantize(v)) == quantize(v): a value that went through a ray once
// goes through again unchanged.
//
// Error: each channel within half a unit, 2^(E - 140): for a largest channel in [2^e, 2^(e+1)),
// at most 2^(e - 13), or 2^(e - 12) when it rounded up to 2^(e+1). The smaller channels lose
// relative precision as they fall below the largest; their absolute error is that bound. Out of range: a negative or NaN channel encodes as 0; +inf and values that round past
// the largest float saturate at (2^13 - 1) * 2^115 (about 3.4e38).
#pragma once

#include <stdint.h>

#include "firmware/common/float_bits.h"
#include "firmware/common/vec3.h"

namespace strata::kernels {

struct PackedColor {
  uint16_t w[3];
};

constexpr uint32_t kPackedMantissaBits = 13;
constexpr uint32_t kPackedMantissaMax = (1u << kPackedMantissaBits) - 1;

namespace packed_detail {

// A channel as significand * 2^(exponent - 150), exponent in 1..254 (subnormals at 1). Negative
// and NaN read as 0, +inf as the largest float.
struct Channel {
  uint32_t significand;
  uint32_t exponent;
};

inline Channel channel(float f) {
  uint32_t u = float_bits(f);
  if (u >> 31) return {0, 1};  // negative (or -0, or a negative NaN)
  uint32_t e = u >> 23;
  if (e == 255) {
    if (u & 0x7FFFFFu) return {0, 1};  // NaN
    u = 0x7F7FFFFFu;                    // +inf: the largest float
    e = 254;
  }
  const uint32_t fraction = u & 0x7FFFFFu;
  if (e == 0) return {fraction, 1};
  return {fraction | 0x800000u, e};
}

// round(significand * 2^(exponent - 150) * 2^(139 - shared)), half up; shared >= exponent.
inline uint32_t mantissa(Channel c, uint32_t shared) {
  const uint32_t shift = shared - c.exponent + 11;  // >= 11
  if (shift >= 25) return 0;  // below half a unit: significand < 2^24
  return (c.significand + (1u << (shift - 1))) >> shift;
}

}  // namespace packed_detail

inline PackedColor pack_color(Vec3f v) {
  using namespace packed_detail;
  const Channel c[3] = {channel(v.x), channel(v.y), channel(v.z)};
  // The largest channel: with the exponents equal, the larger significand.
  uint32_t big = 0;
  for (uint32_t i = 1; i < 3; ++i)
    if (c[i].exponent > c[big].exponent ||
        (c[i].exponent == c[big].exponent && c[i].significand > c[big].significand))
      big = i;
  uint32_t m[3] = {0, 0, 0};
  uint32_t shared = 0;
  if (c[big].significand != 0) {
    shared = c[big].exponent;
    // Rounded up to 2^13: the next exponent, unless that is past the largest float, where the
    // mantissas saturate instead.
    if (mantissa(c[big], shared) > kPackedMantissaMax && shared < 254) ++shared;
    for (uint32_t i = 0; i < 3; ++i) {
      m[i] = mantissa(c[i], shared);
      if (m[i] > kPackedMantissaMax) m[i] = kPackedMantissaMax;
    }
    if ((m[0] | m[1] | m[2]) == 0) shared = 0;  // all below half a unit: one encoding of zero
  }
  const uint32_t lo = m[0] | (m[1] << 13) | ((m[2] & 0x3Fu) << 26);
  const uint32_t hi = (m[2] >> 6) | (shared << 7);
  return {{uint16_t(lo & 0xFFFFu), uint16_t(lo >> 16), uint16_t(hi)}};
}

inline Vec3f unpack_color(PackedColor p) {
  const uint32_t lo = uint32_t(p.w[0]) | (uint32_t(p.w[1]) << 16);
  const uint32_t hi = p.w[2];
  const uint32_t shared = (hi >> 7) & 0xFFu;
  if (shared == 0) return {0.0f, 0.0f, 0.0f};
  const uint32_t m0 = lo & kPackedMantissaMax;
  const uint32_t m1 = (lo >> 13) & kPackedMantissaMax;
  const uint32_t m2 = (lo >> 26) | ((hi & 0x7Fu) << 6);
  // 2^(shared - 139), shared in 1..254: a normal float from 2^-126 up, a subnormal below.
  const int32_t k = int32_t(shared) - 139;
  const float scale = bits_float(k >= -126 ? uint32_t(k + 127) << 23 : 1u << uint32_t(k + 149));
  return {float(m0) * scale, float(m1) * scale, float(m2) * scale};
}

inline Vec3f quantize_color(Vec3f v) { return unpack_color(pack_color(v)); }

}  // namespace strata::kernels
