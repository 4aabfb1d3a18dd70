// Why a run of the hart stopped. Trivially copyable: producing one never allocates.
#pragma once

#include <cstdint>
#include <string>

namespace strata::iss {

enum class StopReason : uint8_t {
  kInstructionLimit,  // the budget ran out; run() again to continue
  kToHost,            // the program stored (code << 1) | 1 to tohost
  kHalt,              // strata.halt
  kTrap,              // an exception with no handler (mtvec == 0)
  kHookError,         // the STRaTA hook could not execute an operation
  kYield,             // the hook asked to end the run after this instruction; run() again to continue
  kDeferred           // the hook asked to stop before this instruction, which did nothing: run() again
                      // executes it (an embedder that must first let time pass, tm_fast_forward.cpp)
};

struct RunResult {
  StopReason reason = StopReason::kInstructionLimit;
  uint32_t pc = 0;    // the stopping instruction; the next one for kInstructionLimit and kYield
  uint32_t insn = 0;  // its encoding; 0 when it could not be fetched
  uint32_t cause = 0;  // kTrap: mcause
  uint32_t tval = 0;   // kTrap: mtval
  uint32_t exit_code = 0;  // kToHost
  uint64_t executed = 0;   // instructions retired by this call
  const char* detail = nullptr;  // extra explanation (static string), may be null

  bool ok() const { return reason == StopReason::kHalt || (reason == StopReason::kToHost && exit_code == 0); }
};

const char* stop_reason_name(StopReason r);

// One line, e.g. "trap: load access fault at pc 0x00010040 (lw a0, 0(a1)), mtval 0x00000000".
std::string describe(const RunResult& r);

}  // namespace strata::iss
