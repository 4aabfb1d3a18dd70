// RV32I: every base instruction, on hand-assembled words.
#include "iss_test_support.h"

#include <gtest/gtest.h>

namespace strata::iss::testing {
namespace {

using namespace enc;

TEST(IssRv32i, RegisterAluOps) {
  EXPECT_EQ(run_rr(add, 0xFFFFFFFFu, 1), 0u);  // wraps
  EXPECT_EQ(run_rr(add, 0x7FFFFFFFu, 1), 0x80000000u);
  EXPECT_EQ(run_rr(sub, 0, 1), 0xFFFFFFFFu);
  EXPECT_EQ(run_rr(sub, 0x80000000u, 1), 0x7FFFFFFFu);
  EXPECT_EQ(run_rr(sll, 1, 31), 0x80000000u);
  EXPECT_EQ(run_rr(sll, 1, 32), 1u);  // only rs2[4:0] counts
  EXPECT_EQ(run_rr(sll, 3, 33), 6u);
  EXPECT_EQ(run_rr(srl, 0x80000000u, 31), 1u);
  EXPECT_EQ(run_rr(srl, 0x80000000u, 63), 1u);
  EXPECT_EQ(run_rr(sra, 0x80000000u, 31), 0xFFFFFFFFu);
  EXPECT_EQ(run_rr(sra, 0x40000000u, 30), 1u);
  EXPECT_EQ(run_rr(sra, 0x80000000u, 0), 0x80000000u);
  EXPECT_EQ(run_rr(slt, 0xFFFFFFFFu, 0), 1u);
  EXPECT_EQ(run_rr(slt, 0, 0xFFFFFFFFu), 0u);
  EXPECT_EQ(run_rr(slt, 5, 5), 0u);
  EXPECT_EQ(run_rr(sltu, 0xFFFFFFFFu, 0), 0u);
  EXPECT_EQ(run_rr(sltu, 0, 0xFFFFFFFFu), 1u);
  EXPECT_EQ(run_rr(xor_, 0xF0F0F0F0u, 0xFF00FF00u), 0x0FF00FF0u);
  EXPECT_EQ(run_rr(or_, 0xF0F0F0F0u, 0x0F000000u), 0xFFF0F0F0u);
  EXPECT_EQ(run_rr(and_, 0xF0F0F0F0u, 0xFF00FF00u), 0xF000F000u);
}

TEST(IssRv32i, ImmediateAluOps) {
  Machine m({addi(1, 0, -1), addi(2, 1, 2047), addi(3, 0, -2048), slti(4, 1, 0), slti(5, 1, -1),
             sltiu(6, 0, -1), sltiu(7, 1, -1), xori(8, 2, -1), ori(9, 0, 0x555), andi(10, 1, 0x0F0),
             slli(11, 1, 31), srli(12, 1, 31), srai(13, 11, 31), srai(14, 11, 0), lui(15, 0xABCDE000u),
             auipc(16, 0x00001000u)});
  ASSERT_EQ(m.run().reason, StopReason::kHalt);
  EXPECT_EQ(m.hart.x(1), 0xFFFFFFFFu);
  EXPECT_EQ(m.hart.x(2), 2046u);
  EXPECT_EQ(m.hart.x(3), static_cast<uint32_t>(-2048));
  EXPECT_EQ(m.hart.x(4), 1u);
  EXPECT_EQ(m.hart.x(5), 0u);
  EXPECT_EQ(m.hart.x(6), 1u);  // the immediate is sign-extended, then compared unsigned
  EXPECT_EQ(m.hart.x(7), 0u);
  EXPECT_EQ(m.hart.x(8), ~2046u);
  EXPECT_EQ(m.hart.x(9), 0x555u);
  EXPECT_EQ(m.hart.x(10), 0x0F0u);
  EXPECT_EQ(m.hart.x(11), 0x80000000u);
  EXPECT_EQ(m.hart.x(12), 1u);
  EXPECT_EQ(m.hart.x(13), 0xFFFFFFFFu);
  EXPECT_EQ(m.hart.x(14), 0x80000000u);
  EXPECT_EQ(m.hart.x(15), 0xABCDE000u);
  EXPECT_EQ(m.hart.x(16), Machine::kCodeBase + 15 * 4 + 0x1000);
}

TEST(IssRv32i, RegisterZeroStaysZero) {
  Machine m({addi(0, 0, 5), lui(0, 0x12345000u), add(0, 0, 0), lw(0, 1, 0), jal(0, 4), addi(2, 0, 0)});
  m.hart.set_x(1, Machine::kDataBase);
  m.memory.write32(Machine::kDataBase, 0xDEADBEEF);
  ASSERT_EQ(m.run().reason, StopReason::kHalt);
  EXPECT_EQ(m.hart.x(0), 0u);
  EXPECT_EQ(m.hart.x(2), 0u);
  m.hart.set_x(0, 7);  // debugger writes to x0 are ignored too
  EXPECT_EQ(m.hart.x(0), 0u);
}

TEST(IssRv32i, LoadsSignAndZeroExtend) {
  Machine m({lb(2, 1, 0), lbu(3, 1, 0), lh(4, 1, 0), lhu(5, 1, 0), lw(6, 1, 0), lb(7, 1, 3), lh(8, 1, 2),
             lbu(9, 1, 3), lw(10, 1, -4)});
  m.hart.set_x(1, Machine::kDataBase + 8);
  m.memory.write32(Machine::kDataBase + 8, 0x7FFF8F80u);
  m.memory.write32(Machine::kDataBase + 4, 0x01020304u);
  ASSERT_EQ(m.run().reason, StopReason::kHalt);
  EXPECT_EQ(m.hart.x(2), 0xFFFFFF80u);
  EXPECT_EQ(m.hart.x(3), 0x80u);
  EXPECT_EQ(m.hart.x(4), 0xFFFF8F80u);
  EXPECT_EQ(m.hart.x(5), 0x8F80u);
  EXPECT_EQ(m.hart.x(6), 0x7FFF8F80u);
  EXPECT_EQ(m.hart.x(7), 0x7Fu);
  EXPECT_EQ(m.hart.x(8), 0x7FFFu);
  EXPECT_EQ(m.hart.x(9), 0x7Fu);
  EXPECT_EQ(m.hart.x(10), 0x01020304u);  // negative offset
}

TEST(IssRv32i, StoresWriteOnlyTheirBytes) {
  Machine m({sw(2, 1, 0), sb(3, 1, 1), sh(3, 1, 2), sw(2, 1, -4), sb(2, 1, -1)});
  m.hart.set_x(1, Machine::kDataBase + 8);
  m.hart.set_x(2, 0x11223344u);
  m.hart.set_x(3, 0xAABBCCDDu);
  ASSERT_EQ(m.run().reason, StopReason::kHalt);
  EXPECT_EQ(m.memory.read32(Machine::kDataBase + 8), 0xCCDDDD44u);
  EXPECT_EQ(m.memory.read32(Machine::kDataBase + 4), 0x44223344u);
}

struct BranchCase {
  uint32_t (*make)(uint32_t, uint32_t, int32_t);
  uint32_t a, b;
  bool taken;
};

TEST(IssRv32i, BranchesTakenAndNotTaken) {
  const BranchCase cases[] = {
      {beq, 5, 5, true},           {beq, 5, 6, false},          {bne, 5, 6, true},
      {bne, 5, 5, false},          {blt, 0xFFFFFFFFu, 0, true}, {blt, 0, 0xFFFFFFFFu, false},
      {blt, 3, 3, false},          {bge, 3, 3, true},           {bge, 0xFFFFFFFFu, 0, false},
      {bge, 0, 0x80000000u, true}, {bltu, 0, 0xFFFFFFFFu, true}, {bltu, 0xFFFFFFFFu, 0, false},
      {bgeu, 0xFFFFFFFFu, 0, true}, {bgeu, 0, 1, false},        {bgeu, 7, 7, true},
  };
  for (const BranchCase& c : cases) {
    // branch over one instruction that would set x3
    Machine m({c.make(1, 2, 8), addi(3, 0, 1), addi(4, 0, 1)});
    m.hart.set_x(1, c.a);
    m.hart.set_x(2, c.b);
    ASSERT_EQ(m.run().reason, StopReason::kHalt);
    EXPECT_EQ(m.hart.x(3), c.taken ? 0u : 1u) << c.a << " vs " << c.b;
    EXPECT_EQ(m.hart.x(4), 1u);
  }
}

TEST(IssRv32i, BackwardBranchLoop) {
  // x1 = 10; do { x2 += x1; x1 -= 1 } while (x1 != 0)
  Machine m({addi(1, 0, 10), add(2, 2, 1), addi(1, 1, -1), bne(1, 0, -8)});
  ASSERT_EQ(m.run().reason, StopReason::kHalt);
  EXPECT_EQ(m.hart.x(2), 55u);
  EXPECT_EQ(m.hart.instructions_retired(), 1u + 3 * 10 + 1);
}

TEST(IssRv32i, JalAndJalrLinkAndTarget) {
  const uint32_t base = Machine::kCodeBase;
  Machine m({jal(1, 12), addi(5, 0, 1), halt(), jalr(2, 1, 4), addi(6, 0, 1)});
  ASSERT_EQ(m.run().reason, StopReason::kHalt);
  EXPECT_EQ(m.hart.x(1), base + 4);
  EXPECT_EQ(m.hart.x(2), base + 16);
  EXPECT_EQ(m.hart.x(5), 0u);  // skipped by jal
  EXPECT_EQ(m.hart.pc(), base + 8);  // jalr went to x1 + 4, the halt
}

TEST(IssRv32i, JalrClearsBitZeroAndHandlesRdEqualsRs1) {
  Machine m({jalr(1, 1, 1), addi(5, 0, 1), addi(6, 0, 1)});
  m.hart.set_x(1, Machine::kCodeBase + 8);
  ASSERT_EQ(m.run().reason, StopReason::kHalt);
  EXPECT_EQ(m.hart.x(1), Machine::kCodeBase + 4);  // link written after the target was read
  EXPECT_EQ(m.hart.x(5), 0u);
  EXPECT_EQ(m.hart.x(6), 1u);
}

TEST(IssRv32i, FenceAndWfiAreNoOps) {
  Machine m({fence(), wfi(), fence_i(), addi(1, 0, 3)});
  ASSERT_EQ(m.run().reason, StopReason::kHalt);
  EXPECT_EQ(m.hart.x(1), 3u);
}

TEST(IssRv32i, MalformedEncodingsAreIllegal) {
  const uint32_t words[] = {
      0x00000000u,              // all zeros
      0xFFFFFFFFu,              // longer-instruction prefix
      r(0x01, 1, 2, 1, 3, 0x13),  // slli with funct7 bit 0 set (shamt[5] on RV32)
      b(8, 1, 2, 2),            // branch funct3 2
      i(0, 1, 3, 2, 0x03),      // load funct3 3 (ld)
      s(0, 1, 2, 3, 0x23),      // store funct3 3 (sd)
      r(0x40, 1, 2, 0, 3, 0x33),  // OP funct7 0x40
      i(0, 1, 1, 2, 0x67),      // jalr funct3 1
      0x00200073u,              // SYSTEM funct3 0 with unknown immediate (uret)
      fop(0x00, 1, 2, 3, 5),    // fadd with reserved rounding mode 5
      r4(1, 2, 3, 0, 4, 0x43) | (1u << 25),  // fmadd.d (fmt D)
  };
  for (uint32_t w : words) {
    Machine m({w});
    const RunResult r = m.run();
    EXPECT_EQ(r.reason, StopReason::kTrap) << std::hex << w;
    EXPECT_EQ(r.cause, cause::kIllegalInstruction) << std::hex << w;
    EXPECT_EQ(r.tval, w);
    EXPECT_EQ(r.pc, Machine::kCodeBase);
    EXPECT_EQ(r.insn, w);
  }
}

}  // namespace
}  // namespace strata::iss::testing
