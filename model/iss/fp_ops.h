// RISC-V single-precision arithmetic on raw bit patterns, exactly as the F extension
// specifies: all five rounding modes (including RMM, which hosts lack), canonical NaNs,
// and the accrued exception flags. Independent of the host's floating-point environment.
#pragma once

#include <cmath>
#include <cstdint>

#include "firmware/common/float_bits.h"

namespace strata::iss::fp {

// fflags bits
constexpr uint32_t kNX = 1u, kUF = 2u, kOF = 4u, kDZ = 8u, kNV = 16u;

// rm field values
constexpr unsigned kRne = 0, kRtz = 1, kRdn = 2, kRup = 3, kRmm = 4, kDyn = 7;

constexpr uint32_t kCanonicalNan = 0x7FC00000u;

constexpr uint32_t kSign = 0x80000000u;

// The exact software implementation of every operation, for any rounding mode. rm must
// already be resolved (0..4); flags are OR-ed into `flags`.
namespace soft {
uint32_t add(uint32_t a, uint32_t b, unsigned rm, uint32_t& flags);
uint32_t sub(uint32_t a, uint32_t b, unsigned rm, uint32_t& flags);
uint32_t mul(uint32_t a, uint32_t b, unsigned rm, uint32_t& flags);
uint32_t div(uint32_t a, uint32_t b, unsigned rm, uint32_t& flags);
uint32_t sqrt(uint32_t a, unsigned rm, uint32_t& flags);
uint32_t fma(uint32_t a, uint32_t b, uint32_t c, unsigned rm, uint32_t& flags);  // a*b+c, one rounding
uint32_t min(uint32_t a, uint32_t b, uint32_t& flags);
uint32_t max(uint32_t a, uint32_t b, uint32_t& flags);
uint32_t eq(uint32_t a, uint32_t b, uint32_t& flags);  // quiet
uint32_t lt(uint32_t a, uint32_t b, uint32_t& flags);  // signaling
uint32_t le(uint32_t a, uint32_t b, uint32_t& flags);  // signaling
uint32_t to_int32(uint32_t a, unsigned rm, uint32_t& flags);    // fcvt.w.s
uint32_t to_uint32(uint32_t a, unsigned rm, uint32_t& flags);   // fcvt.wu.s
uint32_t from_int32(uint32_t v, unsigned rm, uint32_t& flags);  // fcvt.s.w
uint32_t from_uint32(uint32_t v, unsigned rm, uint32_t& flags); // fcvt.s.wu
}  // namespace soft

uint32_t classify(uint32_t a);

constexpr uint32_t sgnj(uint32_t a, uint32_t b) { return (a & ~kSign) | (b & kSign); }
constexpr uint32_t sgnjn(uint32_t a, uint32_t b) { return (a & ~kSign) | (~b & kSign); }
constexpr uint32_t sgnjx(uint32_t a, uint32_t b) { return a ^ (b & kSign); }

// Inline fast paths for the common case: round to nearest even with a normal, finite
// result (not the smallest normal). The host computes the binary32 result itself (its default environment is round to
// nearest even without flush-to-zero, which the simulator never changes) and an exact
// binary64 check gives the inexact flag. Everything else goes to the soft implementation.
namespace detail {
// Finite and above the smallest normal: a result of exactly 2^-126 may come from a tiny
// exact value, and then it underflows, so that case takes the soft path.
inline bool normal(uint32_t a) {
  const uint32_t magnitude = a & ~kSign;
  return magnitude > 0x00800000u && magnitude < 0x7F800000u;
}
inline bool nan(uint32_t a) { return (a & ~kSign) > 0x7F800000u; }
}  // namespace detail

inline uint32_t add(uint32_t a, uint32_t b, unsigned rm, uint32_t& flags) {
  if (rm == kRne) {
    const float fa = bits_float(a), fb = bits_float(b);
    const float r = fa + fb;
    if (detail::normal(float_bits(r))) {
      const double x = fa, y = fb, s = x + y, yy = s - x;
      const double err = (x - (s - yy)) + (y - yy);  // TwoSum: x + y == s + err exactly
      if (s != static_cast<double>(r) || err != 0.0) flags |= kNX;
      return float_bits(r);
    }
  }
  return soft::add(a, b, rm, flags);
}

inline uint32_t sub(uint32_t a, uint32_t b, unsigned rm, uint32_t& flags) { return add(a, b ^ kSign, rm, flags); }

inline uint32_t mul(uint32_t a, uint32_t b, unsigned rm, uint32_t& flags) {
  if (rm == kRne) {
    const float fa = bits_float(a), fb = bits_float(b);
    const float r = fa * fb;
    if (detail::normal(float_bits(r))) {
      if (static_cast<double>(fa) * static_cast<double>(fb) != static_cast<double>(r)) flags |= kNX;
      return float_bits(r);
    }
  }
  return soft::mul(a, b, rm, flags);
}

inline uint32_t div(uint32_t a, uint32_t b, unsigned rm, uint32_t& flags) {
  if (rm == kRne) {
    const float fa = bits_float(a), fb = bits_float(b);
    const float r = fa / fb;
    if (detail::normal(float_bits(r))) {
      if (static_cast<double>(r) * static_cast<double>(fb) != static_cast<double>(fa)) flags |= kNX;
      return float_bits(r);
    }
  }
  return soft::div(a, b, rm, flags);
}

inline uint32_t sqrt(uint32_t a, unsigned rm, uint32_t& flags) {
  if (rm == kRne && a - 1u < 0x7F7FFFFFu) {  // positive, finite, nonzero: the root is normal
    const float fa = bits_float(a);
    const float r = std::sqrt(fa);
    if (static_cast<double>(r) * static_cast<double>(r) != static_cast<double>(fa)) flags |= kNX;
    return float_bits(r);
  }
  return soft::sqrt(a, rm, flags);
}

inline uint32_t fma(uint32_t a, uint32_t b, uint32_t c, unsigned rm, uint32_t& flags) {
  return soft::fma(a, b, c, rm, flags);
}

inline uint32_t min(uint32_t a, uint32_t b, uint32_t& flags) {
  if (!detail::nan(a) && !detail::nan(b) && ((a | b) & ~kSign) != 0)
    return bits_float(a) < bits_float(b) ? a : b;
  return soft::min(a, b, flags);
}

inline uint32_t max(uint32_t a, uint32_t b, uint32_t& flags) {
  if (!detail::nan(a) && !detail::nan(b) && ((a | b) & ~kSign) != 0)
    return bits_float(a) > bits_float(b) ? a : b;
  return soft::max(a, b, flags);
}

inline uint32_t eq(uint32_t a, uint32_t b, uint32_t& flags) {
  if (!detail::nan(a) && !detail::nan(b)) return bits_float(a) == bits_float(b);
  return soft::eq(a, b, flags);
}

inline uint32_t lt(uint32_t a, uint32_t b, uint32_t& flags) {
  if (!detail::nan(a) && !detail::nan(b)) return bits_float(a) < bits_float(b);
  return soft::lt(a, b, flags);
}

inline uint32_t le(uint32_t a, uint32_t b, uint32_t& flags) {
  if (!detail::nan(a) && !detail::nan(b)) return bits_float(a) <= bits_float(b);
  return soft::le(a, b, flags);
}

inline uint32_t to_int32(uint32_t a, unsigned rm, uint32_t& flags) {
  if (rm == kRtz && (a & 0x7F800000u) < 0x4F000000u) {  // |a| < 2^31: C's truncating cast
    const float fa = bits_float(a);
    const int32_t i = static_cast<int32_t>(fa);
    if (static_cast<float>(i) != fa) flags |= kNX;
    return static_cast<uint32_t>(i);
  }
  return soft::to_int32(a, rm, flags);
}

inline uint32_t to_uint32(uint32_t a, unsigned rm, uint32_t& flags) { return soft::to_uint32(a, rm, flags); }

inline uint32_t from_int32(uint32_t v, unsigned rm, uint32_t& flags) {
  if (rm == kRne) {
    const int32_t i = static_cast<int32_t>(v);
    const float r = static_cast<float>(i);
    if (static_cast<double>(r) != static_cast<double>(i)) flags |= kNX;
    return float_bits(r);
  }
  return soft::from_int32(v, rm, flags);
}

inline uint32_t from_uint32(uint32_t v, unsigned rm, uint32_t& flags) { return soft::from_uint32(v, rm, flags); }

}  // namespace strata::iss::fp
