// In-order issue timing of a TP: dependency chains, memory latency from the caller, XU
// contention between TPs, the fused pipelines as seen from the instruction stream, and the
// stall cycles by cause.
#include "model/tm/tp_timing.h"
#include "test/tm/tm_test_support.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace strata::tm {
namespace {

using testing::decoded;
using testing::enc::add;
using testing::enc::addi;
using testing::enc::fadd;
using testing::enc::fdiv;
using testing::enc::fmadd;
using testing::enc::fmul;
using testing::enc::fsw;
using testing::enc::lw;
using testing::enc::sw;
namespace st = testing::st;

class TpTimingTest : public ::testing::Test {
 protected:
  explicit TpTimingTest(const TmConfig& c = TmConfig{}) : config(c), table(config), xus(config), tp(table) {}

  Cycle issue(TpTiming& t, uint32_t word, Cycle fetch_ready = 0) {
    return t.issue(decoded(word), fetch_ready, xus).issue;
  }
  Cycle issue(uint32_t word, Cycle fetch_ready = 0) { return issue(tp, word, fetch_ready); }
  // A memory-like op whose access the memory system accepts at once and answers after `latency`.
  Cycle memory(TpTiming& t, uint32_t word, Cycle latency) {
    const iss::Decoded d = decoded(word);
    const Cycle at = t.begin_memory(d, 0);
    return t.complete_memory(d, at, at + latency).issue;
  }
  Cycle memory(uint32_t word, Cycle latency) { return memory(tp, word, latency); }
  uint64_t stalls(const TpTiming& t, StallCause c) const { return t.stats().stalls(c); }

