// Test helpers for the ISS: an instruction encoder (so tests do not depend on the RISC-V
// toolchain) and a small machine that runs a list of instruction words.
#pragma once

#include "firmware/abi/strata_isa.h"
#include "model/iss/csr.h"
#include "model/iss/hart.h"

#include <cstdint>
#include <cstring>
#include <vector>

namespace strata::iss::testing {

// ---- Encoder ----
namespace enc {

constexpr uint32_t u32(int32_t v) { return static_cast<uint32_t>(v); }

constexpr uint32_t r(uint32_t f7, uint32_t rs2, uint32_t rs1, uint32_t f3, uint32_t rd, uint32_t opcode) {
  return (f7 << 25) | (rs2 << 20) | (rs1 << 15) | (f3 << 12) | (rd << 7) | opcode;
}
constexpr uint32_t i(int32_t imm, uint32_t rs1, uint32_t f3, uint32_t rd, uint32_t opcode) {
  return ((u32(imm) & 0xFFFu) << 20) | (rs1 << 15) | (f3 << 12) | (rd << 7) | opcode;
}
constexpr uint32_t s(int32_t imm, uint32_t rs2, uint32_t rs1, uint32_t f3, uint32_t opcode) {
  const uint32_t v = u32(imm);
  return (((v >> 5) & 0x7Fu) << 25) | (rs2 << 20) | (rs1 << 15) | (f3 << 12) | ((v & 31u) << 7) | opcode;
}
constexpr uint32_t b(int32_t imm, uint32_t rs2, uint32_t rs1, uint32_t f3) {
  const uint32_t v = u32(imm);
  return (((v >> 12) & 1u) << 31) | (((v >> 5) & 63u) << 25) | (rs2 << 20) | (rs1 << 15) | (f3 << 12) |
         (((v >> 1) & 15u) << 8) | (((v >> 11) & 1u) << 7) | 0x63u;
}
constexpr uint32_t u(uint32_t imm, uint32_t rd, uint32_t opcode) { return (imm & 0xFFFFF000u) | (rd << 7) | opcode; }
constexpr uint32_t j(int32_t imm, uint32_t rd) {
  const uint32_t v = u32(imm);
  return (((v >> 20) & 1u) << 31) | (((v >> 1) & 0x3FFu) << 21) | (((v >> 11) & 1u) << 20) |
         (((v >> 12) & 0xFFu) << 12) | (rd << 7) | 0x6Fu;
}
constexpr uint32_t r4(uint32_t rs3, uint32_t rs2, uint32_t rs1, uint32_t rm, uint32_t rd, uint32_t opcode) {
  return (rs3 << 27) | (rs2 << 20) | (rs1 << 15) | (rm << 12) | (rd << 7) | opcode;
}

#define STRATA_ENC_R(name, f7, f3) \
  constexpr uint32_t name(uint32_t rd, uint32_t rs1, uint32_t rs2) { return r(f7, rs2, rs1, f3, rd, 0x33); }
STRATA_ENC_R(add, 0x00, 0)
STRATA_ENC_R(sub, 0x20, 0)
STRATA_ENC_R(sll, 0x00, 1)
STRATA_ENC_R(slt, 0x00, 2)
STRATA_ENC_R(sltu, 0x00, 3)
STRATA_ENC_R(xor_, 0x00, 4)
STRATA_ENC_R(srl, 0x00, 5)
STRATA_ENC_R(sra, 0x20, 5)
STRATA_ENC_R(or_, 0x00, 6)
STRATA_ENC_R(and_, 0x00, 7)
STRATA_ENC_R(mul, 0x01, 0)
STRATA_ENC_R(mulh, 0x01, 1)
STRATA_ENC_R(mulhsu, 0x01, 2)
STRATA_ENC_R(mulhu, 0x01, 3)
STRATA_ENC_R(div, 0x01, 4)
STRATA_ENC_R(divu, 0x01, 5)
STRATA_ENC_R(rem, 0x01, 6)
STRATA_ENC_R(remu, 0x01, 7)
#undef STRATA_ENC_R

#define STRATA_ENC_I(name, f3, opcode) \
  constexpr uint32_t name(uint32_t rd, uint32_t rs1, int32_t imm) { return i(imm, rs1, f3, rd, opcode); }
STRATA_ENC_I(addi, 0, 0x13)
STRATA_ENC_I(slti, 2, 0x13)
STRATA_ENC_I(sltiu, 3, 0x13)
STRATA_ENC_I(xori, 4, 0x13)
STRATA_ENC_I(ori, 6, 0x13)
STRATA_ENC_I(andi, 7, 0x13)
STRATA_ENC_I(lb, 0, 0x03)
STRATA_ENC_I(lh, 1, 0x03)
STRATA_ENC_I(lw, 2, 0x03)
STRATA_ENC_I(lbu, 4, 0x03)
STRATA_ENC_I(lhu, 5, 0x03)
STRATA_ENC_I(jalr, 0, 0x67)
STRATA_ENC_I(flw, 2, 0x07)
#undef STRATA_ENC_I

constexpr uint32_t slli(uint32_t rd, uint32_t rs1, uint32_t sh) { return r(0x00, sh, rs1, 1, rd, 0x13); }
constexpr uint32_t srli(uint32_t rd, uint32_t rs1, uint32_t sh) { return r(0x00, sh, rs1, 5, rd, 0x13); }
constexpr uint32_t srai(uint32_t rd, uint32_t rs1, uint32_t sh) { return r(0x20, sh, rs1, 5, rd, 0x13); }

constexpr uint32_t sb(uint32_t rs2, uint32_t rs1, int32_t imm) { return s(imm, rs2, rs1, 0, 0x23); }
constexpr uint32_t sh(uint32_t rs2, uint32_t rs1, int32_t imm) { return s(imm, rs2, rs1, 1, 0x23); }
constexpr uint32_t sw(uint32_t rs2, uint32_t rs1, int32_t imm) { return s(imm, rs2, rs1, 2, 0x23); }
constexpr uint32_t fsw(uint32_t rs2, uint32_t rs1, int32_t imm) { return s(imm, rs2, rs1, 2, 0x27); }

constexpr uint32_t beq(uint32_t rs1, uint32_t rs2, int32_t off) { return b(off, rs2, rs1, 0); }
constexpr uint32_t bne(uint32_t rs1, uint32_t rs2, int32_t off) { return b(off, rs2, rs1, 1); }
constexpr uint32_t blt(uint32_t rs1, uint32_t rs2, int32_t off) { return b(off, rs2, rs1, 4); }
constexpr uint32_t bge(uint32_t rs1, uint32_t rs2, int32_t off) { return b(off, rs2, rs1, 5); }
constexpr uint32_t bltu(uint32_t rs1, uint32_t rs2, int32_t off) { return b(off, rs2, rs1, 6); }
constexpr uint32_t bgeu(uint32_t rs1, uint32_t rs2, int32_t off) { return b(off, rs2, rs1, 7); }

constexpr uint32_t lui(uint32_t rd, uint32_t imm) { return u(imm, rd, 0x37); }
constexpr uint32_t auipc(uint32_t rd, uint32_t imm) { return u(imm, rd, 0x17); }
constexpr uint32_t jal(uint32_t rd, int32_t off) { return j(off, rd); }

constexpr uint32_t csrrw(uint32_t rd, uint32_t csr, uint32_t rs1) { return (csr << 20) | (rs1 << 15) | (1u << 12) | (rd << 7) | 0x73; }
constexpr uint32_t csrrs(uint32_t rd, uint32_t csr, uint32_t rs1) { return (csr << 20) | (rs1 << 15) | (2u << 12) | (rd << 7) | 0x73; }
constexpr uint32_t csrrc(uint32_t rd, uint32_t csr, uint32_t rs1) { return (csr << 20) | (rs1 << 15) | (3u << 12) | (rd << 7) | 0x73; }
constexpr uint32_t csrrwi(uint32_t rd, uint32_t csr, uint32_t z) { return (csr << 20) | (z << 15) | (5u << 12) | (rd << 7) | 0x73; }
constexpr uint32_t csrrsi(uint32_t rd, uint32_t csr, uint32_t z) { return (csr << 20) | (z << 15) | (6u << 12) | (rd << 7) | 0x73; }
constexpr uint32_t csrrci(uint32_t rd, uint32_t csr, uint32_t z) { return (csr << 20) | (z << 15) | (7u << 12) | (rd << 7) | 0x73; }

constexpr uint32_t ecall() { return 0x00000073; }
constexpr uint32_t ebreak() { return 0x00100073; }
constexpr uint32_t mret() { return 0x30200073; }
constexpr uint32_t wfi() { return 0x10500073; }
constexpr uint32_t fence() { return 0x0FF0000F; }
constexpr uint32_t fence_i() { return 0x0000100F; }
constexpr uint32_t nop() { return addi(0, 0, 0); }

// OP-FP; rm 7 = dynamic.
constexpr uint32_t fop(uint32_t f7, uint32_t rd, uint32_t rs1, uint32_t rs2, uint32_t rm) { return r(f7, rs2, rs1, rm, rd, 0x53); }
constexpr uint32_t fadd(uint32_t rd, uint32_t rs1, uint32_t rs2, uint32_t rm = 7) { return fop(0x00, rd, rs1, rs2, rm); }
constexpr uint32_t fsub(uint32_t rd, uint32_t rs1, uint32_t rs2, uint32_t rm = 7) { return fop(0x04, rd, rs1, rs2, rm); }
constexpr uint32_t fmul(uint32_t rd, uint32_t rs1, uint32_t rs2, uint32_t rm = 7) { return fop(0x08, rd, rs1, rs2, rm); }
constexpr uint32_t fdiv(uint32_t rd, uint32_t rs1, uint32_t rs2, uint32_t rm = 7) { return fop(0x0C, rd, rs1, rs2, rm); }
constexpr uint32_t fsqrt(uint32_t rd, uint32_t rs1, uint32_t rm = 7) { return fop(0x2C, rd, rs1, 0, rm); }
constexpr uint32_t fsgnj(uint32_t rd, uint32_t rs1, uint32_t rs2) { return fop(0x10, rd, rs1, rs2, 0); }
constexpr uint32_t fsgnjn(uint32_t rd, uint32_t rs1, uint32_t rs2) { return fop(0x10, rd, rs1, rs2, 1); }
constexpr uint32_t fsgnjx(uint32_t rd, uint32_t rs1, uint32_t rs2) { return fop(0x10, rd, rs1, rs2, 2); }
constexpr uint32_t fmin(uint32_t rd, uint32_t rs1, uint32_t rs2) { return fop(0x14, rd, rs1, rs2, 0); }
constexpr uint32_t fmax(uint32_t rd, uint32_t rs1, uint32_t rs2) { return fop(0x14, rd, rs1, rs2, 1); }
constexpr uint32_t fcvt_w_s(uint32_t rd, uint32_t rs1, uint32_t rm = 7) { return fop(0x60, rd, rs1, 0, rm); }
constexpr uint32_t fcvt_wu_s(uint32_t rd, uint32_t rs1, uint32_t rm = 7) { return fop(0x60, rd, rs1, 1, rm); }
constexpr uint32_t fmv_x_w(uint32_t rd, uint32_t rs1) { return fop(0x70, rd, rs1, 0, 0); }
constexpr uint32_t fclass(uint32_t rd, uint32_t rs1) { return fop(0x70, rd, rs1, 0, 1); }
constexpr uint32_t feq(uint32_t rd, uint32_t rs1, uint32_t rs2) { return fop(0x50, rd, rs1, rs2, 2); }
constexpr uint32_t flt(uint32_t rd, uint32_t rs1, uint32_t rs2) { return fop(0x50, rd, rs1, rs2, 1); }
constexpr uint32_t fle(uint32_t rd, uint32_t rs1, uint32_t rs2) { return fop(0x50, rd, rs1, rs2, 0); }
constexpr uint32_t fcvt_s_w(uint32_t rd, uint32_t rs1, uint32_t rm = 7) { return fop(0x68, rd, rs1, 0, rm); }
constexpr uint32_t fcvt_s_wu(uint32_t rd, uint32_t rs1, uint32_t rm = 7) { return fop(0x68, rd, rs1, 1, rm); }
constexpr uint32_t fmv_w_x(uint32_t rd, uint32_t rs1) { return fop(0x78, rd, rs1, 0, 0); }
constexpr uint32_t fmadd(uint32_t rd, uint32_t rs1, uint32_t rs2, uint32_t rs3, uint32_t rm = 7) { return r4(rs3, rs2, rs1, rm, rd, 0x43); }
constexpr uint32_t fmsub(uint32_t rd, uint32_t rs1, uint32_t rs2, uint32_t rs3, uint32_t rm = 7) { return r4(rs3, rs2, rs1, rm, rd, 0x47); }
constexpr uint32_t fnmsub(uint32_t rd, uint32_t rs1, uint32_t rs2, uint32_t rs3, uint32_t rm = 7) { return r4(rs3, rs2, rs1, rm, rd, 0x4B); }
constexpr uint32_t fnmadd(uint32_t rd, uint32_t rs1, uint32_t rs2, uint32_t rs3, uint32_t rm = 7) { return r4(rs3, rs2, rs1, rm, rd, 0x4F); }

// The STRaTA extension, from the same constants the firmware uses.
constexpr uint32_t strata(uint32_t opcode, uint32_t f3, uint32_t f7, uint32_t rd, uint32_t rs1, uint32_t rs2) {
  return r(f7, rs2, rs1, f3, rd, opcode);
}
constexpr uint32_t halt() { return strata(STRATA_OPCODE_THREAD, STRATA_F3_CONTROL, STRATA_CONTROL_HALT, 0, 0, 0); }

}  // namespace enc

// ---- Machine ----
inline uint32_t bits(float f) {
  uint32_t b;
  std::memcpy(&b, &f, 4);
  return b;
}
inline float value(uint32_t b) {
  float f;
  std::memcpy(&f, &b, 4);
  return f;
}

// Code at kCodeBase (with strata.halt appended), data memory above it.
class Machine {
 public:
  static constexpr uint32_t kCodeBase = 0x1000;
  static constexpr uint32_t kDataBase = 0x4000;
  static constexpr uint32_t kMemorySize = 0x8000;  // ends at 0x9000

