// A binary32 value and its bit pattern, both ways: the verilated pipelines' ports carry bits,
// the C++ side carries floats.
#pragma once

#include <cstdint>
#include <cstring>

namespace strata::rtl {

inline uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

inline float from_bits(uint32_t u) {
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

}  // namespace strata::rtl
