// Each self-checking program in firmware/tests, compiled by riscv64-unknown-elf-gcc, runs to
// a pass on the ISS. A failing check exits with its source line number.
#include "model/iss/functional_strata_hook.h"
#include "model/iss/program.h"

#include <gtest/gtest.h>

#include <string>

namespace strata::iss {
namespace {

class IssFirmware : public ::testing::TestWithParam<const char*> {};

TEST_P(IssFirmware, RunsToPass) {
  const std::string name = GetParam();
  Program program = load_program(std::string(STRATA_ISS_FIRMWARE_DIR) + "/" + name + ".elf");
  FunctionalStrataHook hook;
  Hart<FlatMemory> hart(program.code, program.memory, &hook);
  prepare_hart(hart, program);
  const RunResult r = hart.run(200'000'000);
  if (name == "halt") {
    EXPECT_EQ(r.reason, StopReason::kHalt) << describe(r);
    uint32_t result = 0;
    program.memory.read(*program.elf.symbol("result"), &result, 4);
    EXPECT_EQ(result, 42u);
    return;
  }
  EXPECT_EQ(r.reason, StopReason::kToHost) << describe(r);
  EXPECT_EQ(r.exit_code, 0u) << name << ".c failed the check on line " << r.exit_code;
  EXPECT_GT(r.executed, 100u);
}

INSTANTIATE_TEST_SUITE_P(Programs, IssFirmware,
                         ::testing::Values("recursion", "memory", "intmath", "floatmath", "traps", "strata_ops",
                                           "pipeline_twin", "halt", "bench"),
                         [](const ::testing::TestParamInfo<const char*>& param) { return std::string(param.param); });

}  // namespace
}  // namespace strata::iss
