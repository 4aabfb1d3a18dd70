// strata-sim end to end on hostile files: a cache entry that is a FIFO or a folder, and a
// folder given as a config or firmware. Each is an error naming the path, never a hang.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "test/support/run_program.h"
#include "test/support/test_files.h"

namespace strata::sim::testing {
namespace {

const std::string kSim = STRATA_SIM_EXE;
const std::string kConfigs = std::string(STRATA_SOURCE_DIR) + "/sim/configs/";

// Builds Cornell's image into `cache` once and returns the cache entry's path.
std::filesystem::path cached_entry(const std::filesystem::path& cache) {
  const ProgramResult r = run_program({kSim, "scene", "info", "cornell:size=0.2", "--cache-dir", cache.string()});
  EXPECT_EQ(r.exit_status, 0) << r.output;
  for (const auto& e : std::filesystem::directory_iterator(cache))
    if (e.path().extension() == ".strs") return e.path();
  ADD_FAILURE() << "no cache entry in " << cache;
  return {};
}

TEST(InputFaults, ACacheEntryThatIsAFifoIsAnErrorNotAHang) {
  TempDir dir;
  const auto cache = dir / "cache";
  const auto entry = cached_entry(cache);
  ASSERT_FALSE(entry.empty());
  std::filesystem::remove(entry);
  ASSERT_EQ(mkfifo(entry.c_str(), 0644), 0);
  const ProgramResult r =
      run_program({kSim, "scene", "info", "cornell:size=0.2", "--cache-dir", cache.string()}, 0, 30);
  EXPECT_EQ(r.signal, 0) << "hung (killed by the test's alarm)";
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find(entry.string() + ": the scene cache entry is not a regular file"), std::string::npos)
      << r.output;
}

TEST(InputFaults, ACacheEntryThatIsAFolderLeavesNoTemporaries) {
  TempDir dir;
  const auto cache = dir / "cache";
  const auto entry = cached_entry(cache);
  ASSERT_FALSE(entry.empty());
  std::filesystem::remove(entry);
  std::filesystem::create_directory(entry);
  const ProgramResult r = run_program({kSim, "scene", "info", "cornell:size=0.2", "--cache-dir", cache.string()});
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("not a regular file"), std::string::npos) << r.output;
  for (const auto& e : std::filesystem::directory_iterator(cache))
    EXPECT_EQ(e.path().string().find(".tmp."), std::string::npos) << e.path();
}

TEST(InputFaults, AFolderAsConfigOrFirmwareIsNamed) {
  TempDir dir;
  ProgramResult r = run_program({kSim, "run", "--config", dir.path().string(), "--scene", "cornell:size=0.2",
                                 "--res", "8x8", "--no-cache", "--out", (dir / "o").string()});
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find(dir.path().string() + ": cannot open config file: not a regular file"), std::string::npos)
      << r.output;
  r = run_program({kSim, "run", "--config", kConfigs + "trax.json", "--scene", "cornell:size=0.2", "--res", "8x8",
                   "--set", "tms=1", "--no-cache", "--firmware", dir.path().string(), "--out", (dir / "o").string()});
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find(dir.path().string() + ": cannot open file: not a regular file"), std::string::npos)
      << r.output;
}

// Issue 39 (minor): sampled timing's options set in another mode do nothing, and the run says so
// (it still runs); in sampled mode, or left at their defaults, there is no warning.
TEST(InputFaults, SampledOnlyOptionsInAnotherModeAreWarnedAbout) {
  TempDir dir;
  const auto run = [&](const std::string& mode, const std::string& set) {
    std::vector<std::string> args = {kSim, "run", "--config", std::string(STRATA_SOURCE_DIR) + "/sim/configs/trax.json",
                                     "--scene", "cornell:size=0.2", "--res", "8x8", "--set", "tms=1", "--no-cache",
                                     "--quiet", "--set", "timing.mode=" + mode, "--out", (dir / mode).string()};
    if (!set.empty()) args.insert(args.end(), {"--set", set});
    return run_program(args);
  };
  ProgramResult r = run("lt", "timing.sample_target_error=0.02");
  EXPECT_EQ(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("warning: timing.sample_target_error set, but timing.mode is loosely-timed"), std::string::npos)
      << r.output;
  r = run("precise", "timing.sample_period_cycles=50000");
  EXPECT_EQ(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("warning: timing.sample_period_cycles set, but timing.mode is precise"), std::string::npos)
      << r.output;
  r = run("lt", "");
  EXPECT_EQ(r.output.find("sampled timing's options do nothing"), std::string::npos) << r.output;
  r = run("sampled", "timing.sample_target_error=0.5");
  EXPECT_EQ(r.exit_status, 0) << r.output;
  EXPECT_EQ(r.output.find("sampled timing's options do nothing"), std::string::npos) << r.output;
}

// Issue 39 F6: a config nested 100,000 levels deep crashed strata-sim with SIGSEGV (arrays at
// once, objects after 30 s). Now it exits 1 at once with an error naming the file and the limit.
TEST(InputFaults, AConfigNested100000LevelsDeepIsAnErrorNotACrash) {
  TempDir dir;
  const int depth = 100000;
  std::string objects;
  for (int i = 0; i < depth; ++i) objects += "{\"a\": ";
  objects += "1" + std::string(depth, '}');
  const struct {
    const char* name;
    std::string text;
  } cases[] = {{"arrays.json", "{\"tms\": " + std::string(depth, '[') + std::string(depth, ']') + "}"},
               {"objects.json", objects}};
  for (const auto& c : cases) {
    const auto file = dir / c.name;
    std::ofstream(file) << c.text;
    const ProgramResult r = run_program({kSim, "run", "--config", file.string(), "--scene", "cornell:size=0.2",
                                         "--res", "8x8", "--no-cache", "--quiet", "--out", (dir / "o").string()},
                                        0, 10);
    EXPECT_EQ(r.signal, 0) << c.name << ": killed by signal " << r.signal << " (SIGALRM: took over 10 s)";
    EXPECT_EQ(r.exit_status, 1) << r.output;
    EXPECT_NE(r.output.find(file.string() + ": nested deeper than 64 levels"), std::string::npos) << r.output;
  }
}

}  // namespace
}  // namespace strata::sim::testing
