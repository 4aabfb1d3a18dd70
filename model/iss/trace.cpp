#include "model/iss/trace.h"

#include "model/iss/csr.h"
#include "model/iss/disassembler.h"

#include <string>

namespace strata::iss {

void trace_retired(std::FILE* out, uint32_t hart, uint32_t pc, uint32_t word, const Decoded& d,
                   const uint32_t* x, const uint32_t* f) {
  std::string writes;
  const OpInfo& info = op_info(d.op);
  const uint8_t fields[3] = {d.rd, d.rs1, d.rs2};
  char buf[40];
  for (unsigned i = 0; i < 3; ++i) {
    if (info.role[i] == Role::kIntDst && fields[i] != 0) {
      std::snprintf(buf, sizeof buf, " %s=0x%08x", int_reg_name(fields[i]), x[fields[i]]);
      writes += buf;
    } else if (info.role[i] == Role::kFpDst) {
      std::snprintf(buf, sizeof buf, " %s=0x%08x", fp_reg_name(fields[i]), f[fields[i]]);
      writes += buf;
    }
  }
  std::fprintf(out, "[%u] %08x %08x  %-36s%s\n", hart, pc, word, disassemble(d, word, pc).c_str(), writes.c_str());
}

void trace_trap(std::FILE* out, uint32_t hart, uint32_t pc, uint32_t cause, uint32_t tval, bool handled) {
  std::fprintf(out, "[%u] %08x trap: %s (mcause %u, mtval 0x%08x)%s\n", hart, pc, cause_name(cause), cause, tval,
               handled ? ", to mtvec" : ", no handler");
}

}  // namespace strata::iss