  TmConfig config;
  OpTimingTable table;
  XuCrossbar xus;
  TpTiming tp;
};

TEST_F(TpTimingTest, DependentFpChainIssuesEveryTwoCycles) {
  EXPECT_EQ(issue(fmul(1, 2, 3)), 0u);
  EXPECT_EQ(issue(fadd(4, 1, 5)), 2u);  // waits for f1
  EXPECT_EQ(issue(fmul(6, 4, 7)), 4u);  // waits for f4
  EXPECT_EQ(tp.fp_ready(6), 6u);
  EXPECT_EQ(tp.next_issue(), 5u);
  EXPECT_EQ(stalls(tp, StallCause::kOperand), 2u);
  EXPECT_EQ(tp.stats().total_stalls(), 2u);
}

TEST_F(TpTimingTest, IndependentOpsIssueBackToBack) {
  EXPECT_EQ(issue(fmul(1, 2, 3)), 0u);
  EXPECT_EQ(issue(fadd(4, 5, 6)), 1u);
  EXPECT_EQ(issue(fmul(7, 8, 9)), 2u);
  EXPECT_EQ(tp.stats().total_stalls(), 0u);
}

TEST_F(TpTimingTest, IntegerAluChainHasNoBubbles) {
  EXPECT_EQ(issue(addi(1, 0, 1)), 0u);
  EXPECT_EQ(issue(addi(2, 1, 1)), 1u);
  EXPECT_EQ(issue(add(3, 2, 1)), 2u);
  EXPECT_EQ(tp.int_ready(3), 3u);
}

TEST_F(TpTimingTest, LoadUseWaitsForTheMemorySystem) {
  EXPECT_EQ(memory(lw(1, 2, 0), 30), 0u);  // data at 30
  EXPECT_EQ(issue(addi(5, 0, 1)), 1u);     // independent: no wait
  EXPECT_EQ(issue(add(3, 1, 1)), 30u);
  EXPECT_EQ(stalls(tp, StallCause::kMemory), 28u);
  EXPECT_EQ(stalls(tp, StallCause::kOperand), 0u);
}

TEST_F(TpTimingTest, MemoryNotAcceptingYetIsAMemoryStall) {
  const iss::Decoded d = decoded(sw(1, 2, 0));
  EXPECT_EQ(tp.begin_memory(d, 0), 0u);
  const IssueTiming t = tp.complete_memory(d, 3, 0);  // a busy bank takes it at 3
  EXPECT_EQ(t.issue, 3u);
  EXPECT_EQ(tp.next_issue(), 4u);
  EXPECT_EQ(stalls(tp, StallCause::kMemory), 3u);
}

TEST_F(TpTimingTest, StoreWaitsForTheValueItStores) {
  EXPECT_EQ(issue(fmul(1, 2, 3)), 0u);
  EXPECT_EQ(tp.begin_memory(decoded(fsw(1, 2, 0)), 0), 2u);
}

TEST_F(TpTimingTest, NinthTpWaitsOneCycleForAMultiplier) {
  std::vector<TpTiming> tps(9, TpTiming(table));
  for (unsigned i = 0; i < 9; ++i) EXPECT_EQ(issue(tps[i], fmul(1, 2, 3)), i < 8 ? 0u : 1u);
  EXPECT_EQ(stalls(tps[8], StallCause::kStructural), 1u);
  EXPECT_EQ(tps[8].fp_ready(1), 3u);
}

TEST_F(TpTimingTest, DividesOfTwoTpsAreSerialised) {
  TpTiming other(table);
  EXPECT_EQ(issue(fdiv(1, 2, 3)), 0u);
  EXPECT_EQ(issue(other, fdiv(1, 2, 3)), 16u);
  EXPECT_EQ(stalls(other, StallCause::kStructural), 16u);
  EXPECT_EQ(other.fp_ready(1), 32u);
}

TEST_F(TpTimingTest, FusedMultiplyAddTakesBothLatencies) {
  EXPECT_EQ(issue(fmadd(1, 2, 3, 4)), 0u);
  EXPECT_EQ(tp.fp_ready(1), 4u);
  EXPECT_EQ(issue(fadd(5, 1, 1)), 4u);
}

TEST_F(TpTimingTest, WriteAfterWriteWaitsForTheEarlierWrite) {
  EXPECT_EQ(issue(fdiv(1, 2, 3)), 0u);
  EXPECT_EQ(issue(fadd(1, 4, 5)), 16u);  // must not overtake the divide to f1
  EXPECT_EQ(tp.fp_ready(1), 18u);
}

TEST_F(TpTimingTest, FetchReadyDelaysIssue) {
  EXPECT_EQ(issue(addi(1, 0, 1), 5), 5u);
  EXPECT_EQ(stalls(tp, StallCause::kFetch), 5u);
}

TEST_F(TpTimingTest, ConfigureDoesNotStallTheTpButTheBoxTestWaits) {
  const IssueTiming cfg = tp.issue(decoded(st::pipe_box()), 0, xus);
  EXPECT_EQ(cfg.issue, 0u);
  EXPECT_EQ(cfg.result_ready, 4u);  // the mode is usable at 0 + reconfigure_cycles
  EXPECT_EQ(issue(addi(1, 0, 1)), 1u);
  EXPECT_EQ(issue(st::boxtest(5, 6)), 4u);
  EXPECT_EQ(stalls(tp, StallCause::kStructural), 2u);
  EXPECT_EQ(tp.int_ready(5), 12u);
  EXPECT_EQ(tp.fp_ready(6), 12u);
}

TEST_F(TpTimingTest, BoxTestWaitsForItsInputRegisters) {
  issue(st::pipe_box());                            // usable at 4
  EXPECT_EQ(memory(st::ldray(10), 19), 1u);         // ray inputs at 20
  EXPECT_EQ(memory(st::ldbox(11), 19), 2u);         // box inputs at 21
  EXPECT_EQ(issue(st::boxtest(5, 6)), 21u);
  EXPECT_EQ(stalls(tp, StallCause::kMemory), 18u);  // slot 3, inputs at 21
  EXPECT_EQ(issue(add(7, 5, 0)), 29u);              // the hit flag after 8 cycles
  EXPECT_EQ(stalls(tp, StallCause::kOperand), 7u);
}

TEST_F(TpTimingTest, BoxTestsOfTenTpsStartOneCycleApart) {
  std::vector<TpTiming> tps(10, TpTiming(table));
  EXPECT_EQ(issue(tps[0], st::pipe_box()), 0u);  // usable at 4
  for (unsigned i = 0; i < 10; ++i) {
    const IssueTiming t = tps[i].issue(decoded(st::boxtest(5, 6)), 0, xus);
    EXPECT_EQ(t.issue, 4u + i);
    EXPECT_EQ(t.result_ready, 12u + i);
  }
}

TEST_F(TpTimingTest, TriangleTestThenDivide) {
  issue(st::pipe_triangle());                 // usable at 4
  EXPECT_EQ(memory(st::ldray(10), 9), 1u);    // ready at 10
  EXPECT_EQ(memory(st::ldtri(11), 9), 2u);    // ready at 11
  EXPECT_EQ(issue(st::tritest(5)), 11u);      // hit flag at 42
  EXPECT_EQ(tp.int_ready(5), 42u);
  EXPECT_EQ(issue(st::tridiv(1, 2, 3)), 42u); // reads the latched partial result
  for (unsigned f = 1; f <= 3; ++f) EXPECT_EQ(tp.fp_ready(f), 58u);
}

TEST_F(TpTimingTest, SetTmaxDoesNotHideAPendingRayLoad) {
  issue(st::pipe_box());
  memory(st::ldray(10), 49);                 // issue 1, ray inputs at 50
  memory(st::ldbox(11), 1);                  // issue 2
  EXPECT_EQ(issue(st::settmax(4)), 3u);
  EXPECT_EQ(issue(st::boxtest(5, 6)), 50u);
}

TEST_F(TpTimingTest, IdsAndX0) {
  EXPECT_EQ(issue(st::threadid(1)), 0u);
  EXPECT_EQ(issue(addi(2, 1, 1)), 1u);
  EXPECT_EQ(memory(lw(0, 2, 0), 100), 2u);  // a load to x0 leaves nothing pending
  EXPECT_EQ(issue(addi(0, 0, 0)), 3u);
}

TEST_F(TpTimingTest, StreamOpsAndAtomicsAreTimedByTheCaller) {
  const uint32_t memory_like[] = {lw(1, 2, 0), sw(1, 2, 0), fsw(1, 2, 0), st::atominc(1, 2), st::streampop(1, 2),
                                  st::ldray(2), st::ldtri(2)};
  for (uint32_t w : memory_like) EXPECT_TRUE(tp.is_memory(decoded(w))) << std::hex << w;
  const uint32_t not_memory[] = {fadd(1, 2, 3), st::boxtest(1, 2), st::threadid(1), st::pipe_general(),
                                 st::settmax(1)};
  for (uint32_t w : not_memory) EXPECT_FALSE(tp.is_memory(decoded(w))) << std::hex << w;
  EXPECT_EQ(memory(st::atominc(1, 2), 40), 0u);
  EXPECT_EQ(issue(add(3, 1, 1)), 40u);
}

TEST_F(TpTimingTest, WrongPhaseIsRejected) {
  EXPECT_THROW(tp.issue(decoded(lw(1, 2, 0)), 0, xus), std::logic_error);
  EXPECT_THROW(tp.begin_memory(decoded(fadd(1, 2, 3)), 0), std::logic_error);
  EXPECT_THROW(tp.complete_memory(decoded(lw(1, 2, 0)), 0, 5), std::logic_error);  // no begin
  EXPECT_THROW(tp.issue(decoded(st::boxtest(1, 2)), 0, xus), std::logic_error);   // general mode
}

TEST_F(TpTimingTest, WaitsForEveryOperandInBothRegisterFiles) {
  // fsw reads an FP source (rs2) and an int base (rs1); the later one decides, and names the
  // cause: here the divide (an XU) outlasts the load.
  memory(lw(1, 2, 0), 10);          // x1 at 10
  EXPECT_EQ(issue(fdiv(3, 4, 5)), 1u);  // f3 at 17
  EXPECT_EQ(memory(fsw(3, 1, 0), 1), 17u);
  EXPECT_EQ(stalls(tp, StallCause::kOperand), 15u);
  EXPECT_EQ(stalls(tp, StallCause::kMemory), 0u);
  // And the other way round: the load outlasts an FP source, so the wait is a memory stall.
  memory(lw(6, 2, 0), 40);          // issues at 18, x6 at 58
  EXPECT_EQ(memory(fsw(3, 6, 0), 1), 58u);
  EXPECT_EQ(stalls(tp, StallCause::kMemory), 39u);
  // x0 is never waited for, though it is a source.
  EXPECT_EQ(memory(sw(0, 0, 0), 1), 59u);
}

TEST_F(TpTimingTest, TiedOperandsNameTheFirstSlotsCause) {
  // rs1 (an int from memory) and rs2 (an FP from an XU) ready in the same cycle: fsw's
  // rs1 comes first among its operands (rd is unused), so the wait counts as memory.
  EXPECT_EQ(issue(fdiv(3, 4, 5)), 0u);  // f3 at 16
  memory(lw(1, 2, 0), 15);              // issues at 1, x1 at 16
  EXPECT_EQ(memory(fsw(3, 1, 0), 1), 16u);
  EXPECT_EQ(stalls(tp, StallCause::kMemory), 14u);
  EXPECT_EQ(stalls(tp, StallCause::kOperand), 0u);
}

TEST(TpOpTiming, EveryArithmeticOpUsesASharedUnit) {
  const OpTimingTable table{TmConfig{}};
  for (unsigned i = 0; i < iss::kOpCount; ++i) {
    const auto op = static_cast<iss::Op>(i);
    const iss::InstrClass cls = iss::op_info(op).cls;
    const Route route = table[op].route;
    if (cls == iss::InstrClass::kFpAdd || cls == iss::InstrClass::kFpMul || cls == iss::InstrClass::kFpDivSqrt ||
        cls == iss::InstrClass::kMulDiv) {
      EXPECT_EQ(route, Route::kXu) << iss::op_info(op).mnemonic;
    }
    if (cls == iss::InstrClass::kLoad || cls == iss::InstrClass::kStore || cls == iss::InstrClass::kStrataStream ||
        cls == iss::InstrClass::kStrataGlobal) {
      EXPECT_EQ(route, Route::kMemory) << iss::op_info(op).mnemonic;
    }
    if (route == Route::kLocal) {
      EXPECT_GE(table[op].latency, 1u) << iss::op_info(op).mnemonic;
    }
  }
  EXPECT_EQ(table[iss::Op::kFsqrt].xu, XuClass::kFpInvSqrt);
  EXPECT_EQ(table[iss::Op::kFlt].xu, XuClass::kFpCmp);
  EXPECT_EQ(table[iss::Op::kFcvtSW].xu, XuClass::kFpAdd);
  EXPECT_EQ(table[iss::Op::kFsgnj].route, Route::kLocal);
}

}  // namespace
}  // namespace strata::tm
