// How the rounding works: binary32 operands are exact in binary64. Each operation is computed
// in binary64 together with the sign of its rounding error (TwoSum for sums, an exact FMA
// residual for quotients and roots; products are exact). That gives the result rounded to
// odd in 53 bits, which keeps enough information for one correct rounding to 24 bits in any
// mode (Boldo and Melquiond, 53 >= 2*24 + 2), done below in integer arithmetic together with
// the flags. Nothing here depends on the host's rounding mode or exception flags; the inline
// fast paths in the header rely only on the host default of round to nearest even.
#include "model/iss/fp_ops.h"

#include <cmath>
#include <cstring>

namespace strata::iss::fp {
namespace {

constexpr uint32_t kExpMask = 0x7F800000u;
constexpr uint32_t kFracMask = 0x007FFFFFu;
constexpr uint32_t kQuietBit = 0x00400000u;
constexpr uint32_t kInf = 0x7F800000u;
constexpr uint32_t kMaxFinite = 0x7F7FFFFFu;

inline bool is_nan(uint32_t a) { return (a & ~kSign) > kExpMask; }
inline bool is_snan(uint32_t a) { return is_nan(a) && !(a & kQuietBit); }
inline bool is_inf(uint32_t a) { return (a & ~kSign) == kExpMask; }
inline bool is_zero(uint32_t a) { return (a & ~kSign) == 0; }
inline bool sign_of(uint32_t a) { return (a & kSign) != 0; }

inline double widen(uint32_t a) { return static_cast<double>(bits_float(a)); }

inline uint32_t narrow_exact(double d) {  // only for values exact in binary32 (0, inf)
  return float_bits(static_cast<float>(d));
}

inline uint64_t bits_of(double d) {
  uint64_t b;
  std::memcpy(&b, &d, sizeof b);
  return b;
}

inline double from_bits(uint64_t b) {
  double d;
  std::memcpy(&d, &b, sizeof d);
  return d;
}

bool round_away(bool negative, bool lsb, uint64_t rem, uint64_t half, unsigned rm) {
  switch (rm) {
    case kRne: return rem > half || (rem == half && lsb);
    case kRtz: return false;
    case kRdn: return negative && rem != 0;
    case kRup: return !negative && rem != 0;
    default: return rem >= half;  // kRmm
  }
}

uint32_t overflow(bool negative, unsigned rm, uint32_t& flags) {
  flags |= kOF | kNX;
  const uint32_t s = negative ? kSign : 0u;
  switch (rm) {
    case kRtz: return s | kMaxFinite;
    case kRdn: return s | (negative ? kInf : kMaxFinite);
    case kRup: return s | (negative ? kMaxFinite : kInf);
    default: return s | kInf;
  }
}

// v is finite and nonzero; if it came from an inexact computation it is rounded to odd.
uint32_t round_to_single(double v, unsigned rm, uint32_t& flags) {
  const uint64_t b = bits_of(v);
  const bool negative = (b >> 63) != 0;
  const int biased = static_cast<int>((b >> 52) & 0x7FF);
  uint64_t m = b & ((uint64_t{1} << 52) - 1);
  int exp;  // v = m * 2^(exp - 52), with bit 52 of m set
  if (biased == 0) {
    exp = -1022;
    while (!(m >> 52)) {
      m <<= 1;
      --exp;
    }
  } else {
    m |= uint64_t{1} << 52;
    exp = biased - 1023;
  }
  const uint32_t s = negative ? kSign : 0u;
  constexpr uint64_t kLow29 = (uint64_t{1} << 29) - 1;
  if (exp >= -126) {
    uint64_t keep = m >> 29;
    const uint64_t rem = m & kLow29;
    if (round_away(negative, keep & 1, rem, uint64_t{1} << 28, rm) && ++keep == (uint64_t{1} << 24)) {
      keep >>= 1;
      ++exp;
    }
    if (exp > 127) return overflow(negative, rm, flags);
    if (rem) flags |= kNX;
    return s | (static_cast<uint32_t>(exp + 127) << 23) | (static_cast<uint32_t>(keep) & kFracMask);
  }
  // Below the normal range: the result is a multiple of 2^-149.
  const int shift = -exp - 97;  // >= 30
  uint64_t keep, rem, half;
  if (shift > 60) {
    keep = 0;
    rem = 1;  // nonzero, below half an ulp
    half = 2;
  } else {
    keep = m >> shift;
    rem = m & ((uint64_t{1} << shift) - 1);
    half = uint64_t{1} << (shift - 1);
  }
  // Tininess is detected after rounding: only a value just below 2^-126 that rounds up to
  // it at full precision is not tiny.
  bool tiny = true;
  if (exp == -127) {
    const uint64_t k24 = m >> 29;
    if (k24 + 1 == (uint64_t{1} << 24) &&
        round_away(negative, k24 & 1, m & kLow29, uint64_t{1} << 28, rm))
      tiny = false;
  }
  if (round_away(negative, keep & 1, rem, half, rm)) ++keep;  // may carry into the normal range
  if (rem) {
    flags |= kNX;
    if (tiny) flags |= kUF;
  }
  return s | static_cast<uint32_t>(keep);
}

// err_sign: sign of (exact - s); s is the binary64 result rounded to nearest.
double to_odd(double s, double err) {
  if (err == 0.0) return s;
  uint64_t b = bits_of(s);
  const bool s_negative = (b >> 63) != 0;
  const bool exact_smaller_in_magnitude = (err < 0.0) != s_negative;
  if (exact_smaller_in_magnitude) --b;
  return from_bits(b | 1u);
}

uint32_t nan_result(bool invalid, uint32_t& flags) {
  if (invalid) flags |= kNV;
  return kCanonicalNan;
}

// x + y for finite binary64 values holding binary32 operands or an exact binary32 product.
uint32_t sum(double x, double y, unsigned rm, uint32_t& flags) {
  const double s = x + y;
  const double yy = s - x;
  const double err = (x - (s - yy)) + (y - yy);  // TwoSum: exact since nothing overflows
  if (s == 0.0 && err == 0.0) {
    // An exact zero sum is +0 unless both addends are -0, or rounding is downward.
    const bool sx = std::signbit(x), sy = std::signbit(y);
    const bool negative = sx == sy ? sx : rm == kRdn;
    return negative ? kSign : 0u;
  }
  return round_to_single(to_odd(s, err), rm, flags);
}

}  // namespace

namespace soft {

uint32_t add(uint32_t a, uint32_t b, unsigned rm, uint32_t& flags) {
  if (is_nan(a) || is_nan(b)) return nan_result(is_snan(a) || is_snan(b), flags);
  if (is_inf(a) || is_inf(b)) {
    if (is_inf(a) && is_inf(b) && sign_of(a) != sign_of(b)) return nan_result(true, flags);
    return is_inf(a) ? a : b;
  }
  return sum(widen(a), widen(b), rm, flags);
}

uint32_t sub(uint32_t a, uint32_t b, unsigned rm, uint32_t& flags) {
  return add(a, b ^ kSign, rm, flags);
}

uint32_t mul(uint32_t a, uint32_t b, unsigned rm, uint32_t& flags) {
  if (is_nan(a) || is_nan(b)) return nan_result(is_snan(a) || is_snan(b), flags);
  if ((is_inf(a) && is_zero(b)) || (is_zero(a) && is_inf(b))) return nan_result(true, flags);
  const double p = widen(a) * widen(b);  // exact: 24x24 bits fit in 53
  if (p == 0.0 || std::isinf(p)) return narrow_exact(p);
  return round_to_single(p, rm, flags);
}

uint32_t div(uint32_t a, uint32_t b, unsigned rm, uint32_t& flags) {
  if (is_nan(a) || is_nan(b)) return nan_result(is_snan(a) || is_snan(b), flags);
  if ((is_inf(a) && is_inf(b)) || (is_zero(a) && is_zero(b))) return nan_result(true, flags);
  const uint32_t s = (a ^ b) & kSign;
  if (is_inf(a)) return s | kInf;
  if (is_zero(b)) {
    flags |= kDZ;
    return s | kInf;
  }
  if (is_inf(b) || is_zero(a)) return s;
  const double x = widen(a), y = widen(b);
  const double q = x / y;
  const double r = std::fma(-q, y, x);  // exact remainder: x/y = q + r/y
  const double err = std::signbit(y) ? -r : r;
  return round_to_single(to_odd(q, err), rm, flags);
}

uint32_t sqrt(uint32_t a, unsigned rm, uint32_t& flags) {
  if (is_nan(a)) return nan_result(is_snan(a), flags);
  if (is_zero(a)) return a;
  if (sign_of(a)) return nan_result(true, flags);
  if (is_inf(a)) return a;
  const double x = widen(a);
  const double s = std::sqrt(x);
  const double r = std::fma(-s, s, x);  // exact residual of a correctly rounded root
  return round_to_single(to_odd(s, r), rm, flags);
}

uint32_t fma(uint32_t a, uint32_t b, uint32_t c, unsigned rm, uint32_t& flags) {
  const bool inf_times_zero = (is_inf(a) && is_zero(b)) || (is_zero(a) && is_inf(b));
  // The spec requires NV for inf*0 even when the addend is a quiet NaN.
  if (is_nan(a) || is_nan(b) || is_nan(c))
    return nan_result(is_snan(a) || is_snan(b) || is_snan(c) || inf_times_zero, flags);
  if (inf_times_zero) return nan_result(true, flags);
  const double p = widen(a) * widen(b);  // exact, or infinite only for an infinite operand
  if (std::isinf(p) || is_inf(c)) {
    if (std::isinf(p) && is_inf(c) && std::signbit(p) != sign_of(c)) return nan_result(true, flags);
    return std::isinf(p) ? narrow_exact(p) : c;
  }
  return sum(p, widen(c), rm, flags);
}

uint32_t min(uint32_t a, uint32_t b, uint32_t& flags) {
  if (is_snan(a) || is_snan(b)) flags |= kNV;
  if (is_nan(a) && is_nan(b)) return kCanonicalNan;
  if (is_nan(a)) return b;
  if (is_nan(b)) return a;
  if (is_zero(a) && is_zero(b)) return a | b;  // -0 is the smaller zero
  return widen(a) < widen(b) ? a : b;
}

uint32_t max(uint32_t a, uint32_t b, uint32_t& flags) {
  if (is_snan(a) || is_snan(b)) flags |= kNV;
  if (is_nan(a) && is_nan(b)) return kCanonicalNan;
  if (is_nan(a)) return b;
  if (is_nan(b)) return a;
  if (is_zero(a) && is_zero(b)) return a & b;
  return widen(a) > widen(b) ? a : b;
}

uint32_t eq(uint32_t a, uint32_t b, uint32_t& flags) {
  if (is_nan(a) || is_nan(b)) {
    if (is_snan(a) || is_snan(b)) flags |= kNV;
    return 0;
  }
  return widen(a) == widen(b) ? 1u : 0u;
}

uint32_t lt(uint32_t a, uint32_t b, uint32_t& flags) {
  if (is_nan(a) || is_nan(b)) {
    flags |= kNV;
    return 0;
  }
  return widen(a) < widen(b) ? 1u : 0u;
}

uint32_t le(uint32_t a, uint32_t b, uint32_t& flags) {
  if (is_nan(a) || is_nan(b)) {
    flags |= kNV;
    return 0;
  }
  return widen(a) <= widen(b) ? 1u : 0u;
}

}  // namespace soft

uint32_t classify(uint32_t a) {
  const bool negative = sign_of(a);
  if (is_nan(a)) return is_snan(a) ? 1u << 8 : 1u << 9;
  if (is_inf(a)) return negative ? 1u << 0 : 1u << 7;
  if (is_zero(a)) return negative ? 1u << 3 : 1u << 4;
  if ((a & kExpMask) == 0) return negative ? 1u << 2 : 1u << 5;
  return negative ? 1u << 1 : 1u << 6;
}

namespace soft {

namespace {

// x rounded to an integer in mode rm; x is finite.
double round_integral(double x, unsigned rm, bool& inexact) {
  const double t = std::trunc(x);
  const double frac = std::fabs(x - t);  // exact
  inexact = frac != 0.0;
  if (!inexact) return t;
  const bool negative = x < 0.0;
  bool away;
  switch (rm) {
    case kRne: away = frac > 0.5 || (frac == 0.5 && std::fmod(t, 2.0) != 0.0); break;
    case kRtz: away = false; break;
    case kRdn: away = negative; break;
    case kRup: away = !negative; break;
    default: away = frac >= 0.5; break;
  }
  return away ? t + (negative ? -1.0 : 1.0) : t;
}

}  // namespace

uint32_t to_int32(uint32_t a, unsigned rm, uint32_t& flags) {
  if (is_nan(a)) {
    flags |= kNV;
    return 0x7FFFFFFFu;
  }
  if (is_inf(a)) {
    flags |= kNV;
    return sign_of(a) ? 0x80000000u : 0x7FFFFFFFu;
  }
  bool inexact;
  const double r = round_integral(widen(a), rm, inexact);
  if (r > 2147483647.0) {
    flags |= kNV;
    return 0x7FFFFFFFu;
  }
  if (r < -2147483648.0) {
    flags |= kNV;
    return 0x80000000u;
  }
  if (inexact) flags |= kNX;
  return static_cast<uint32_t>(static_cast<int32_t>(r));
}

uint32_t to_uint32(uint32_t a, unsigned rm, uint32_t& flags) {
  if (is_nan(a)) {
    flags |= kNV;
    return 0xFFFFFFFFu;
  }
  if (is_inf(a)) {
    flags |= kNV;
    return sign_of(a) ? 0u : 0xFFFFFFFFu;
  }
  bool inexact;
  const double r = round_integral(widen(a), rm, inexact);
  if (r > 4294967295.0) {
    flags |= kNV;
    return 0xFFFFFFFFu;
  }
  if (r < 0.0) {  // -0 (from a small negative value rounded toward zero) is valid
    flags |= kNV;
    return 0u;
  }
  if (inexact) flags |= kNX;
  return static_cast<uint32_t>(r);
}

uint32_t from_int32(uint32_t v, unsigned rm, uint32_t& flags) {
  if (v == 0) return 0;
  return round_to_single(static_cast<double>(static_cast<int32_t>(v)), rm, flags);
}

uint32_t from_uint32(uint32_t v, unsigned rm, uint32_t& flags) {
  if (v == 0) return 0;
  return round_to_single(static_cast<double>(v), rm, flags);
}

}  // namespace soft
}  // namespace strata::iss::fp
