// Golden statistics: a small Cornell frame on each design, loosely timed and precise, run
// through the built strata-sim; its stats.json must equal test/golden/<design>-<mode>.json
// exactly, every field but the simulator's own wall-clock figures. Any change to the timing,
// the memory system, the firmware or the statistics shows here, even one that moves loosely
// timed and precise together. When a change is intended, `scripts/regenerate golden` rewrites
// the files; review their diff before committing it.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "test/support/test_files.h"

namespace {

namespace fs = std::filesystem;
using strata::sim::testing::read_text;
using strata::sim::testing::TempDir;

struct Golden {
  const char* design;
  const char* mode;
};

// The frame: 2 TMs of 8 TPs, a fifth-size Cornell box at 12x12 with a 512 KB stream memory.
const char* kFrame =
    " --set tms=2 --set tps_per_tm=8 --set memory.stream.size_bytes=524288 --scene cornell:size=0.2 --res 12x12"
    " --quiet --no-cache --check";

fs::path golden_file(const Golden& g) {
  return fs::path(STRATA_SOURCE_DIR) / "test" / "golden" / (std::string(g.design) + "-" + g.mode + ".json");
}

// Host figures differ from run to run; everything else must not.
nlohmann::json without_wall_clock(nlohmann::json j) {
  for (const char* k : {"wall_seconds", "instructions_per_second", "rays_per_second"}) j["simulation"].erase(k);
  return j;
}

// Dotted paths where a and b differ (at most `limit`).
void differences(const nlohmann::json& a, const nlohmann::json& b, const std::string& at, std::vector<std::string>& out,
                 size_t limit = 25) {
  if (out.size() >= limit) return;
  if (a.is_object() && b.is_object()) {
    for (auto it = a.begin(); it != a.end(); ++it)
      differences(it.value(), b.contains(it.key()) ? b[it.key()] : nlohmann::json(), at + "." + it.key(), out, limit);
    for (auto it = b.begin(); it != b.end(); ++it)
      if (!a.contains(it.key())) out.push_back(at + "." + it.key() + ": absent in the golden file");
    return;
  }
  if (a != b) out.push_back(at + ": golden " + a.dump() + ", now " + b.dump());
}

class GoldenStats : public ::testing::TestWithParam<Golden> {};

TEST_P(GoldenStats, EqualExactlyApartFromWallClock) {
  const Golden g = GetParam();
  TempDir dir;
  const fs::path out = dir.path() / "run";
  const std::string cmd = std::string("'") + STRATA_SIM_EXE + "' run --config '" + STRATA_SOURCE_DIR +
                          "/sim/configs/" + g.design + ".json' --set timing.mode=" + g.mode + kFrame + " --out '" +
                          out.string() + "' >'" + (dir / "log.txt").string() + "' 2>&1";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(dir / "log.txt");
  const nlohmann::json now = without_wall_clock(nlohmann::json::parse(read_text(out / "stats.json")));

  if (std::getenv("STRATA_REGENERATE_GOLDEN")) {
    fs::create_directories(golden_file(g).parent_path());
    std::ofstream(golden_file(g)) << now.dump(1) << "\n";
    GTEST_SKIP() << "regenerated " << golden_file(g);
  }
  ASSERT_TRUE(fs::exists(golden_file(g))) << golden_file(g) << " is missing: run scripts/regenerate golden";
  const nlohmann::json golden = nlohmann::json::parse(read_text(golden_file(g)));
  std::vector<std::string> diff;
  differences(golden, now, g.design + std::string(" ") + g.mode, diff);
  std::string text;
  for (const std::string& d : diff) text += "  " + d + "\n";
  EXPECT_TRUE(diff.empty()) << "stats.json differs from " << golden_file(g)
                            << " (if intended: scripts/regenerate golden, and review the diff):\n"
                            << text;
}

INSTANTIATE_TEST_SUITE_P(Chip, GoldenStats,
                         ::testing::Values(Golden{"trax", "lt"}, Golden{"trax", "precise"},
                                           Golden{"strata-streams", "lt"}, Golden{"strata-streams", "precise"},
                                           Golden{"strata-pipelines", "lt"}, Golden{"strata-pipelines", "precise"}),
                         [](const ::testing::TestParamInfo<Golden>& i) {
                           std::string n = std::string(i.param.design) + "_" + i.param.mode;
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

}  // namespace
