// strata-sim's outputs under faults (issue: hostile input): a write that fails (a full disk,
// simulated with RLIMIT_FSIZE) is an error with a non-zero exit and leaves no cut-off file
// under its final name; an unwritable --out fails before the simulation.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "test/support/run_program.h"
#include "test/support/test_files.h"

namespace strata::sim::testing {
namespace {

const std::string kSim = STRATA_SIM_EXE;
const std::string kConfig = std::string(STRATA_SOURCE_DIR) + "/sim/configs/trax.json";

std::vector<std::string> tiny_run(const std::filesystem::path& out) {
  return {kSim, "run", "--config", kConfig, "--scene", "cornell:size=0.2", "--res", "8x8", "--set", "tms=1",
          "--no-cache", "--quiet", "--out", out.string()};
}

// No file under `dir` is a left-over temporary.
void expect_no_partial_files(const std::filesystem::path& dir) {
  if (!std::filesystem::exists(dir)) return;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << e.path();
}

TEST(OutputFaults, RunWithAFullDiskFailsAndWritesNoCutOffStats) {
  TempDir dir;
  const auto out = dir / "run";
  // 4 KB: the images of an 8x8 frame fit, stats.json (tens of KB) does not.
  const ProgramResult r = run_program(tiny_run(out), 4096);
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("stats.json: cannot write: File too large"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("wrote "), std::string::npos) << r.output;  // never reports success
  EXPECT_FALSE(std::filesystem::exists(out / "stats.json"));
  expect_no_partial_files(out);
}

TEST(OutputFaults, RunWithoutALimitWritesEveryOutput) {
  // The control of the test above: the same run, with room, succeeds.
  TempDir dir;
  const auto out = dir / "run";
  const ProgramResult r = run_program(tiny_run(out));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  for (const char* f : {"stats.json", "image.png", "image.exr"}) EXPECT_GT(std::filesystem::file_size(out / f), 0u) << f;
  expect_no_partial_files(out);
}

TEST(OutputFaults, ImagesThatDoNotFitAreNotLeftCutOff) {
  TempDir dir;
  const auto out = dir / "run";
  const ProgramResult r = run_program(tiny_run(out), 600);  // less than the 8x8 EXR
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("image.exr: cannot write EXR: File too large"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out / "image.exr"));
  expect_no_partial_files(out);
}

TEST(OutputFaults, AnUncreatableOutFolderFailsBeforeTheSimulation) {
  TempDir dir;
  std::ofstream(dir / "a-file") << "x";
  const ProgramResult r = run_program(tiny_run(dir / "a-file" / "run"));
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("--out " + (dir / "a-file" / "run").string() + ": cannot create the folder"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("frame "), std::string::npos) << r.output;  // no summary: it never ran
}

TEST(OutputFaults, AVcdPathThatIsAFolderIsRefused) {
  TempDir dir;
  std::vector<std::string> args = tiny_run(dir / "run");
  args.insert(args.end(), {"--vcd", dir.path().string()});
  const ProgramResult r = run_program(args);
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("--vcd " + dir.path().string() + ": is a folder, not a file"), std::string::npos) << r.output;
}

TEST(OutputFaults, AVcdWindowThatEndsBeforeItStartsIsRefused) {
  TempDir dir;
  std::vector<std::string> args = tiny_run(dir / "run");
  args.insert(args.end(), {"--vcd", (dir / "w.vcd").string(), "--vcd-start", "100", "--vcd-end", "50"});
  const ProgramResult r = run_program(args);
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("--vcd-start 100 is after --vcd-end 50"), std::string::npos) << r.output;
}

// Issue 39 F3, F4: 0 cycles between progress lines would wake the monitor every cycle, and a
// 0-cycle VCD window traces no signal; both are refused before the simulation.
TEST(OutputFaults, ZeroProgressCyclesAndAZeroCycleVcdWindowAreRefused) {
  TempDir dir;
  std::vector<std::string> progress = tiny_run(dir / "run");
  progress.insert(progress.end(), {"--progress-cycles", "0"});
  ProgramResult r = run_program(progress);
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("--progress-cycles 0: must be at least 1"), std::string::npos) << r.output;
  std::vector<std::string> vcd = tiny_run(dir / "run");
  vcd.insert(vcd.end(), {"--vcd", (dir / "w.vcd").string(), "--vcd-window", "0"});
  r = run_program(vcd);
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("--vcd-window 0: must be at least 1 cycle"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("frame "), std::string::npos) << r.output;  // it never ran
  EXPECT_FALSE(std::filesystem::exists(dir / "w.vcd"));
}

// A VCD time window that starts after the frame's end selects no sample: the run says so.
TEST(OutputFaults, AVcdWindowPastTheFrameIsReported) {
  TempDir dir;
  std::vector<std::string> late = tiny_run(dir / "run");
  late.insert(late.end(), {"--vcd", (dir / "late.vcd").string(), "--vcd-start", "100000000"});
  ProgramResult r = run_program(late);
  EXPECT_EQ(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("warning        --vcd-start 100000000 is at or after the frame's last cycle"),
            std::string::npos)
      << r.output;
  std::vector<std::string> early = tiny_run(dir / "run2");
  early.insert(early.end(), {"--vcd", (dir / "early.vcd").string(), "--vcd-start", "10"});
  r = run_program(early);
  EXPECT_EQ(r.exit_status, 0) << r.output;
  EXPECT_EQ(r.output.find("--vcd-start 10 is at or after"), std::string::npos) << r.output;
}

TEST(OutputFaults, RenderWithAFullDiskFails) {
  TempDir dir;
  const auto out = dir / "render";
  const ProgramResult r = run_program(
      {kSim, "render", "cornell:size=0.2", "--res", "8x8", "--no-cache", "--out", out.string()}, 512);
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("native.exr: cannot write EXR: File too large"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("wrote "), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out / "native.exr"));
  EXPECT_FALSE(std::filesystem::exists(out / "native-stats.json"));
  expect_no_partial_files(out);
}

TEST(OutputFaults, SceneInfoJsonWithAFullDiskLeavesNoEmptyFile) {
  TempDir dir;
  const auto json = dir / "info.json";
  const ProgramResult r =
      run_program({kSim, "scene", "info", "cornell:size=0.2", "--no-cache", "--json", json.string()}, 512);
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("info.json: cannot write: File too large"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(json));
  expect_no_partial_files(dir.path());
}

TEST(OutputFaults, TraceGenerateWithAFullDiskLeavesNoEmptyFile) {
  TempDir dir;
  const auto rays = dir / "rays.bin";
  const ProgramResult r = run_program(
      {kSim, "trace", "--scene", "cornell:size=0.2", "--generate", "1000", "--out", rays.string()}, 4096);
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("rays.bin: cannot write ray file: File too large"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(rays));
  expect_no_partial_files(dir.path());
}

TEST(OutputFaults, TraceGenerateRefusesACountItCannotHold) {
  TempDir dir;
  const ProgramResult r = run_program({kSim, "trace", "--scene", "cornell:size=0.2", "--generate", "4294967295",
                                       "--out", (dir / "rays.bin").string()});
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("--generate: at most 134217728 rays, got 4294967295"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace strata::sim::testing
