// Retired-instruction classes and register-file access counts.
#include "iss_test_support.h"

#include "model/iss/functional_strata_hook.h"

#include <gtest/gtest.h>

namespace strata::iss::testing {
namespace {

using namespace enc;

TEST(IssCounters, ClassesOfRetiredInstructions) {
  FunctionalStrataHook hook;
  Machine m({addi(1, 0, 3), add(2, 1, 1), beq(0, 0, 4), jal(0, 4), lw(3, 10, 0), sw(3, 10, 4), mul(4, 1, 1),
             div(4, 1, 1), fadd(1, 2, 3), fsub(1, 2, 3), fmul(1, 2, 3), fdiv(1, 2, 3), fsqrt(1, 2),
             fmadd(1, 2, 3, 4), fmin(1, 2, 3), fcvt_w_s(5, 1), fmv_x_w(5, 1), csrrs(6, csr::kMinstret, 0),
             fence(), strata(STRATA_OPCODE_THREAD, STRATA_F3_ID, STRATA_ID_TP, 7, 0, 0),
             strata(STRATA_OPCODE_THREAD, STRATA_F3_GLOBAL, STRATA_GLOBAL_ATOMIC_INC, 7, 0, 0),
             strata(STRATA_OPCODE_PIPE, STRATA_F3_PIPE_CONFIG, STRATA_PIPE_BOX, 0, 0, 0),
             strata(STRATA_OPCODE_PIPE, STRATA_F3_PIPE_TEST, STRATA_BOX_TEST, 8, 0, 9)},
            &hook);
  m.enable_fp();
  m.hart.set_x(10, Machine::kDataBase);
  ASSERT_EQ(m.run().reason, StopReason::kHalt);
  const Counters c = m.hart.counters();
  EXPECT_EQ(c.retired, 24u);
  EXPECT_EQ(c.retired, m.hart.instructions_retired());
  EXPECT_EQ(c.of(InstrClass::kIntAlu), 2u);
  EXPECT_EQ(c.of(InstrClass::kBranch), 2u);
  EXPECT_EQ(c.of(InstrClass::kLoad), 1u);
  EXPECT_EQ(c.of(InstrClass::kStore), 1u);
  EXPECT_EQ(c.of(InstrClass::kMulDiv), 2u);
  EXPECT_EQ(c.of(InstrClass::kFpAdd), 2u);
  EXPECT_EQ(c.of(InstrClass::kFpMul), 1u);
  EXPECT_EQ(c.of(InstrClass::kFpDivSqrt), 2u);
  EXPECT_EQ(c.of(InstrClass::kFpFused), 1u);
  EXPECT_EQ(c.of(InstrClass::kFpMisc), 3u);
  EXPECT_EQ(c.of(InstrClass::kSystem), 2u);
  EXPECT_EQ(c.of(InstrClass::kStrataId), 1u);
  EXPECT_EQ(c.of(InstrClass::kStrataGlobal), 1u);
  EXPECT_EQ(c.of(InstrClass::kStrataPipeConfig), 1u);
  EXPECT_EQ(c.of(InstrClass::kStrataBoxTest), 1u);
  EXPECT_EQ(c.of(InstrClass::kStrataControl), 1u);  // the appended halt
  EXPECT_EQ(m.hart.op_count(Op::kFadd), 1u);
  const std::string report = format_counters(c);
  EXPECT_NE(report.find("fp_div_sqrt"), std::string::npos) << report;
  EXPECT_EQ(report.find("strata_stream"), std::string::npos) << report;  // never retired: left out
}

TEST(IssCounters, RegisterFileAccessesExcludeX0) {
  // reads/writes: add 2/1, add-to-x0 2/0, addi-from-x0 0/1, sw 2/0, beq x0,x0 0/0,
  // fadd fp 2/1, fmadd fp 3/1, fcvt.w.s fp1 int-w1, boxtest int-w1 fp-w1, halt 0/0
  Machine m({add(1, 2, 3), add(0, 2, 3), addi(4, 0, 1), sw(4, 10, 0), beq(0, 0, 4), fadd(1, 2, 3),
             fmadd(1, 2, 3, 4), fcvt_w_s(5, 1, 1),
             strata(STRATA_OPCODE_PIPE, STRATA_F3_PIPE_TEST, STRATA_BOX_TEST, 8, 0, 9)});
  FunctionalStrataHook hook;
  m.hart.set_hook(&hook);
  hook.execute(HookCall{Op::kStPipeBox, 0, 0, 0, nullptr, nullptr});
  m.enable_fp();
  m.hart.set_x(10, Machine::kDataBase);
  ASSERT_EQ(m.run().reason, StopReason::kHalt);
  const Counters c = m.hart.counters();
  EXPECT_EQ(c.int_reads, 2u + 2 + 0 + 2 + 0);
  EXPECT_EQ(c.int_writes, 1u + 0 + 1 + 1 + 1);
  EXPECT_EQ(c.fp_reads, 2u + 3 + 1);
  EXPECT_EQ(c.fp_writes, 1u + 1 + 1);
}

TEST(IssCounters, TrapsDoNotRetire) {
  Machine m({lw(1, 0, 0)});
  EXPECT_EQ(m.run().reason, StopReason::kTrap);
  EXPECT_EQ(m.hart.counters().retired, 0u);
  EXPECT_EQ(m.hart.counters().int_writes, 0u);
}

}  // namespace
}  // namespace strata::iss::testing
