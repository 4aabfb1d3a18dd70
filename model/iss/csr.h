// CSR numbers, mstatus fields and exception causes of the machine-mode-only hart.
#pragma once

#include <cstdint>

namespace strata::iss {

namespace csr {
constexpr uint16_t kFflags = 0x001, kFrm = 0x002, kFcsr = 0x003;
constexpr uint16_t kMstatus = 0x300, kMisa = 0x301, kMie = 0x304, kMtvec = 0x305;
constexpr uint16_t kMscratch = 0x340, kMepc = 0x341, kMcause = 0x342, kMtval = 0x343, kMip = 0x344;
constexpr uint16_t kMcycle = 0xB00, kMinstret = 0xB02, kMcycleh = 0xB80, kMinstreth = 0xB82;
constexpr uint16_t kCycle = 0xC00, kTime = 0xC01, kInstret = 0xC02;
constexpr uint16_t kCycleh = 0xC80, kTimeh = 0xC81, kInstreth = 0xC82;
constexpr uint16_t kMvendorid = 0xF11, kMarchid = 0xF12, kMimpid = 0xF13, kMhartid = 0xF14;
}  // namespace csr

namespace mstatus {
constexpr uint32_t kMie = 1u << 3;
constexpr uint32_t kMpie = 1u << 7;
constexpr uint32_t kMpp = 3u << 11;  // always M: the hart has no other privilege mode
constexpr uint32_t kFs = 3u << 13;
constexpr uint32_t kFsDirty = 3u << 13;
constexpr uint32_t kSd = 1u << 31;
constexpr uint32_t kWritable = kMie | kMpie | kFs;
}  // namespace mstatus

// misa: MXL=32, extensions F, I, M and X (non-standard: the STRaTA extension).
constexpr uint32_t kMisa = (1u << 30) | (1u << ('F' - 'A')) | (1u << ('I' - 'A')) |
                           (1u << ('M' - 'A')) | (1u << ('X' - 'A'));

namespace cause {
constexpr uint32_t kInstructionMisaligned = 0;
constexpr uint32_t kInstructionAccessFault = 1;
constexpr uint32_t kIllegalInstruction = 2;
constexpr uint32_t kBreakpoint = 3;
constexpr uint32_t kLoadMisaligned = 4;
constexpr uint32_t kLoadAccessFault = 5;
constexpr uint32_t kStoreMisaligned = 6;
constexpr uint32_t kStoreAccessFault = 7;
constexpr uint32_t kEcallM = 11;
}  // namespace cause

const char* cause_name(uint32_t cause);
const char* csr_name(uint16_t number);  // nullptr if the hart does not implement it

}  // namespace strata::iss
