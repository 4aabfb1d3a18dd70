// What one TP's timing counts: why it waited, cycle by cycle, by cause.
#pragma once

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

// Only the stalls: what the TPs issued, and their register-file traffic, the ISS counts
// already (iss::Counters), so the timing does not count them a second time per instruction.
struct TpStats {
  std::array<uint64_t, kStallCauseCount> stall_cycles{};

  uint64_t stalls(StallCause c) const { return stall_cycles[static_cast<unsigned>(c)]; }
  uint64_t total_stalls() const {
    uint64_t sum = 0;
    for (uint64_t s : stall_cycles) sum += s;
    return sum;
  }
};

}  // namespace strata::tm
