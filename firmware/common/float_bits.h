// A binary32 value's bit pattern, and back. One definition for every side that needs it: the
// kernels (packed colours), the ISS's float instructions and fused-test hook, the RTL's ports
// and the numerics tests. Freestanding, so the firmware and the host compile it alike: the copy
// is __builtin_memcpy, which compilers fold to a register move.
#pragma once

#include <stdint.h>

namespace strata {

inline uint32_t float_bits(float f) {
  uint32_t u;
  __builtin_memcpy(&u, &f, sizeof u);
  return u;
}

inline float bits_float(uint32_t u) {
  float f;
  __builtin_memcpy(&f, &u, sizeof f);
  return f;
}

}  // namespace strata
