// The verilated IEEE-754 binary32 units (rtl/fp/) driven back to back, one operand pair per
// clock, and compared bit for bit with the host's float arithmetic (built with
// -ffp-contract=off, SSE on x86-64: round to nearest even, no flush to zero). Used by the
// unit tests (test/rtl) and by the long campaign (scripts/rtl-campaign).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace strata::rtl {

// What is compared: mul a*b, add a+b and sub a-b (one RTL unit, fp32_add), cmp the three
// relations a<b, a<=b, a==b (fp32_cmp), minmax both max_ignore_nan(a, b) and
// min_ignore_nan(a, b) of firmware/common/intersect.h (fp32_minmax).
enum class FpOp { kMul, kAdd, kSub, kCmp, kMinMax };
const char* fp_op_name(FpOp op);
std::vector<FpOp> all_fp_ops();

using OperandPair = std::pair<uint32_t, uint32_t>;

struct FpMismatch {
  uint32_t a, b;
  std::string what;  // "rtl 0x... host 0x..." or which relation differed
};

struct FpCompareResult {
  uint64_t vectors = 0;     // operand pairs driven through the unit and checked
  uint64_t mismatches = 0;  // pairs where any checked output differed
  std::vector<FpMismatch> first;  // the first few mismatches, for the message
};

// The comparison rule for a float result: bit-identical to the host's, or any NaN where the
// host has a NaN.
bool fp_results_agree(uint32_t rtl, uint32_t host);

// Drives the pairs through the verilated unit, one per cycle, and compares each result with
// the host's. A non-NaN host result must match bit for bit; a NaN host result needs any NaN.
FpCompareResult compare_fp_unit(FpOp op, const std::vector<OperandPair>& pairs);

// Deterministic random operands (std::mt19937_64 from seed), a mix of classes chosen per
// pair: uniform bit patterns (every exponent, NaNs, infinities), nearby exponents (alignment,
// cancellation), short significands (exact results and rounding ties), exponent sums at the
// overflow and underflow thresholds, subnormals, and equal or neighbouring values.
std::vector<OperandPair> random_operands(FpOp op, uint64_t count, uint64_t seed);

// Every edge class, enumerated: all pairs of a list of special values (+-0, smallest and
// largest subnormals, smallest normal, +-1 and its neighbours, largest finite, +-inf, qNaN
// and sNaN of both signs), plus generated ties, overflows, underflows and cancellations.
std::vector<OperandPair> edge_operands(FpOp op);

std::string describe(const FpCompareResult& r, FpOp op);

}  // namespace strata::rtl