  explicit Machine(std::vector<uint32_t> program, StrataHook* hook = nullptr, uint32_t hart_id = 0)
      : memory(kCodeBase, kMemorySize), code(kCodeBase, with_halt(program)), hart(code, memory, hook, hart_id) {
    const std::vector<uint32_t> words = with_halt(std::move(program));
    memory.write(kCodeBase, words.data(), words.size() * 4);
  }

  RunResult run(uint64_t limit = 100000) { return hart.run(limit); }
  void enable_fp() { hart.write_csr(csr::kMstatus, 1u << 13); }
  uint32_t csr(uint16_t number) const {
    uint32_t v = 0;
    hart.read_csr(number, v);
    return v;
  }

  FlatMemory memory;
  CodeImage code;
  Hart<FlatMemory> hart;

 private:
  static std::vector<uint32_t> with_halt(std::vector<uint32_t> words) {
    words.push_back(enc::halt());
    return words;
  }
};

// Runs one register-register integer instruction: x1 = a, x2 = b, result in x3.
inline uint32_t run_rr(uint32_t (*make)(uint32_t, uint32_t, uint32_t), uint32_t a, uint32_t b) {
  Machine m({make(3, 1, 2)});
  m.hart.set_x(1, a);
  m.hart.set_x(2, b);
  m.run();
  return m.hart.x(3);
}

// Runs one FP instruction with f1 = a, f2 = b, f3 = c and frm = frm; returns the register the
// instruction writes (f or x, register 4) and the accrued flags.
struct FpOutcome {
  uint32_t result;
  uint32_t flags;
  RunResult run;
};

inline FpOutcome run_fp(uint32_t insn, uint32_t a, uint32_t b = 0, uint32_t c = 0, uint32_t frm = 0,
                        bool int_result = false) {
  Machine m({insn});
  m.enable_fp();
  m.hart.set_f(1, a);
  m.hart.set_f(2, b);
  m.hart.set_x(1, a);  // for the conversions and moves from integer registers
  m.hart.set_x(2, b);
  m.hart.set_f(3, c);
  m.hart.write_csr(csr::kFrm, frm);
  const RunResult r = m.run();
  return {int_result ? m.hart.x(4) : m.hart.f(4), m.csr(csr::kFflags), r};
}

}  // namespace strata::iss::testing
