// What one TP's timing counts: instructions by class, why it waited, and the fetch and
// register-file traffic that the energy model prices.
#pragma once

#include "model/iss/counters.h"

#include <array>
#include <cstdint>

namespace strata::tm {

enum class StallCause : uint8_t {
  kFetch,       // the instruction was not fetched yet (the caller's fetch_ready)
  kOperand,     // a source (or a pending write to a destination) from an XU or the ALU
  kMemory,      // a source from a memory-like op, or the memory system not accepting yet
  kStructural,  // the XU or fused pipeline was busy, or being reconfigured
  kCount
};
constexpr unsigned kStallCauseCount = static_cast<unsigned>(StallCause::kCount);

constexpr const char* stall_cause_name(StallCause c) {
  constexpr const char* kNames[kStallCauseCount] = {"fetch", "operand", "memory", "structural"};
  return c < StallCause::kCount ? kNames[static_cast<unsigned>(c)] : "invalid";
}

struct TpStats {
  uint64_t issued = 0;
  uint64_t fetches = 0;  // one per issued instruction: in order, no prediction, no refetch
  std::array<uint64_t, iss::kClassCount> issued_by_class{};
  std::array<uint64_t, kStallCauseCount> stall_cycles{};
  uint64_t int_reads = 0, int_writes = 0;  // register-file accesses, x0 excluded (as the ISS)
  uint64_t fp_reads = 0, fp_writes = 0;

  uint64_t of(iss::InstrClass c) const { return issued_by_class[static_cast<unsigned>(c)]; }
  uint64_t stalls(StallCause c) const { return stall_cycles[static_cast<unsigned>(c)]; }
  uint64_t total_stalls() const {
    uint64_t sum = 0;
    for (uint64_t s : stall_cycles) sum += s;
    return sum;
  }
};

}  // namespace strata::tm
