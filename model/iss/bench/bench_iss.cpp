// ISS speed, in retired guest instructions per second (the MIPS counter).
//   BM_IssIntegerLoop: a hand-assembled load/ALU/store/branch loop; needs no toolchain.
//   BM_IssFirmware:    firmware/tests/bench.c (integer and FP kernels) to completion.
#include "model/iss/functional_strata_hook.h"
#include "model/iss/hart.h"
#include "model/iss/program.h"

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace {

using namespace strata::iss;

constexpr uint32_t r_type(uint32_t f7, uint32_t rs2, uint32_t rs1, uint32_t f3, uint32_t rd, uint32_t opcode) {
  return (f7 << 25) | (rs2 << 20) | (rs1 << 15) | (f3 << 12) | (rd << 7) | opcode;
}
constexpr uint32_t i_type(int32_t imm, uint32_t rs1, uint32_t f3, uint32_t rd, uint32_t opcode) {
  return (static_cast<uint32_t>(imm) << 20) | (rs1 << 15) | (f3 << 12) | (rd << 7) | opcode;
}
constexpr uint32_t s_type(int32_t imm, uint32_t rs2, uint32_t rs1, uint32_t f3) {
  const uint32_t u = static_cast<uint32_t>(imm);
  return ((u >> 5) << 25) | (rs2 << 20) | (rs1 << 15) | (f3 << 12) | ((u & 31) << 7) | 0x23;
}
constexpr uint32_t b_type(int32_t imm, uint32_t rs2, uint32_t rs1, uint32_t f3) {
  const uint32_t u = static_cast<uint32_t>(imm);
  return (((u >> 12) & 1) << 31) | (((u >> 5) & 63) << 25) | (rs2 << 20) | (rs1 << 15) | (f3 << 12) |
         (((u >> 1) & 15) << 8) | (((u >> 11) & 1) << 7) | 0x63;
}

void BM_IssIntegerLoop(benchmark::State& state) {
  constexpr uint32_t kA0 = 10, kT0 = 5, kT1 = 6, kT2 = 7, kT3 = 28, kT4 = 29;
  const std::vector<uint32_t> code = {
      i_type(0, 0, 0, kT0, 0x13),             // addi t0, zero, 0
      i_type(0, kA0, 2, kT2, 0x03),           // loop: lw t2, 0(a0)
      r_type(0, kT0, kT2, 0, kT2, 0x33),      // add t2, t2, t0
      r_type(0, kT1, kT2, 4, kT3, 0x33),      // xor t3, t2, t1
      r_type(1, kT3, kT2, 0, kT4, 0x33),      // mul t4, t2, t3
      s_type(4, kT4, kA0, 2),                 // sw t4, 4(a0)
      i_type(1, kT0, 0, kT0, 0x13),           // addi t0, t0, 1
      b_type(-24, kT1, kT0, 1),               // bne t0, t1, loop
      r_type(0, 0, 0, 7, 0, 0x0B),            // strata.halt
  };
  constexpr uint32_t kBase = 0x1000, kData = 0x8000, kIterations = 1'000'000;
  FlatMemory memory(kBase, 0x10000);
  memory.write(kBase, code.data(), code.size() * 4);
  CodeImage image(kBase, code);
  Hart<FlatMemory> hart(image, memory);
  uint64_t instructions = 0;
  for (auto _ : state) {
    hart.reset(kBase);
    hart.set_x(kA0, kData);
    hart.set_x(kT1, kIterations);
    const RunResult r = hart.run(UINT64_MAX);
    if (r.reason != StopReason::kHalt) state.SkipWithError(describe(r).c_str());
    instructions += r.executed;
  }
  state.counters["MIPS"] = benchmark::Counter(static_cast<double>(instructions) / 1e6, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_IssIntegerLoop)->Unit(benchmark::kMillisecond);

#ifdef STRATA_ISS_FIRMWARE_DIR
void BM_IssFirmware(benchmark::State& state) {
  const Program pristine = load_program(std::string(STRATA_ISS_FIRMWARE_DIR) + "/bench.elf");
  uint64_t instructions = 0;
  for (auto _ : state) {
    state.PauseTiming();
    Program program = pristine;
    FunctionalStrataHook hook;
    Hart<FlatMemory> hart(program.code, program.memory, &hook);
    prepare_hart(hart, program);
    state.ResumeTiming();
    const RunResult r = hart.run(UINT64_MAX);
    if (!r.ok()) state.SkipWithError(describe(r).c_str());
    instructions += r.executed;
  }
  state.counters["MIPS"] = benchmark::Counter(static_cast<double>(instructions) / 1e6, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_IssFirmware)->Unit(benchmark::kMillisecond);
#endif

}  // namespace

BENCHMARK_MAIN();
