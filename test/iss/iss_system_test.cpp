// Zicsr, the machine-mode CSRs, traps, the instruction limit, tohost and self-modifying code.
#include "iss_test_support.h"

#include <gtest/gtest.h>

namespace strata::iss::testing {
namespace {

using namespace enc;

TEST(IssCsr, ReadWriteSetClearForms) {
  Machine m({csrrw(2, csr::kMscratch, 1), csrrs(3, csr::kMscratch, 4), csrrc(5, csr::kMscratch, 6),
             csrrwi(7, csr::kMscratch, 21), csrrsi(8, csr::kMscratch, 10), csrrci(9, csr::kMscratch, 1),
             csrrs(10, csr::kMscratch, 0)});
  m.hart.set_x(1, 0xF0F0F0F0u);
  m.hart.set_x(4, 0x0000000Fu);
  m.hart.set_x(6, 0xF0000000u);
  m.hart.write_csr(csr::kMscratch, 0x11111111u);
  ASSERT_EQ(m.run().reason, StopReason::kHalt);
  EXPECT_EQ(m.hart.x(2), 0x11111111u);
  EXPECT_EQ(m.hart.x(3), 0xF0F0F0F0u);
  EXPECT_EQ(m.hart.x(5), 0xF0F0F0FFu);
  EXPECT_EQ(m.hart.x(7), 0x00F0F0FFu);
  EXPECT_EQ(m.hart.x(8), 21u);
  EXPECT_EQ(m.hart.x(9), 31u);
  EXPECT_EQ(m.hart.x(10), 30u);
}

TEST(IssCsr, ReadOnlyCsrsReadWithX0SourceButTrapOnWrite) {
  Machine ok({csrrs(1, csr::kMhartid, 0), csrrsi(2, csr::kMhartid, 0), csrrs(3, csr::kMisa, 0)}, nullptr, 7);
  ASSERT_EQ(ok.run().reason, StopReason::kHalt);
  EXPECT_EQ(ok.hart.x(1), 7u);
  EXPECT_EQ(ok.hart.x(2), 7u);
  EXPECT_EQ(ok.hart.x(3), kMisa);
  EXPECT_EQ(kMisa >> 30, 1u);

  for (uint32_t w : {csrrw(0, csr::kMhartid, 0), csrrs(1, csr::kMhartid, 2), csrrwi(0, csr::kCycle, 1),
                     csrrs(1, 0x7C0, 0) /* not implemented */}) {
    Machine m({w});
    m.hart.set_x(2, 1);
    const RunResult r = m.run();
    EXPECT_EQ(r.reason, StopReason::kTrap) << std::hex << w;
    EXPECT_EQ(r.cause, cause::kIllegalInstruction);
    EXPECT_EQ(r.tval, w);
  }
}

TEST(IssCsr, CountersCountRetiredInstructions) {
  Machine m({nop(), nop(), csrrs(1, csr::kMinstret, 0), csrrs(2, csr::kInstret, 0), csrrs(3, csr::kMcycle, 0),
             csrrw(0, csr::kMinstret, 4), csrrs(5, csr::kMinstret, 0), csrrs(6, csr::kMinstreth, 0)});
  m.hart.set_x(4, 1000);
  ASSERT_EQ(m.run().reason, StopReason::kHalt);
  EXPECT_EQ(m.hart.x(1), 2u);  // the reading instruction has not retired yet
  EXPECT_EQ(m.hart.x(2), 3u);
  EXPECT_EQ(m.hart.x(3), 4u);  // mcycle = retired instructions in a functional run
  EXPECT_EQ(m.hart.x(5), 1000u);  // the written value: the writing instruction's increment is lost
  EXPECT_EQ(m.hart.x(6), 0u);
  m.hart.add_stall_cycles(50);
  EXPECT_EQ(m.csr(csr::kMcycle), 9u + 50u);
}

TEST(IssCsr, AWrittenCycleCountIsWhatTheNextInstructionReads) {
  Machine m({csrrw(0, csr::kMcycle, 4), csrrs(5, csr::kMcycle, 0), nop(), csrrs(6, csr::kMcycle, 0),
             csrrw(0, csr::kMinstreth, 7), csrrs(8, csr::kMinstreth, 0), csrrs(9, csr::kMinstret, 0)});
  m.hart.set_x(4, 500);
  m.hart.set_x(7, 2);
  ASSERT_EQ(m.run().reason, StopReason::kHalt);
  EXPECT_EQ(m.hart.x(5), 500u);
  EXPECT_EQ(m.hart.x(6), 502u);  // two more instructions retired since
  EXPECT_EQ(m.hart.x(8), 2u);
  EXPECT_EQ(m.hart.x(9), 5u);  // low half: 4 before the write, whose own count is lost, +1 (the read)
}

TEST(IssCsr, FloatingPointCsrsComposeAndNeedFs) {
  Machine off({csrrs(1, csr::kFflags, 0)});
  const RunResult r = off.run();
  EXPECT_EQ(r.reason, StopReason::kTrap);
  EXPECT_EQ(r.cause, cause::kIllegalInstruction);

  Machine m({csrrwi(0, csr::kFcsr, 0), csrrwi(0, csr::kFrm, 3), csrrwi(0, csr::kFflags, 0x15),
             csrrs(1, csr::kFcsr, 0), csrrw(2, csr::kFcsr, 3), csrrs(4, csr::kFrm, 0), csrrs(5, csr::kFflags, 0),
             csrrs(6, csr::kMstatus, 0)});
  m.enable_fp();
  m.hart.set_x(3, 0xFFu);
  ASSERT_EQ(m.run().reason, StopReason::kHalt);
  EXPECT_EQ(m.hart.x(1), (3u << 5) | 0x15u);
  EXPECT_EQ(m.hart.x(2), (3u << 5) | 0x15u);
  EXPECT_EQ(m.hart.x(4), 7u);
  EXPECT_EQ(m.hart.x(5), 0x1Fu);
  EXPECT_EQ(m.hart.x(6) & mstatus::kFs, mstatus::kFsDirty);  // writing FP state dirties it
  EXPECT_NE(m.hart.x(6) & mstatus::kSd, 0u);
}

TEST(IssCsr, WarlFields) {
  Machine m({});
  m.hart.write_csr(csr::kMepc, 0x1003);
  m.hart.write_csr(csr::kMtvec, 0x2003);
  m.hart.write_csr(csr::kMstatus, 0xFFFFFFFFu);
  m.hart.write_csr(csr::kMisa, 0);
  EXPECT_EQ(m.csr(csr::kMepc), 0x1000u);
  EXPECT_EQ(m.csr(csr::kMtvec), 0x2001u);
  EXPECT_EQ(m.csr(csr::kMstatus),
            mstatus::kMie | mstatus::kMpie | mstatus::kMpp | mstatus::kFs | mstatus::kSd);
  EXPECT_EQ(m.csr(csr::kMisa), kMisa);
}

struct TrapCase {
  const char* name;
  std::vector<uint32_t> code;
  uint32_t x1;
  uint32_t cause;
  uint32_t tval;
};

std::vector<TrapCase> trap_cases() {
  const uint32_t data = Machine::kDataBase;
  return {
      {"load misaligned", {lw(2, 1, 1)}, data, cause::kLoadMisaligned, data + 1},
      {"half load misaligned", {lhu(2, 1, 3)}, data, cause::kLoadMisaligned, data + 3},
      {"load access fault", {lw(2, 1, 0)}, 0x100, cause::kLoadAccessFault, 0x100},
      {"byte load past the end", {lb(2, 1, 0)}, Machine::kCodeBase + Machine::kMemorySize, cause::kLoadAccessFault,
       Machine::kCodeBase + Machine::kMemorySize},
      {"store misaligned", {sw(2, 1, 2)}, data, cause::kStoreMisaligned, data + 2},
      {"store access fault", {sh(2, 1, 0)}, 0xFFFFFFF0u, cause::kStoreAccessFault, 0xFFFFFFF0u},
      {"ecall", {ecall()}, 0, cause::kEcallM, 0},
      {"ebreak", {ebreak()}, 0, cause::kBreakpoint, Machine::kCodeBase},
      {"jump misaligned", {jalr(0, 1, 2)}, Machine::kCodeBase, cause::kInstructionMisaligned,
       Machine::kCodeBase + 2},
      {"branch misaligned", {beq(0, 0, 6)}, 0, cause::kInstructionMisaligned, Machine::kCodeBase + 6},
  };
}

TEST(IssTrap, UnhandledExceptionsStopWithPcInstructionAndReason) {
  for (const TrapCase& c : trap_cases()) {
    Machine m(c.code);
    m.hart.set_x(1, c.x1);
    const RunResult r = m.run();
    EXPECT_EQ(r.reason, StopReason::kTrap) << c.name;
    EXPECT_EQ(r.cause, c.cause) << c.name;
    EXPECT_EQ(r.tval, c.tval) << c.name;
    EXPECT_EQ(r.pc, Machine::kCodeBase) << c.name;
    EXPECT_EQ(r.insn, c.code[0]) << c.name;
    EXPECT_EQ(r.executed, 0u) << c.name;
    EXPECT_EQ(m.hart.pc(), Machine::kCodeBase) << c.name;
    EXPECT_NE(describe(r).find(cause_name(c.cause)), std::string::npos) << describe(r);
  }
}

TEST(IssTrap, FetchOutsideCodeIsAnAccessFault) {
  Machine m({jalr(0, 1, 0)});
  m.hart.set_x(1, Machine::kDataBase);  // data, not code
  const RunResult r = m.run();
  EXPECT_EQ(r.reason, StopReason::kTrap);
  EXPECT_EQ(r.cause, cause::kInstructionAccessFault);
  EXPECT_EQ(r.tval, Machine::kDataBase);
  EXPECT_EQ(r.pc, Machine::kDataBase);
  EXPECT_EQ(r.insn, 0u);
  EXPECT_EQ(r.executed, 1u);
}

TEST(IssTrap, HandledExceptionsSetMachineCsrsAndReturn) {
  const uint32_t handler = Machine::kCodeBase + 4 * 12;
  for (const TrapCase& c : trap_cases()) {
    if (c.cause == cause::kInstructionMisaligned) continue;  // mepc + 4 would not skip a jump's target
    // 0-2: point mtvec at the handler; 3: the faulting instruction; 4: where mret returns.
    std::vector<uint32_t> code = {lui(10, handler & 0xFFFFF000u), addi(10, 10, static_cast<int32_t>(handler & 0xFFFu)),
                                  csrrw(0, csr::kMtvec, 10), c.code[0], addi(20, 0, 1), halt()};
    while (code.size() < 12) code.push_back(nop());
    // handler: read CSRs, bump mepc, mret
    code.push_back(csrrs(11, csr::kMcause, 0));
    code.push_back(csrrs(12, csr::kMepc, 0));
    code.push_back(csrrs(13, csr::kMtval, 0));
    code.push_back(csrrs(14, csr::kMstatus, 0));
    code.push_back(addi(15, 12, 4));
    code.push_back(csrrw(0, csr::kMepc, 15));
    code.push_back(mret());
    Machine m(code);
    m.hart.set_x(1, c.x1);
    m.hart.write_csr(csr::kMstatus, mstatus::kMie);
    const RunResult r = m.run();
    ASSERT_EQ(r.reason, StopReason::kHalt) << c.name << ": " << describe(r);
    EXPECT_EQ(m.hart.x(11), c.cause) << c.name;
    const uint32_t fault_pc = Machine::kCodeBase + 12;
    EXPECT_EQ(m.hart.x(12), fault_pc) << c.name;
    EXPECT_EQ(m.hart.x(13), c.cause == cause::kBreakpoint ? fault_pc : c.tval) << c.name;
    EXPECT_EQ(m.hart.x(14) & (mstatus::kMie | mstatus::kMpie), mstatus::kMpie) << c.name;
    EXPECT_EQ(m.hart.x(14) & mstatus::kMpp, mstatus::kMpp) << c.name;
    EXPECT_EQ(m.hart.x(20), 1u) << c.name;
    EXPECT_NE(m.csr(csr::kMstatus) & mstatus::kMie, 0u) << c.name;  // mret restored MIE
  }
}

TEST(IssTrap, HandlerOutsideCodeStops) {
  Machine m({ecall()});
  m.hart.write_csr(csr::kMtvec, Machine::kDataBase);
  const RunResult r = m.run();
  EXPECT_EQ(r.reason, StopReason::kTrap);
  EXPECT_EQ(r.cause, cause::kEcallM);
}

TEST(IssLimit, StopsAtTheLimitAndResumes) {
  Machine m({addi(1, 1, 1), jal(0, -4)});
  RunResult r = m.run(1000);
  EXPECT_EQ(r.reason, StopReason::kInstructionLimit);
  EXPECT_EQ(r.executed, 1000u);
  EXPECT_EQ(m.hart.x(1), 500u);
  r = m.run(11);
  EXPECT_EQ(r.executed, 11u);
  EXPECT_EQ(m.hart.x(1), 506u);
  EXPECT_EQ(m.hart.instructions_retired(), 1011u);
  r = m.hart.step();
  EXPECT_EQ(r.executed, 1u);
  EXPECT_EQ(r.pc, Machine::kCodeBase);
  EXPECT_EQ(m.run(0).executed, 0u);
}

TEST(IssLimit, TrapLoopsAreBoundedToo) {
  Machine m({ecall()});
  m.hart.write_csr(csr::kMtvec, Machine::kCodeBase);  // the handler is the ecall itself
  const RunResult r = m.run(100);
  EXPECT_EQ(r.reason, StopReason::kInstructionLimit);
  EXPECT_EQ(r.executed, 0u);
}

TEST(IssToHost, ExitCodeEndsTheRun) {
  const uint32_t tohost = Machine::kDataBase + 64;
  Machine m({addi(2, 0, (5 << 1) | 1), sw(0, 1, 0), sw(2, 1, 4), sw(2, 1, 0), addi(3, 0, 1)});
  m.hart.set_x(1, tohost);
  m.hart.set_tohost(tohost);
  const RunResult r = m.run();
  EXPECT_EQ(r.reason, StopReason::kToHost);
  EXPECT_EQ(r.exit_code, 5u);
  EXPECT_EQ(r.pc, Machine::kCodeBase + 12);
  EXPECT_EQ(r.executed, 4u);  // the store retired; zero and the neighbouring word did not stop
  EXPECT_EQ(m.hart.x(3), 0u);
  EXPECT_FALSE(r.ok());
}

TEST(IssSelfModifyingCode, StoresIntoCodeAreReDecoded) {
  // Overwrite instruction 3 (addi x5, x0, 1) with addi x5, x0, 2 before reaching it.
  Machine m({lw(2, 1, 0), sw(2, 3, 0), fence_i(), addi(5, 0, 1)});
  m.memory.write32(Machine::kDataBase, addi(5, 0, 2));
  m.hart.set_x(1, Machine::kDataBase);
  m.hart.set_x(3, Machine::kCodeBase + 12);
  ASSERT_EQ(m.run().reason, StopReason::kHalt);
  EXPECT_EQ(m.hart.x(5), 2u);
}

TEST(IssRunResult, DescribesEveryReason) {
  RunResult r;
  r.reason = StopReason::kTrap;
  r.cause = cause::kLoadAccessFault;
  r.pc = 0x1234;
  r.insn = enc::lw(10, 11, 0);
  r.tval = 0xDEAD;
  const std::string text = describe(r);
  EXPECT_NE(text.find("load access fault"), std::string::npos) << text;
  EXPECT_NE(text.find("0x00001234"), std::string::npos) << text;
  EXPECT_NE(text.find("lw a0, 0(a1)"), std::string::npos) << text;
  EXPECT_NE(text.find("0x0000dead"), std::string::npos) << text;
  r.reason = StopReason::kHookError;
  r.detail = "pipeline missing";
  EXPECT_NE(describe(r).find("pipeline missing"), std::string::npos);
  r.reason = StopReason::kInstructionLimit;
  EXPECT_NE(describe(r).find("instruction limit"), std::string::npos);
}

}  // namespace
}  // namespace strata::iss::testing
