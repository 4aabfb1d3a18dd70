// The disassembler and the per-instruction trace.
#include "iss_test_support.h"

#include "model/iss/disassembler.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace strata::iss::testing {
namespace {

using namespace enc;

TEST(IssDisassembler, Formats) {
  const uint32_t pc = 0x1000;
  EXPECT_EQ(disassemble(add(10, 11, 12), pc), "add a0, a1, a2");
  EXPECT_EQ(disassemble(addi(2, 2, -16), pc), "addi sp, sp, -16");
  EXPECT_EQ(disassemble(srai(5, 6, 31), pc), "srai t0, t1, 31");
  EXPECT_EQ(disassemble(lw(10, 2, 8), pc), "lw a0, 8(sp)");
  EXPECT_EQ(disassemble(sb(11, 10, -1), pc), "sb a1, -1(a0)");
  EXPECT_EQ(disassemble(beq(10, 0, -8), pc), "beq a0, zero, 0x00000ff8");
  EXPECT_EQ(disassemble(jal(1, 0x100), pc), "jal ra, 0x00001100");
  EXPECT_EQ(disassemble(jalr(0, 1, 0), pc), "jalr zero, 0(ra)");
  EXPECT_EQ(disassemble(lui(10, 0x12345000u), pc), "lui a0, 0x12345");
  EXPECT_EQ(disassemble(csrrs(10, csr::kMcause, 0), pc), "csrrs a0, mcause, zero");
  EXPECT_EQ(disassemble(csrrwi(0, 0x7C0, 3), pc), "csrrwi zero, 0x7c0, 3");
  EXPECT_EQ(disassemble(ecall(), pc), "ecall");
  EXPECT_EQ(disassemble(fence(), pc), "fence iorw, iorw");
  EXPECT_EQ(disassemble(flw(10, 11, 4), pc), "flw fa0, 4(a1)");
  EXPECT_EQ(disassemble(fsw(10, 2, 0), pc), "fsw fa0, 0(sp)");
  EXPECT_EQ(disassemble(fadd(10, 11, 12), pc), "fadd.s fa0, fa1, fa2");
  EXPECT_EQ(disassemble(fadd(10, 11, 12, 1), pc), "fadd.s fa0, fa1, fa2, rtz");
  EXPECT_EQ(disassemble(fmadd(0, 1, 2, 3, 0), pc), "fmadd.s ft0, ft1, ft2, ft3, rne");
  EXPECT_EQ(disassemble(fcvt_w_s(10, 10, 1), pc), "fcvt.w.s a0, fa0, rtz");
  EXPECT_EQ(disassemble(feq(10, 0, 1), pc), "feq.s a0, ft0, ft1");
  EXPECT_EQ(disassemble(halt(), pc), "strata.halt");
  EXPECT_EQ(disassemble(strata(STRATA_OPCODE_PIPE, STRATA_F3_PIPE_TEST, STRATA_BOX_TEST, 10, 0, 15), pc),
            "strata.boxtest a0, fa5");
  EXPECT_EQ(disassemble(strata(STRATA_OPCODE_THREAD, STRATA_F3_STREAM, STRATA_STREAM_PUSH, 10, 11, 12), pc),
            "strata.streampush a0, a1, a2");
  EXPECT_EQ(disassemble(0xFFFFFFFFu, pc), "illegal 0xffffffff");
}

TEST(IssTrace, PrintsPcDisassemblyAndWrites) {
  std::FILE* out = std::tmpfile();
  ASSERT_NE(out, nullptr);
  Machine m({addi(10, 0, 42), sw(10, 11, 0), lw(12, 11, 1)});
  m.hart.set_x(11, Machine::kDataBase);
  m.hart.set_trace(out);
  m.run();
  std::rewind(out);
  std::string text;
  char buf[256];
  while (std::fgets(buf, sizeof buf, out)) text += buf;
  std::fclose(out);
  EXPECT_NE(text.find("00001000 02a00513  addi a0, zero, 42"), std::string::npos) << text;
  EXPECT_NE(text.find("a0=0x0000002a"), std::string::npos) << text;
  EXPECT_NE(text.find("sw a0, 0(a1)"), std::string::npos) << text;
  EXPECT_NE(text.find("trap: load address misaligned"), std::string::npos) << text;
}

}  // namespace
}  // namespace strata::iss::testing
