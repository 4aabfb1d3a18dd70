// The frame report: the summary is written from the statistics snapshot, so every number it
// prints is the one in stats.json; the fidelity sentinels warn when they fire; an interrupted
// run reports no frame rate. And strata-sim's Ctrl-C path end to end: exit status 130 with
// valid partial outputs.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "chip_support.h"
#include "model/chip/chip_report.h"
#include "test/support/test_files.h"

namespace strata::chip::test {
namespace {

using sim::testing::read_text;
using sim::testing::TempDir;

std::string line_starting(const std::string& text, const std::string& start) {
  size_t at = 0;
  while (at < text.size()) {
    const size_t end = text.find('\n', at);
    const std::string line = text.substr(at, end == std::string::npos ? std::string::npos : end - at);
    if (line.compare(0, start.size(), start) == 0) return line;
    if (end == std::string::npos) break;
    at = end + 1;
  }
  return "";
}

TEST(FrameReport, SummaryPrintsTheSnapshotsNumbersWithTheirMode) {
  REQUIRE_KERNEL("baseline");
  const SmallFrame frame(scenes::make_cornell({0.2, 1}), 8);
  const sim::PreparedFrame f = frame.on(small_chip(transport::TimingMode::kLooselyTimed, 1, 4));
  Chip chip("chip", f.config, f.inputs);
  sc_core::sc_start();
  ASSERT_TRUE(chip.finished()) << chip.error();
  const FrameReport report(chip, 2.0);
  const stats::Values& v = report.values();
  const std::string s = report.summary();

  EXPECT_NE(line_starting(s, "frame").find(std::to_string(v.count("frame.cycles")) + " cycles"), std::string::npos) << s;
  EXPECT_NE(line_starting(s, "rays").find(std::to_string(v.count("rays.primary.traced")) + " primary"),
            std::string::npos)
      << s;
  EXPECT_NE(line_starting(s, "instructions").find(std::to_string(v.count("instructions.retired")) + " retired"),
            std::string::npos)
      << s;
  char hit[32];
  std::snprintf(hit, sizeof hit, "%.2f%% hit rate", 100.0 * v.number("memory.l1d.hit_rate"));
  EXPECT_NE(line_starting(s, "L1 data").find(hit), std::string::npos) << s;
  char dram[32];
  std::snprintf(dram, sizeof dram, "%.3f MB", v.number("memory.dram.bytes") * 1e-6);
  EXPECT_NE(line_starting(s, "DRAM").find(dram), std::string::npos) << s;
  // Every line with a timing-dependent number names the mode it came from.
  for (const char* start : {"frame", "L1 data", "L1 instruction", "L2 / stream", "DRAM", "bytes by data", "energy",
                            "fidelity"})
    EXPECT_NE(line_starting(s, start).find("[loosely-timed]"), std::string::npos) << start << "\n" << s;
  EXPECT_NE(line_starting(s, "simulator").find("2.00 s wall"), std::string::npos) << s;
  EXPECT_EQ(s.find("warning"), std::string::npos) << s;

  // The JSON says the same.
  const nlohmann::json j = report.to_json();
  EXPECT_EQ(j["frame"]["cycles"], v.count("frame.cycles"));
  EXPECT_EQ(j["units"]["memory.dram.bytes"], "bytes");
  EXPECT_EQ(j["units"]["energy_nj.total"], "nJ");
  EXPECT_EQ(j["timing"]["mode"], "loosely-timed");
  EXPECT_FALSE(j.contains("interrupted"));
  EXPECT_FALSE(j["memory"]["l1d"].contains("per_tm"));
  EXPECT_EQ(report.to_json({"tm"})["memory"]["l1d"]["per_tm"].size(), 1u);
}

TEST(FrameReport, SentinelsWarnWhenACalendarIsTooShort) {
  REQUIRE_KERNEL("baseline");
  const SmallFrame frame(scenes::make_cornell({0.2, 1}), 8);
  ChipConfig config = small_chip(transport::TimingMode::kLooselyTimed, 1, 4);
  config.timing.quantum_cycles = 32;
  config.l1d.calendar_horizon_cycles = 64;  // far less than a miss takes: fills overflow
  config.finalize();
  const sim::PreparedFrame f = frame.on(config);
  Chip chip("chip", f.config, f.inputs);
  sc_core::sc_start();
  ASSERT_TRUE(chip.finished()) << chip.error();
  const FrameReport report(chip, 1.0);
  EXPECT_GT(report.values().count("fidelity.calendar_overflow_bookings"), 0u);
  EXPECT_GT(report.values().count("memory.l1d.calendar_overflow_bookings"), 0u);
  EXPECT_NE(report.summary().find("warning        "), std::string::npos) << report.summary();
}

TEST(FrameReport, AnInterruptedRunHasNoFrameRate) {
  REQUIRE_KERNEL("baseline");
  const SmallFrame frame(scenes::make_cornell({0.2, 1}), 8);
  const sim::PreparedFrame f = frame.on(small_chip(transport::TimingMode::kLooselyTimed, 1, 4));
  Chip chip("chip", f.config, f.inputs);
  sc_core::sc_start(sc_core::sc_time(2000, sc_core::SC_NS));  // stops early, as Ctrl-C would
  ASSERT_FALSE(chip.finished());
  const FrameReport report(chip, 1.0, true);
  const nlohmann::json j = report.to_json();
  EXPECT_EQ(j["interrupted"], true);
  EXPECT_TRUE(j["frame"]["frames_per_second"].is_null());
  EXPECT_GE(j["frame"]["cycles"].get<uint64_t>(), 2000u);
  EXPECT_NE(report.summary().find("cycles simulated before the interrupt"), std::string::npos) << report.summary();
  EXPECT_EQ(report.summary().find("frames/s"), std::string::npos);
}

// strata-sim run, interrupted by SIGINT once it reports progress: exit status 130, and the
// partial image and statistics it wrote are complete files.
TEST(RunCommand, CtrlCExitsWith130AndWritesValidPartialOutputs) {
  TempDir dir;
  const std::string out = (dir / "run").string();
  int err[2];
  ASSERT_EQ(pipe(err), 0);
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    dup2(err[1], STDERR_FILENO);
    const int devnull = ::open("/dev/null", O_WRONLY);
    dup2(devnull, STDOUT_FILENO);
    close(err[0]);
    const std::string config = std::string(STRATA_SOURCE_DIR) + "/sim/configs/trax.json";
    execl(STRATA_SIM_EXE, STRATA_SIM_EXE, "run", "--config", config.c_str(), "--scene", "cornell:size=0.2", "--res",
          "64x64", "--set", "tms=2", "--set", "tps_per_tm=4", "--set", "timing.mode=precise", "--progress",
          "--progress-cycles", "20000", "--no-cache", "--out", out.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  close(err[1]);
  std::string seen;
  char buf[512];
  bool interrupted = false;
  for (ssize_t n; (n = read(err[0], buf, sizeof buf)) > 0;) {
    seen.append(buf, size_t(n));
    if (!interrupted && seen.find("progress:") != std::string::npos) {
      kill(pid, SIGINT);  // the simulation is running: its monitor sees the flag at the next report
      interrupted = true;
    }
  }
  close(err[0]);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(interrupted) << "no progress line was printed:\n" << seen;
  ASSERT_TRUE(WIFEXITED(status)) << seen;
  EXPECT_EQ(WEXITSTATUS(status), 130) << seen;
  const nlohmann::json j = nlohmann::json::parse(read_text(dir / "run/stats.json"));  // throws if cut off
  EXPECT_EQ(j["interrupted"], true);
  EXPECT_TRUE(j["frame"]["frames_per_second"].is_null());
  EXPECT_LT(j["frame"]["pixels_done"].get<uint64_t>(), 64u * 64u);
  const std::string png = read_text(dir / "run/image.png");
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  const std::string exr = read_text(dir / "run/image.exr");
  ASSERT_GT(exr.size(), 4u);
  EXPECT_EQ(exr.substr(0, 4), std::string("\x76\x2f\x31\x01", 4)) << "not an OpenEXR file";
}

}  // namespace
}  // namespace strata::chip::test
