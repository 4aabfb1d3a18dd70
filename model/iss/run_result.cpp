#include "model/iss/run_result.h"

#include "model/iss/csr.h"
#include "model/iss/disassembler.h"

#include <cstdio>

namespace strata::iss {

const char* stop_reason_name(StopReason r) {
  switch (r) {
    case StopReason::kInstructionLimit: return "instruction limit";
    case StopReason::kToHost: return "tohost";
    case StopReason::kHalt: return "halt";
    case StopReason::kTrap: return "trap";
    case StopReason::kHookError: return "STRaTA hook error";
    case StopReason::kYield: return "yield";
    case StopReason::kDeferred: return "deferred";
  }
  return "?";
}

std::string describe(const RunResult& r) {
  char buf[256];
  const std::string insn = r.insn ? " (" + disassemble(r.insn, r.pc) + ")" : std::string();
  switch (r.reason) {
    case StopReason::kInstructionLimit:
      std::snprintf(buf, sizeof buf, "instruction limit reached after %llu instructions, next pc 0x%08x",
                    static_cast<unsigned long long>(r.executed), r.pc);
      return buf;
    case StopReason::kToHost:
      std::snprintf(buf, sizeof buf, "tohost exit code %u at pc 0x%08x", r.exit_code, r.pc);
      return buf;
    case StopReason::kHalt:
      std::snprintf(buf, sizeof buf, "halted at pc 0x%08x", r.pc);
      return buf;
    case StopReason::kTrap:
      std::snprintf(buf, sizeof buf, "trap: %s at pc 0x%08x%s, mcause %u, mtval 0x%08x%s%s", cause_name(r.cause),
                    r.pc, insn.c_str(), r.cause, r.tval, r.detail ? ": " : "", r.detail ? r.detail : "");
      return buf;
    case StopReason::kHookError:
      std::snprintf(buf, sizeof buf, "STRaTA hook error at pc 0x%08x%s: %s", r.pc, insn.c_str(),
                    r.detail ? r.detail : "unspecified");
      return buf;
    case StopReason::kYield:
      std::snprintf(buf, sizeof buf, "yielded to the embedder after %llu instructions, next pc 0x%08x",
                    static_cast<unsigned long long>(r.executed), r.pc);
      return buf;
    case StopReason::kDeferred:
      std::snprintf(buf, sizeof buf, "deferred by the embedder after %llu instructions, before pc 0x%08x%s",
                    static_cast<unsigned long long>(r.executed), r.pc, insn.c_str());
      return buf;
  }
  return "?";
}

}  // namespace strata::iss
