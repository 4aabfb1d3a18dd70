// The kinds of shared execution unit in a TM and the configurations of its reconfigurable
// FP units. Stats and energy are keyed by these, so the names are stable JSON keys.
#pragma once

#include <cstdint>

namespace strata::tm {

enum class XuClass : uint8_t { kFpMul, kFpAdd, kFpCmp, kFpDiv, kFpInvSqrt, kIntMul, kIntDiv, kCount };
constexpr unsigned kXuClassCount = static_cast<unsigned>(XuClass::kCount);

// What the TM's reconfigurable FP multipliers and adders are wired as. Only these two unit
// classes change with the mode; every other class is always general.
enum class PipelineMode : uint8_t { kGeneral, kBox, kTriangle, kCount };
constexpr unsigned kModeCount = static_cast<unsigned>(PipelineMode::kCount);

constexpr const char* xu_class_name(XuClass c) {
  constexpr const char* kNames[kXuClassCount] = {"fp_mul", "fp_add", "fp_cmp", "fp_div",
                                                 "fp_inv_sqrt", "int_mul", "int_div"};
  return c < XuClass::kCount ? kNames[static_cast<unsigned>(c)] : "invalid";
}

constexpr const char* mode_name(PipelineMode m) {
  constexpr const char* kNames[kModeCount] = {"general", "box", "triangle"};
  return m < PipelineMode::kCount ? kNames[static_cast<unsigned>(m)] : "invalid";
}

}  // namespace strata::tm
