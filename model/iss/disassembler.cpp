#include "model/iss/disassembler.h"

#include "model/iss/csr.h"

#include <cstdio>

namespace strata::iss {
namespace {

constexpr const char* kIntNames[32] = {
    "zero", "ra", "sp", "gp", "tp", "t0", "t1", "t2", "s0", "s1", "a0", "a1", "a2", "a3", "a4", "a5",
    "a6", "a7", "s2", "s3", "s4", "s5", "s6", "s7", "s8", "s9", "s10", "s11", "t3", "t4", "t5", "t6"};
constexpr const char* kFpNames[32] = {
    "ft0", "ft1", "ft2", "ft3", "ft4", "ft5", "ft6", "ft7", "fs0", "fs1", "fa0", "fa1", "fa2", "fa3", "fa4", "fa5",
    "fa6", "fa7", "fs2", "fs3", "fs4", "fs5", "fs6", "fs7", "fs8", "fs9", "fs10", "fs11", "ft8", "ft9", "ft10", "ft11"};
constexpr const char* kRoundingNames[8] = {"rne", "rtz", "rdn", "rup", "rmm", "?5", "?6", "dyn"};

std::string csr_text(int32_t number) {
  if (const char* name = csr_name(static_cast<uint16_t>(number))) return name;
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%03x", static_cast<unsigned>(number));
  return buf;
}

std::string fence_set(unsigned bits) {
  std::string s;
  if (bits & 8) s += 'i';
  if (bits & 4) s += 'o';
  if (bits & 2) s += 'r';
  if (bits & 1) s += 'w';
  return s.empty() ? "0" : s;
}

}  // namespace

const char* int_reg_name(unsigned i) { return kIntNames[i & 31]; }
const char* fp_reg_name(unsigned i) { return kFpNames[i & 31]; }

std::string disassemble(uint32_t word, uint32_t pc) { return disassemble(decode(word), word, pc); }

std::string disassemble(const Decoded& d, uint32_t word, uint32_t pc) {
  const OpInfo& info = op_info(d.op);
  const char* m = info.mnemonic;
  const char* rd = kIntNames[d.rd];
  const char* rs1 = kIntNames[d.rs1];
  const char* rs2 = kIntNames[d.rs2];
  const uint32_t target = pc + static_cast<uint32_t>(d.imm);
  char buf[96];
  switch (info.format) {
    case Format::kR: std::snprintf(buf, sizeof buf, "%s %s, %s, %s", m, rd, rs1, rs2); break;
    case Format::kI:
    case Format::kShift: std::snprintf(buf, sizeof buf, "%s %s, %s, %d", m, rd, rs1, d.imm); break;
    case Format::kLoad:
    case Format::kJalr: std::snprintf(buf, sizeof buf, "%s %s, %d(%s)", m, rd, d.imm, rs1); break;
    case Format::kStore: std::snprintf(buf, sizeof buf, "%s %s, %d(%s)", m, rs2, d.imm, rs1); break;
    case Format::kFpLoad:
      std::snprintf(buf, sizeof buf, "%s %s, %d(%s)", m, kFpNames[d.rd], d.imm, rs1);
      break;
    case Format::kFpStore:
      std::snprintf(buf, sizeof buf, "%s %s, %d(%s)", m, kFpNames[d.rs2], d.imm, rs1);
      break;
    case Format::kBranch: std::snprintf(buf, sizeof buf, "%s %s, %s, 0x%08x", m, rs1, rs2, target); break;
    case Format::kUpper:
      std::snprintf(buf, sizeof buf, "%s %s, 0x%05x", m, rd, static_cast<uint32_t>(d.imm) >> 12);
      break;
    case Format::kJal: std::snprintf(buf, sizeof buf, "%s %s, 0x%08x", m, rd, target); break;
    case Format::kCsr:
      std::snprintf(buf, sizeof buf, "%s %s, %s, %s", m, rd, csr_text(d.imm).c_str(), rs1);
      break;
    case Format::kCsrImm:
      std::snprintf(buf, sizeof buf, "%s %s, %s, %u", m, rd, csr_text(d.imm).c_str(), unsigned{d.rs1});
      break;
    case Format::kFence:
      std::snprintf(buf, sizeof buf, "%s %s, %s", m, fence_set((static_cast<unsigned>(d.imm) >> 4) & 15).c_str(),
                    fence_set(static_cast<unsigned>(d.imm) & 15).c_str());
      break;
    case Format::kNone: std::snprintf(buf, sizeof buf, "%s", m); break;
    case Format::kOperands: {
      std::string s = m;
      const uint8_t fields[4] = {d.rd, d.rs1, d.rs2, d.rs3};
      const char* sep = " ";
      for (unsigned i = 0; i < 4; ++i) {
        const Role r = info.role[i];
        if (r == Role::kNone) continue;
        s += sep;
        s += (r == Role::kFpSrc || r == Role::kFpDst) ? kFpNames[fields[i]] : kIntNames[fields[i]];
        sep = ", ";
      }
      if (info.has_rm && d.rm != 7) {
        s += ", ";
        s += kRoundingNames[d.rm];
      }
      return s;
    }
    case Format::kIllegal: std::snprintf(buf, sizeof buf, "illegal 0x%08x", word); break;
  }
  return buf;
}

}  // namespace strata::iss
