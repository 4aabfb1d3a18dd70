// strata-sim run stopped from outside: Ctrl-C whatever the progress interval and in every
// timing mode, SIGTERM like SIGINT, and --max-cycles against a frame that will not finish in
// time. Each writes its partial outputs, complete and marked interrupted.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <csignal>
#include <string>

#include "test/support/run_program.h"
#include "test/support/test_files.h"

namespace strata::sim::testing {
namespace {

const std::string kSim = STRATA_SIM_EXE;
const std::string kConfig = std::string(STRATA_SOURCE_DIR) + "/sim/configs/trax.json";

std::vector<std::string> long_run(const std::filesystem::path& out, const std::string& mode) {
  return {kSim, "run", "--config", kConfig, "--scene", "cornell:size=0.2", "--res", "64x64", "--set", "tms=2",
          "--set", "tps_per_tm=4", "--set", "timing.mode=" + mode, "--no-cache", "--progress",
          "--out", out.string()};
}

void expect_partial_outputs(const std::filesystem::path& out) {
  const nlohmann::json j = nlohmann::json::parse(read_text(out / "stats.json"));  // throws if cut off
  EXPECT_EQ(j["interrupted"], true);
  EXPECT_TRUE(j["frame"]["frames_per_second"].is_null());
  EXPECT_LT(j["frame"]["pixels_done"].get<uint64_t>(), 64u * 64u);
  EXPECT_EQ(read_text(out / "image.png").substr(1, 3), "PNG");
}

// Before: Ctrl-C was looked at only when a progress line was due, so with a 4e9-cycle interval
// the frame ran to its end and exited 0.
TEST(Signals, CtrlCStopsTheRunWhateverTheProgressIntervalInEveryMode) {
  for (const char* mode : {"lt", "precise", "sampled"}) {
    TempDir dir;
    std::vector<std::string> args = long_run(dir / "run", mode);
    args.insert(args.end(), {"--progress-cycles", "4000000000"});
    bool sent = false;
    const ProgramResult r = run_program_signalled(args, "progress:", SIGINT, &sent);
    ASSERT_TRUE(sent) << mode << ": no first progress line:\n" << r.output;
    EXPECT_EQ(r.exit_status, 130) << mode << "\n" << r.output;
    expect_partial_outputs(dir / "run");
  }
}

TEST(Signals, SigtermWritesPartialOutputsAndExitsWith143) {
  TempDir dir;
  bool sent = false;
  const ProgramResult r = run_program_signalled(long_run(dir / "run", "lt"), "progress:", SIGTERM, &sent);
  ASSERT_TRUE(sent) << r.output;
  EXPECT_EQ(r.exit_status, 143) << r.output;
  EXPECT_NE(r.output.find("interrupted: partial image and statistics written"), std::string::npos) << r.output;
  expect_partial_outputs(dir / "run");
}

TEST(Signals, MaxCyclesStopsARunThatWouldGoOnWithAClearError) {
  TempDir dir;
  std::vector<std::string> args = long_run(dir / "run", "lt");
  args.insert(args.end(), {"--max-cycles", "50000"});
  const ProgramResult r = run_program(args);
  EXPECT_EQ(r.exit_status, 1) << r.output;
  EXPECT_NE(r.output.find("--max-cycles 50000: the frame did not finish within the limit"), std::string::npos)
      << r.output;
  expect_partial_outputs(dir / "run");
  const nlohmann::json j = nlohmann::json::parse(read_text(dir / "run" / "stats.json"));
  EXPECT_GE(j["frame"]["cycles"].get<uint64_t>(), 50000u);
  EXPECT_LT(j["frame"]["cycles"].get<uint64_t>(), 60000u);  // within a quantum and a step of the limit
}

TEST(Signals, AFrameWithinMaxCyclesFinishesNormally) {
  TempDir dir;
  const ProgramResult r = run_program({kSim, "run", "--config", kConfig, "--scene", "cornell:size=0.2", "--res",
                                       "8x8", "--set", "tms=1", "--no-cache", "--quiet", "--max-cycles", "100000000",
                                       "--out", (dir / "run").string()});
  EXPECT_EQ(r.exit_status, 0) << r.output;
}

}  // namespace
}  // namespace strata::sim::testing
