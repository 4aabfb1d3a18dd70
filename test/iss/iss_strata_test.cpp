// The STRaTA extension: encodings shared with firmware/abi/strata_isa.h, operand and
// memory plumbing through a recording hook, and the functional hook's semantics.
#include "iss_test_support.h"

#include "model/iss/decoder.h"
#include "model/iss/functional_strata_hook.h"

#include <gtest/gtest.h>

#include <limits>

namespace strata::iss::testing {
namespace {

using namespace enc;

constexpr uint32_t T = STRATA_OPCODE_THREAD, P = STRATA_OPCODE_PIPE;

struct Recorded {
  Op op;
  uint32_t hart, rs1, rs2;
  std::vector<uint32_t> in;
};

class RecordingHook : public StrataHook {
 public:
  HookResult execute(const HookCall& call) override {
    calls.push_back({call.op, call.hart_id, call.rs1, call.rs2,
                     std::vector<uint32_t>(call.in, call.in + strata_mem_in_words(call.op))});
    for (unsigned i = 0; i < strata_mem_out_words(call.op); ++i) call.out[i] = 0xA000u + i;
    return result;
  }
  std::vector<Recorded> calls;
  HookResult result;
};

TEST(IssStrata, EveryOperationDecodesFromTheSharedConstants) {
  const std::pair<uint32_t, Op> cases[] = {
      {strata(T, STRATA_F3_ID, STRATA_ID_THREAD, 1, 0, 0), Op::kStThreadId},
      {strata(T, STRATA_F3_ID, STRATA_ID_TP, 1, 0, 0), Op::kStTpId},
      {strata(T, STRATA_F3_ID, STRATA_ID_TM, 1, 0, 0), Op::kStTmId},
      {strata(T, STRATA_F3_ID, STRATA_ID_THREAD_COUNT, 1, 0, 0), Op::kStThreadCount},
      {strata(T, STRATA_F3_ID, STRATA_ID_TPS_PER_TM, 1, 0, 0), Op::kStTpsPerTm},
      {strata(T, STRATA_F3_ID, STRATA_ID_TM_COUNT, 1, 0, 0), Op::kStTmCount},
      {strata(T, STRATA_F3_GLOBAL, STRATA_GLOBAL_ATOMIC_INC, 1, 2, 0), Op::kStAtomicInc},
      {strata(T, STRATA_F3_GLOBAL, STRATA_GLOBAL_ATOMIC_ADD, 1, 2, 3), Op::kStAtomicAdd},
      {strata(T, STRATA_F3_GLOBAL, STRATA_GLOBAL_READ, 1, 2, 0), Op::kStGlobalRead},
      {strata(T, STRATA_F3_GLOBAL, STRATA_GLOBAL_WRITE, 0, 2, 3), Op::kStGlobalWrite},
      {strata(T, STRATA_F3_STREAM, STRATA_STREAM_CAPACITY, 1, 0, 0), Op::kStStreamCapacity},
      {strata(T, STRATA_F3_STREAM, STRATA_STREAM_PUSH, 1, 2, 3), Op::kStStreamPush},
      {strata(T, STRATA_F3_STREAM, STRATA_STREAM_POP, 1, 2, 0), Op::kStStreamPop},
      {strata(T, STRATA_F3_STREAM, STRATA_STREAM_ASSIGN, 1, 0, 0), Op::kStStreamAssign},
      {strata(T, STRATA_F3_STREAM, STRATA_STREAM_PUSH64, 1, 2, 3), Op::kStStreamPush64},
      {strata(T, STRATA_F3_STREAM, STRATA_STREAM_POP64, 1, 2, 0), Op::kStStreamPop64},
      {strata(T, STRATA_F3_CONTROL, STRATA_CONTROL_HALT, 0, 0, 0), Op::kStHalt},
      {strata(P, STRATA_F3_PIPE_CONFIG, STRATA_PIPE_GENERAL, 0, 0, 0), Op::kStPipeGeneral},
      {strata(P, STRATA_F3_PIPE_CONFIG, STRATA_PIPE_BOX, 0, 0, 0), Op::kStPipeBox},
      {strata(P, STRATA_F3_PIPE_CONFIG, STRATA_PIPE_TRIANGLE, 0, 0, 0), Op::kStPipeTriangle},
      {strata(P, STRATA_F3_PIPE_LOAD, STRATA_LOAD_RAY, 0, 2, 0), Op::kStLoadRay},
      {strata(P, STRATA_F3_PIPE_LOAD, STRATA_LOAD_BOX, 0, 2, 0), Op::kStLoadBox},
      {strata(P, STRATA_F3_PIPE_LOAD, STRATA_LOAD_TRIANGLE, 0, 2, 0), Op::kStLoadTriangle},
      {strata(P, STRATA_F3_PIPE_LOAD, STRATA_SET_TMAX, 0, 2, 0), Op::kStSetTmax},
      {strata(P, STRATA_F3_PIPE_TEST, STRATA_BOX_TEST, 1, 0, 2), Op::kStBoxTest},
      {strata(P, STRATA_F3_PIPE_TEST, STRATA_TRIANGLE_TEST, 1, 0, 0), Op::kStTriangleTest},
      {strata(P, STRATA_F3_PIPE_TEST, STRATA_TRIANGLE_DIVIDE, 1, 2, 3), Op::kStTriangleDivide},
  };
  for (const auto& [word, op] : cases) EXPECT_EQ(decode(word).op, op) << std::hex << word;
}

TEST(IssStrata, UnknownOperationsAndNonzeroUnusedFieldsAreIllegal) {
  const uint32_t words[] = {
      strata(T, 3, 0, 0, 0, 0),                                          // unused group
      strata(T, STRATA_F3_ID, 6, 1, 0, 0),                               // unused operation
      strata(T, STRATA_F3_ID, STRATA_ID_THREAD, 1, 5, 0),                // rs1 must be x0
      strata(T, STRATA_F3_CONTROL, STRATA_CONTROL_HALT, 1, 0, 0),        // rd must be x0
      strata(P, STRATA_F3_PIPE_TEST, STRATA_TRIANGLE_TEST, 1, 0, 4),     // rs2 must be x0
      strata(P, 7, 0, 0, 0, 0),
      strata(0x5B, 0, 0, 0, 0, 0),  // custom-2 is not ours
  };
  RecordingHook hook;
  for (uint32_t w : words) {
    Machine m({w}, &hook);
    const RunResult r = m.run();
    EXPECT_EQ(r.reason, StopReason::kTrap) << std::hex << w;
    EXPECT_EQ(r.cause, cause::kIllegalInstruction) << std::hex << w;
    EXPECT_EQ(r.tval, w);
  }
  EXPECT_TRUE(hook.calls.empty());
}

TEST(IssStrata, HookGetsSourcesAndWritesDestinations) {
  RecordingHook hook;
  hook.result.dest[0] = 111;
  hook.result.dest[1] = 222;
  hook.result.dest[2] = 333;
  Machine m({strata(T, STRATA_F3_GLOBAL, STRATA_GLOBAL_ATOMIC_ADD, 5, 6, 7),
             strata(P, STRATA_F3_PIPE_TEST, STRATA_BOX_TEST, 8, 0, 9),
             strata(P, STRATA_F3_PIPE_TEST, STRATA_TRIANGLE_DIVIDE, 10, 11, 12),
             strata(P, STRATA_F3_PIPE_LOAD, STRATA_SET_TMAX, 0, 13, 0),
             strata(T, STRATA_F3_GLOBAL, STRATA_GLOBAL_WRITE, 0, 6, 7)},
            &hook, 3);
  m.enable_fp();
  m.hart.set_x(6, 4);
  m.hart.set_x(7, 10);
  m.hart.set_f(13, 0x3F000000u);
  ASSERT_EQ(m.run().reason, StopReason::kHalt);
  ASSERT_EQ(hook.calls.size(), 5u);
  EXPECT_EQ(hook.calls[0].op, Op::kStAtomicAdd);
  EXPECT_EQ(hook.calls[0].hart, 3u);
  EXPECT_EQ(hook.calls[0].rs1, 4u);
  EXPECT_EQ(hook.calls[0].rs2, 10u);
  EXPECT_EQ(m.hart.x(5), 111u);
  EXPECT_EQ(m.hart.x(8), 111u);  // boxtest: hit flag to x[rd] ...
  EXPECT_EQ(m.hart.f(9), 333u);  // ... entry distance to f[rs2]
  EXPECT_EQ(m.hart.f(10), 111u);  // tridiv: t, u, v to f[rd], f[rs1], f[rs2]
  EXPECT_EQ(m.hart.f(11), 222u);
  EXPECT_EQ(m.hart.f(12), 333u);
  EXPECT_EQ(hook.calls[3].op, Op::kStSetTmax);
  EXPECT_EQ(hook.calls[3].rs1, 0x3F000000u);  // an FP source passes its bits
  EXPECT_EQ(hook.calls[4].rs1, 4u);
  EXPECT_EQ(hook.calls[4].rs2, 10u);
  EXPECT_EQ(m.hart.x(6), 4u);  // gwrite has no destination
}

TEST(IssStrata, MemoryOperandsAreReadAndWrittenThroughTheHart) {
  RecordingHook hook;
  Machine m({strata(P, STRATA_F3_PIPE_LOAD, STRATA_LOAD_RAY, 0, 1, 0),
             strata(P, STRATA_F3_PIPE_LOAD, STRATA_LOAD_BOX, 0, 1, 0),
             strata(P, STRATA_F3_PIPE_LOAD, STRATA_LOAD_TRIANGLE, 0, 1, 0),
             strata(T, STRATA_F3_STREAM, STRATA_STREAM_PUSH, 3, 1, 2)},
            &hook);
  for (uint32_t i = 0; i < 12; ++i) m.memory.write32(Machine::kDataBase + 4 * i, 0x100u + i);
  m.hart.set_x(1, Machine::kDataBase);
  m.hart.set_x(2, 42);
  ASSERT_EQ(m.run().reason, StopReason::kHalt);
  ASSERT_EQ(hook.calls.size(), 4u);
  EXPECT_EQ(hook.calls[0].in.size(), 11u);
  EXPECT_EQ(hook.calls[1].in.size(), 6u);
  EXPECT_EQ(hook.calls[2].in.size(), 9u);
  ASSERT_EQ(hook.calls[3].in.size(), 12u);
  EXPECT_EQ(hook.calls[3].in[11], 0x10Bu);
  EXPECT_EQ(hook.calls[3].rs2, 42u);

  hook.result.status = HookStatus::kStore;
  hook.result.dest[0] = 1;
  Machine pop({strata(T, STRATA_F3_STREAM, STRATA_STREAM_POP, 1, 1, 0)}, &hook);
  pop.hart.set_x(1, Machine::kDataBase + 16);
  ASSERT_EQ(pop.run().reason, StopReason::kHalt);
  EXPECT_EQ(pop.hart.x(1), 1u);  // rd == rs1: the store used the address before the write
  for (uint32_t i = 0; i < 12; ++i) EXPECT_EQ(pop.memory.read32(Machine::kDataBase + 16 + 4 * i), 0xA000u + i);
}

TEST(IssStrata, MemoryOperandFaults) {
  RecordingHook hook;
  Machine misaligned({strata(P, STRATA_F3_PIPE_LOAD, STRATA_LOAD_BOX, 0, 1, 0)}, &hook);
  misaligned.hart.set_x(1, Machine::kDataBase + 2);
  RunResult r = misaligned.run();
  EXPECT_EQ(r.cause, cause::kLoadMisaligned);
  EXPECT_EQ(r.tval, Machine::kDataBase + 2);

  Machine past_end({strata(P, STRATA_F3_PIPE_LOAD, STRATA_LOAD_BOX, 0, 1, 0)}, &hook);
  const uint32_t end = Machine::kCodeBase + Machine::kMemorySize;
  past_end.hart.set_x(1, end - 8);  // the third word is outside
  r = past_end.run();
  EXPECT_EQ(r.cause, cause::kLoadAccessFault);
  EXPECT_EQ(r.tval, end);
  EXPECT_TRUE(hook.calls.empty());

  hook.result.status = HookStatus::kStore;
  Machine pop({strata(T, STRATA_F3_STREAM, STRATA_STREAM_POP, 2, 1, 0)}, &hook);
  pop.hart.set_x(1, 0x10);
  r = pop.run();
  EXPECT_EQ(r.cause, cause::kStoreAccessFault);
  EXPECT_EQ(r.tval, 0x10u);
}

TEST(IssStrata, HookRefusalsAndMissingHook) {
  RecordingHook hook;
  hook.result.status = HookStatus::kIllegal;
  hook.result.message = "box test without box pipeline";
  const uint32_t word = strata(P, STRATA_F3_PIPE_TEST, STRATA_TRIANGLE_TEST, 1, 0, 0);
  Machine m({word}, &hook);
  RunResult r = m.run();
  EXPECT_EQ(r.reason, StopReason::kTrap);
  EXPECT_EQ(r.cause, cause::kIllegalInstruction);
  EXPECT_EQ(r.tval, word);
  EXPECT_NE(describe(r).find("box test without box pipeline"), std::string::npos) << describe(r);

  hook.result.status = HookStatus::kFatal;
  hook.result.message = "stream memory not modelled";
  Machine fatal({word}, &hook);
  r = fatal.run();
  EXPECT_EQ(r.reason, StopReason::kHookError);
  EXPECT_STREQ(r.detail, "stream memory not modelled");
  EXPECT_EQ(r.executed, 0u);

  Machine none({word});
  r = none.run();
  EXPECT_EQ(r.reason, StopReason::kHookError);
  EXPECT_NE(describe(r).find("no STRaTA hook"), std::string::npos);

  // halt needs no hook
  Machine halt_only({addi(1, 0, 1)});
  EXPECT_EQ(halt_only.run().reason, StopReason::kHalt);
}

TEST(IssStrata, ADeferredOperationStopsBeforeItselfAndRunsOnTheNextRun) {
  // Sampled timing's time-ordered fast-forward defers a stream op that must wait for another
  // TP (tm_fast_forward.cpp): the run stops on it with nothing done, and the next run starts
  // with it.
  RecordingHook hook;
  hook.result.status = HookStatus::kDefer;
  hook.result.dest[0] = 77;  // must not be written while deferring
  const uint32_t pop = strata(T, STRATA_F3_STREAM, STRATA_STREAM_POP, 3, 1, 0);
  Machine m({addi(5, 0, 9), pop, addi(6, 0, 4)}, &hook);
  m.hart.set_x(1, Machine::kDataBase);
  m.hart.set_x(3, 123);
  m.memory.write32(Machine::kDataBase, 0x5555u);
  const uint32_t at = Machine::kCodeBase + 4;
  RunResult r = m.run();
  EXPECT_EQ(r.reason, StopReason::kDeferred);
  EXPECT_EQ(r.executed, 1u);  // the addi only
  EXPECT_EQ(r.pc, at);
  EXPECT_EQ(m.hart.pc(), at);
  EXPECT_EQ(m.hart.x(3), 123u);                                 // no destination written
  EXPECT_EQ(m.memory.read32(Machine::kDataBase), 0x5555u);     // no store
  EXPECT_NE(describe(r).find("deferred"), std::string::npos) << describe(r);
  r = m.run();  // deferred again: still there
  EXPECT_EQ(r.reason, StopReason::kDeferred);
  EXPECT_EQ(r.executed, 0u);
  EXPECT_EQ(m.hart.pc(), at);

  hook.result.status = HookStatus::kOk;
  r = m.run();
  EXPECT_EQ(r.reason, StopReason::kHalt);
  EXPECT_EQ(m.hart.x(3), 77u);
  EXPECT_EQ(m.hart.x(6), 4u);
  ASSERT_EQ(hook.calls.size(), 3u);  // asked twice, then executed
  EXPECT_EQ(hook.calls[2].op, Op::kStStreamPop);
}

TEST(IssStrata, FpRegisterOperationsNeedFs) {
  RecordingHook hook;
  Machine m({strata(P, STRATA_F3_PIPE_LOAD, STRATA_SET_TMAX, 0, 1, 0)}, &hook);
  const RunResult r = m.run();
  EXPECT_EQ(r.cause, cause::kIllegalInstruction);
  EXPECT_TRUE(hook.calls.empty());
}

// ---- The functional hook ----

HookResult call(FunctionalStrataHook& hook, Op op, uint32_t rs1 = 0, uint32_t rs2 = 0,
                const std::vector<uint32_t>& in = {}, uint32_t* out = nullptr) {
  return hook.execute(HookCall{op, 0, rs1, rs2, in.data(), out});
}

std::vector<uint32_t> words_of(const void* p, size_t n) {
  std::vector<uint32_t> w(n);
  std::memcpy(w.data(), p, n * 4);
  return w;
}

TEST(IssStrataFunctional, IdsAndGlobalRegisters) {
  FunctionalStrataHook::Config config;
  config.tp_id = 5;
  config.tm_id = 2;
  config.tps_per_tm = 32;
  config.tm_count = 4;
  FunctionalStrataHook hook(config);
  EXPECT_EQ(call(hook, Op::kStThreadId).dest[0], 2u * 32 + 5);
  EXPECT_EQ(call(hook, Op::kStThreadCount).dest[0], 128u);
  EXPECT_EQ(call(hook, Op::kStTpsPerTm).dest[0], 32u);
  EXPECT_EQ(call(hook, Op::kStTmCount).dest[0], 4u);
  EXPECT_EQ(call(hook, Op::kStAtomicInc, 31).dest[0], 0u);
  EXPECT_EQ(call(hook, Op::kStAtomicAdd, 31, 0xFFFFFFFFu).dest[0], 1u);  // wraps
  EXPECT_EQ(call(hook, Op::kStGlobalRead, 31).dest[0], 0u);
  EXPECT_EQ(call(hook, Op::kStAtomicInc, STRATA_GLOBAL_REGISTERS).status, HookStatus::kIllegal);
}

TEST(IssStrataFunctional, StreamCapacityIsEnforced) {
  FunctionalStrataHook::Config config;
  config.stream_capacity = 2;
  FunctionalStrataHook hook(config);
  const std::vector<uint32_t> ray(12, 7);
  EXPECT_EQ(call(hook, Op::kStStreamPush, 0, 1, ray).dest[0], 1u);
  EXPECT_EQ(call(hook, Op::kStStreamPush, 0, 2, ray).dest[0], 1u);
  EXPECT_EQ(call(hook, Op::kStStreamPush, 0, 2, ray).dest[0], 0u);  // full
  EXPECT_EQ(hook.rays_queued(), 2u);
  uint32_t out[12] = {};
  EXPECT_EQ(call(hook, Op::kStStreamPop, 0, 0, {}, out).dest[0], 0u);  // no assignment yet
  EXPECT_EQ(call(hook, Op::kStStreamAssign).dest[0], 1u);  // equal sizes: the lowest id
  EXPECT_EQ(call(hook, Op::kStStreamPop, 0, 0, {}, out).status, HookStatus::kStore);
  EXPECT_EQ(out[11], 7u);
  EXPECT_EQ(call(hook, Op::kStStreamPush, 0, 2, ray).dest[0], 1u);  // room again
}

// A 64-byte ray (the compact path state) comes back whole; a pop of the other width traps.
TEST(IssStrataFunctional, SixtyFourByteRaysComeBackWholeAndWidthsMustMatch) {
  FunctionalStrataHook hook;
  std::vector<uint32_t> ray(16);
  for (uint32_t i = 0; i < 16; ++i) ray[i] = 100 + i;
  EXPECT_EQ(call(hook, Op::kStStreamPush64, 0, 3, ray).dest[0], 1u);
  EXPECT_EQ(call(hook, Op::kStStreamAssign).dest[0], 3u);
  uint32_t out[16] = {};
  EXPECT_EQ(call(hook, Op::kStStreamPop, 0, 0, {}, out).status, HookStatus::kIllegal);  // 48-byte pop
  EXPECT_EQ(call(hook, Op::kStStreamPop64, 0, 0, {}, out).status, HookStatus::kStore);
  for (uint32_t i = 0; i < 16; ++i) EXPECT_EQ(out[i], 100 + i);
}

TEST(IssStrataFunctional, PipelinesNeedTheirConfiguration) {
  FunctionalStrataHook hook;
  EXPECT_EQ(call(hook, Op::kStBoxTest).status, HookStatus::kIllegal);
  EXPECT_EQ(call(hook, Op::kStTriangleTest).status, HookStatus::kIllegal);
  call(hook, Op::kStPipeBox);
  EXPECT_EQ(call(hook, Op::kStBoxTest).status, HookStatus::kOk);
  EXPECT_EQ(call(hook, Op::kStTriangleDivide).status, HookStatus::kIllegal);
  call(hook, Op::kStPipeTriangle);
  EXPECT_EQ(call(hook, Op::kStTriangleTest).status, HookStatus::kOk);
  call(hook, Op::kStPipeGeneral);
  EXPECT_EQ(call(hook, Op::kStTriangleTest).status, HookStatus::kIllegal);
}

TEST(IssStrataFunctional, BoxAndTriangleResults) {
  const float inf = std::numeric_limits<float>::infinity();
  FunctionalStrataHook hook;
  const strata_pipe_ray ray = {{0.25f, 0.25f, -1.0f}, 0.0f, {0.0f, 0.0f, 1.0f}, inf, {inf, inf, 1.0f}, 0.0f};
  const strata_pipe_box box = {{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 3.0f}};  // entered at t = 1
  const strata_pipe_triangle tri = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  call(hook, Op::kStPipeBox);
  call(hook, Op::kStLoadRay, 0, 0, words_of(&ray, STRATA_PIPE_RAY_WORDS));
  call(hook, Op::kStLoadBox, 0, 0, words_of(&box, 6));
  HookResult r = call(hook, Op::kStBoxTest);
  EXPECT_EQ(r.dest[0], 1u);
  EXPECT_EQ(value(r.dest[2]), 1.0f);
  call(hook, Op::kStSetTmax, bits(0.5f));
  r = call(hook, Op::kStBoxTest);
  EXPECT_EQ(r.dest[0], 0u);
  EXPECT_EQ(value(r.dest[2]), inf);

  call(hook, Op::kStPipeTriangle);
  call(hook, Op::kStLoadRay, 0, 0, words_of(&ray, STRATA_PIPE_RAY_WORDS));
  call(hook, Op::kStLoadTriangle, 0, 0, words_of(&tri, 9));
  EXPECT_EQ(call(hook, Op::kStTriangleTest).dest[0], 1u);
  r = call(hook, Op::kStTriangleDivide);
  EXPECT_EQ(value(r.dest[0]), 1.0f);
  EXPECT_EQ(value(r.dest[1]), 0.25f);
  EXPECT_EQ(value(r.dest[2]), 0.25f);
}

}  // namespace
}  // namespace strata::iss::testing
