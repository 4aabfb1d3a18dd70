#include "model/iss/csr.h"

namespace strata::iss {

const char* cause_name(uint32_t c) {
  switch (c) {
    case cause::kInstructionMisaligned: return "instruction address misaligned";
    case cause::kInstructionAccessFault: return "instruction access fault";
    case cause::kIllegalInstruction: return "illegal instruction";
    case cause::kBreakpoint: return "breakpoint";
    case cause::kLoadMisaligned: return "load address misaligned";
    case cause::kLoadAccessFault: return "load access fault";
    case cause::kStoreMisaligned: return "store address misaligned";
    case cause::kStoreAccessFault: return "store access fault";
    case cause::kEcallM: return "environment call from M-mode";
  }
  return "unknown cause";
}

const char* csr_name(uint16_t n) {
  switch (n) {
    case csr::kFflags: return "fflags";
    case csr::kFrm: return "frm";
    case csr::kFcsr: return "fcsr";
    case csr::kMstatus: return "mstatus";
    case csr::kMisa: return "misa";
    case csr::kMie: return "mie";
    case csr::kMtvec: return "mtvec";
    case csr::kMscratch: return "mscratch";
    case csr::kMepc: return "mepc";
    case csr::kMcause: return "mcause";
    case csr::kMtval: return "mtval";
    case csr::kMip: return "mip";
    case csr::kMcycle: return "mcycle";
    case csr::kMinstret: return "minstret";
    case csr::kMcycleh: return "mcycleh";
    case csr::kMinstreth: return "minstreth";
    case csr::kCycle: return "cycle";
    case csr::kTime: return "time";
    case csr::kInstret: return "instret";
    case csr::kCycleh: return "cycleh";
    case csr::kTimeh: return "timeh";
    case csr::kInstreth: return "instreth";
    case csr::kMvendorid: return "mvendorid";
    case csr::kMarchid: return "marchid";
    case csr::kMimpid: return "mimpid";
    case csr::kMhartid: return "mhartid";
  }
  return nullptr;
}

}  // namespace strata::iss
