// Issue 39, F2: a frame's statistics depend on the model only, in every timing mode. Not on
// --progress-cycles, a display option (the progress monitor's wake-ups used to reorder the TMs
// resuming at one cycle, and the first to run took the others' bank slots and rays), and not
// on clock_ghz beyond the seconds (the memory modules counted 1 ns cycles whatever the clock,
// so every memory latency stretched or shrank against the TMs' cycles).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "test/support/run_program.h"
#include "test/support/test_files.h"

namespace strata::sim::testing {
namespace {

const std::string kSim = STRATA_SIM_EXE;
const std::string kConfig = std::string(STRATA_SOURCE_DIR) + "/sim/configs/strata-pipelines.json";
const char* const kModes[] = {"lt", "precise", "sampled"};

// The frame: two TMs share the L2 and the stream memory, so the order they resume in
// at a cycle shows in the counts.
nlohmann::json run_frame(const TempDir& dir, const std::string& tag, const std::string& mode,
                         const std::vector<std::string>& extra) {
  const std::filesystem::path out = dir / tag;
  std::vector<std::string> args = {kSim, "run", "--config", kConfig, "--scene", "cornell", "--res", "8x8",
                                   "--set", "tms=2", "--set", "timing.mode=" + mode, "--no-cache", "--quiet",
                                   "--out", out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const ProgramResult r = run_program(args);
  EXPECT_EQ(r.exit_status, 0) << mode << " " << tag << "\n" << r.output;
  return nlohmann::json::parse(read_text(out / "stats.json"), nullptr, false);
}

void flatten(const nlohmann::json& j, const std::string& path, std::map<std::string, nlohmann::json>& out) {
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) flatten(v, path.empty() ? k : path + "." + k, out);
  } else {
    out[path] = j;
  }
}

// Every field that differs between two stats.json files, but for those in `ignored`.
std::vector<std::string> differences(const nlohmann::json& a, const nlohmann::json& b,
                                     const std::set<std::string>& ignored) {
  std::map<std::string, nlohmann::json> fa, fb;
  flatten(a, "", fa);
  flatten(b, "", fb);
  std::vector<std::string> diff;
  for (const auto& [path, value] : fa) {
    if (ignored.count(path)) continue;
    const auto it = fb.find(path);
    if (it == fb.end() || it->second != value) diff.push_back(path);
  }
  for (const auto& [path, value] : fb)
    if (!ignored.count(path) && !fa.count(path)) diff.push_back(path);
  return diff;
}

// The simulator's own wall time and host memory: the only fields a rerun may change.
const std::set<std::string> kWallFields = {"simulation.wall_seconds", "simulation.instructions_per_second",
                                           "simulation.rays_per_second", "simulation.host_memory_resident_bytes"};

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += "  " + x + "\n";
  return s;
}

// Before: precise 91,092 cycles at --progress-cycles 200000, 89,543 at 1000, 88,069 at 7.
TEST(TimingInvariance, TheProgressCadenceChangesNoStatisticInAnyMode) {
  for (const char* mode : kModes) {
    TempDir dir;
    // 7: the monitor wakes every 7 cycles; 200000: every 8,192 (its stop check).
    const nlohmann::json often = run_frame(dir, "often", mode, {"--progress-cycles", "7"});
    const nlohmann::json rarely = run_frame(dir, "rarely", mode, {"--progress-cycles", "200000"});
    ASSERT_FALSE(often.is_discarded() || rarely.is_discarded()) << mode;
    ASSERT_GT(often["frame"]["cycles"].get<uint64_t>(), 0u) << mode;
    const std::vector<std::string> diff = differences(often, rarely, kWallFields);
    EXPECT_TRUE(diff.empty()) << mode << ": fields that moved with --progress-cycles:\n" << joined(diff);
  }
}

// Before: precise 74,857 cycles at 0.5 GHz, 91,092 at 1 GHz, 116,919 at 2 GHz.
TEST(TimingInvariance, TheClockScalesTheSecondsAndChangesNoCycleCountInAnyMode) {
  for (const char* mode : kModes) {
    TempDir dir;
    const nlohmann::json slow = run_frame(dir, "slow", mode, {"--set", "clock_ghz=0.5"});
    const nlohmann::json fast = run_frame(dir, "fast", mode, {"--set", "clock_ghz=2"});
    ASSERT_FALSE(slow.is_discarded() || fast.is_discarded()) << mode;
    EXPECT_EQ(slow["frame"]["cycles"], fast["frame"]["cycles"]) << mode;
    EXPECT_DOUBLE_EQ(slow["frame"]["seconds"].get<double>(), 4 * fast["frame"]["seconds"].get<double>()) << mode;
    // Everything else but what is per second, and the clock itself.
    std::set<std::string> ignored = kWallFields;
    for (const char* f : {"chip.clock_ghz", "config.clock_ghz", "frame.seconds", "frame.frames_per_second",
                          "memory.dram.bandwidth_gb_per_s", "memory.dram.peak_gb_per_s",
                          "intervals.stats.frame.seconds.half_width",
                          "intervals.stats.frame.frames_per_second.half_width",
                          "intervals.stats.memory.dram.bandwidth_gb_per_s.half_width"})
      ignored.insert(f);
    const std::vector<std::string> diff = differences(slow, fast, ignored);
    EXPECT_TRUE(diff.empty()) << mode << ": fields that moved with clock_ghz:\n" << joined(diff);
  }
}

}  // namespace
}  // namespace strata::sim::testing
