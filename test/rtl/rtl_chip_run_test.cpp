// The RTL inside a chip run (tm.pipeline_impl=rtl, docs/rtl-cosim.md): the built strata-sim
// renders Cornell at 16x16 on 2 TMs of the pipelines design with its fused box and triangle
// tests computed by the verilated pipelines, loosely timed, precise and sampled. The image must be
// bit-identical to the native twin's (--check) and to the C++ pipeline model's run, and every
// statistic of the frame but the simulator's wall clock must equal that run's: the RTL supplies
// only values, which are the model's, and takes no simulated time (the cycles are the XU
// crossbar's, from the TM config), so not a single cycle may differ. The RTL's own latency is
// checked against the config: no mismatch, the documented slow path counted apart.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "test/support/run_program.h"
#include "test/support/test_files.h"

namespace {

namespace fs = std::filesystem;
using strata::sim::testing::read_bytes;
using strata::sim::testing::read_text;
using strata::sim::testing::TempDir;

// The frame: the shipped pipelines design (32 TPs per TM) cut to 2 TMs, Cornell at 16x16.
const char* kFrame = " --set tms=2 --scene cornell --res 16x16 --quiet --no-cache";

struct SimRun {
  bool ok = false;
  std::string log;
  fs::path out;
  nlohmann::json stats;
};

SimRun simulate(const TempDir& dir, const std::string& name, const std::string& args) {
  SimRun r;
  r.out = dir.path() / name;
  const fs::path log = dir.path() / (name + ".log");
  const std::string cmd = std::string("'") + STRATA_SIM_EXE + "' run --config '" + STRATA_SOURCE_DIR +
                          "/sim/configs/strata-pipelines.json'" + kFrame + args + " --out '" + r.out.string() +
                          "' >'" + log.string() + "' 2>&1";
  const int status = std::system(cmd.c_str());
  r.ok = status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  r.log = read_text(log);
  if (r.ok) r.stats = nlohmann::json::parse(read_text(r.out / "stats.json"));
  return r;
}

// Dotted paths where a and b differ (at most `limit`).
void differences(const nlohmann::json& a, const nlohmann::json& b, const std::string& at, std::vector<std::string>& out,
                 size_t limit = 25) {
  if (out.size() >= limit) return;
  if (a.is_object() && b.is_object()) {
    for (auto it = a.begin(); it != a.end(); ++it)
      differences(it.value(), b.contains(it.key()) ? b[it.key()] : nlohmann::json(), at + "." + it.key(), out, limit);
    for (auto it = b.begin(); it != b.end(); ++it)
      if (!a.contains(it.key())) out.push_back(at + "." + it.key() + ": only in the RTL run");
    return;
  }
  if (a != b) out.push_back(at + ": model " + a.dump() + ", rtl " + b.dump());
}

// The frame's statistics without what differs by design: the host's wall clock, the config
// (tm.pipeline_impl), and the RTL's own group with its units.
nlohmann::json frame_statistics(nlohmann::json j) {
  for (const char* k : {"wall_seconds", "instructions_per_second", "rays_per_second"}) j["simulation"].erase(k);
  j.erase("config");
  j.erase("rtl_pipelines");
  for (auto it = j["units"].begin(); it != j["units"].end();)
    it = it.key().rfind("rtl_pipelines.", 0) == 0 ? j["units"].erase(it) : std::next(it);
  return j;
}

class RtlChipRun : public ::testing::TestWithParam<const char*> {};

TEST_P(RtlChipRun, CornellEqualsTheModelRunAndTheNativeTwin) {
  const std::string mode = GetParam();
  TempDir dir;
  const SimRun model = simulate(dir, "model", " --set timing.mode=" + mode);
  ASSERT_TRUE(model.ok) << model.log;
  const SimRun rtl = simulate(dir, "rtl", " --set timing.mode=" + mode + " --set tm.pipeline_impl=rtl --check");
  ASSERT_TRUE(rtl.ok) << rtl.log;
  EXPECT_NE(rtl.log.find("image bit-identical to the native twin's"), std::string::npos) << rtl.log;
  EXPECT_EQ(read_bytes(rtl.out / "image.exr"), read_bytes(model.out / "image.exr"));

  // Cycles first (the headline), then everything else.
  EXPECT_EQ(rtl.stats["frame"]["cycles"], model.stats["frame"]["cycles"]);
  std::vector<std::string> diff;
  differences(frame_statistics(model.stats), frame_statistics(rtl.stats), mode, diff);
  std::string text;
  for (const std::string& d : diff) text += "  " + d + "\n";
  EXPECT_TRUE(diff.empty()) << "the RTL run's statistics differ from the model run's:\n" << text;

  // Every fused test the TMs issued went to the RTL, and took the latency the config charges.
  const nlohmann::json& r = rtl.stats["rtl_pipelines"];
  std::printf("%s: %s cycles; RTL: %s box tests (%s RTL cycles), %s triangle tests (%s RTL cycles), %s slow-path, "
              "%s + %s latency mismatches; wall %.2f s (model %.2f s)\n",
              mode.c_str(), rtl.stats["frame"]["cycles"].dump().c_str(), r["box_tests"].dump().c_str(),
              r["box_rtl_cycles"].dump().c_str(), r["triangle_tests"].dump().c_str(),
              r["triangle_rtl_cycles"].dump().c_str(), r["triangle_slow_path_tests"].dump().c_str(),
              r["box_latency_mismatches"].dump().c_str(), r["triangle_latency_mismatches"].dump().c_str(),
              rtl.stats["simulation"]["wall_seconds"].get<double>(),
              model.stats["simulation"]["wall_seconds"].get<double>());
  EXPECT_EQ(r["tms"], 2);
  EXPECT_EQ(r["triangle_tests"], rtl.stats["rays"]["triangle_tests"]);  // the kernels' own count
  if (mode != "sampled") {  // sampled timing extrapolates the XU counts from its windows
    EXPECT_EQ(r["box_tests"], rtl.stats["xu"]["box_tests"]);
    EXPECT_EQ(r["triangle_tests"], rtl.stats["xu"]["triangle_tests"]);
  }
  EXPECT_GT(r["box_tests"].get<uint64_t>(), 10000u);
  EXPECT_GT(r["triangle_tests"].get<uint64_t>(), 1000u);
  EXPECT_EQ(r["box_latency_mismatches"], 0);
  EXPECT_EQ(r["triangle_latency_mismatches"], 0);
  EXPECT_EQ(rtl.stats["units"]["rtl_pipelines.box_rtl_cycles"], "cycles");
  EXPECT_NE(rtl.log.find("RTL pipelines"), std::string::npos) << "the run summary reports the RTL's counts";
}

// Sampled timing too: its fast-forward runs the fused tests functionally, through the same hook.
INSTANTIATE_TEST_SUITE_P(Modes, RtlChipRun, ::testing::Values("lt", "precise", "sampled"),
                         [](const ::testing::TestParamInfo<const char*>& i) { return std::string(i.param); });

// One TM on the RTL, the other on the model: the same frame, and only TM 1's tests counted.
TEST(RtlChipRunOneTm, OnlyTheChosenTmUsesTheRtl) {
  TempDir dir;
  const SimRun rtl = simulate(dir, "rtl", " --set tm.pipeline_impl=rtl --set tm.pipeline_impl_tms=1 --check "
                                       "--stats-detail tm");
  ASSERT_TRUE(rtl.ok) << rtl.log;
  const nlohmann::json& r = rtl.stats["rtl_pipelines"];
  EXPECT_EQ(r["tms"], 1);
  const nlohmann::json& per_tm = rtl.stats["xu"]["per_tm"];
  ASSERT_EQ(per_tm.size(), 2u) << rtl.stats["xu"].dump();
  EXPECT_EQ(r["box_tests"], per_tm[1]["box_tests"]);
  EXPECT_EQ(r["triangle_tests"], per_tm[1]["triangle_tests"]);
  EXPECT_GT(per_tm[0]["box_tests"].get<uint64_t>(), 0u);
}

// --vcd with the RTL: beside the chip's VCD, one per TM with the pipelines' internal signals,
// recording only the tests issued in the --vcd-start..--vcd-end window, at chip cycle x 1000 ps
// (1 GHz) plus 1 ps per RTL half cycle, the times strictly increasing.
TEST(RtlChipRunVcd, TracesTheRtlSignalsOfTheWindowWithIncreasingTimes) {
  TempDir dir;
  const uint64_t start = 100000, end = 101000;
  const SimRun rtl = simulate(dir, "rtl", " --set tm.pipeline_impl=rtl --vcd '" + (dir / "t.vcd").string() +
                                              "' --vcd-start " + std::to_string(start) + " --vcd-end " +
                                              std::to_string(end));
  ASSERT_TRUE(rtl.ok) << rtl.log;
  EXPECT_TRUE(fs::exists(dir / "t.vcd"));
  for (const char* tm : {"0", "1"}) {
    const fs::path file = dir / (std::string("t.rtl_tm") + tm + ".vcd");
    ASSERT_TRUE(fs::exists(file)) << file;
    const std::string text = read_text(file);
    for (const char* scope : {"$scope module box_pipeline", "$scope module triangle_pipeline", "$timescale 1ps"})
      EXPECT_NE(text.find(scope), std::string::npos) << file << ": " << scope;
    std::vector<uint64_t> times;
    for (size_t at = text.find("\n#"); at != std::string::npos; at = text.find("\n#", at + 1))
      times.push_back(std::stoull(text.substr(at + 2, text.find('\n', at + 1) - at - 2)));
    ASSERT_GT(times.size(), 100u) << file << ": the window holds fused tests";
    EXPECT_GE(times.front(), start * 1000);
    EXPECT_LT(times.back(), (end + 1) * 1000);
    for (size_t i = 1; i < times.size(); ++i) ASSERT_LT(times[i - 1], times[i]) << file << ": dump " << i;
  }
}

// Issue 39 F10/F11 for the RTL's VCDs: a failed write (a full disk; here RLIMIT_FSIZE) made
// Verilator abort the whole run, leaving the file cut off under its final name. Now the run ends
// with an error naming the file, and neither the file nor a temporary is left.
TEST(RtlChipRunVcd, AFullDiskIsAnErrorAndLeavesNoCutOffRtlVcd) {
  TempDir dir;
  // 1,000 chip cycles of RTL signals are 1.3-1.6 MB per TM; the images, stats.json and the
  // chip's VCD of the same window fit in 512 KB.
  const strata::sim::testing::ProgramResult r = strata::sim::testing::run_program(
      {STRATA_SIM_EXE, "run", "--config", std::string(STRATA_SOURCE_DIR) + "/sim/configs/strata-pipelines.json",
       "--set", "tms=2", "--scene", "cornell", "--res", "16x16", "--quiet", "--no-cache", "--set",
       "tm.pipeline_impl=rtl", "--vcd", (dir / "t.vcd").string(), "--vcd-start", "100000", "--vcd-end", "101000",
       "--out", (dir / "run").string()},
      512 * 1024);
  EXPECT_EQ(r.signal, 0) << r.output;  // not an abort
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find(".rtl_tm0.vcd: cannot write RTL VCD: File too large"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("wrote "), std::string::npos) << r.output;
  for (const auto& e : fs::directory_iterator(dir.path())) {
    EXPECT_EQ(e.path().filename().string().find(".rtl_tm"), std::string::npos) << e.path();
    EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << e.path();
  }
}

// Config errors stop the run before it starts, naming the field.
TEST(RtlChipRunConfig, AnUnknownPipelineImplIsAnErrorNamingTheFieldAndTheChoices) {
  TempDir dir;
  const SimRun r = simulate(dir, "bad", " --set tm.pipeline_impl=verilog");
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.log.find("tm.pipeline_impl"), std::string::npos) << r.log;
  EXPECT_NE(r.log.find("one of model, rtl"), std::string::npos) << r.log;
  EXPECT_FALSE(fs::exists(r.out / "stats.json"));
}

TEST(RtlChipRunConfig, AMissingTmOrADesignWithoutPipelinesIsAnErrorNamingTheField) {
  TempDir dir;
  const SimRun no_tm = simulate(dir, "no_tm", " --set tm.pipeline_impl=rtl --set tm.pipeline_impl_tms=0,2");
  EXPECT_FALSE(no_tm.ok);
  EXPECT_NE(no_tm.log.find("tm.pipeline_impl_tms: TM 2 does not exist"), std::string::npos) << no_tm.log;
  const SimRun no_pipelines = simulate(dir, "no_pipelines", " --set tm.pipeline_impl=rtl --set design.name=strata-streams");
  EXPECT_FALSE(no_pipelines.ok);
  EXPECT_NE(no_pipelines.log.find("tm.pipeline_impl: rtl needs a design with the fused pipelines"), std::string::npos)
      << no_pipelines.log;
}

}  // namespace
