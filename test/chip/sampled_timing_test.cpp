// Sampled timing end to end: runs the built strata-sim (STRATA_SIM_EXE) on a small Cornell
// frame in loosely-timed and in sampled mode. Sampling must not change what is computed (the
// image and ray statistics still equal the native twin's, which --check enforces), it must
// actually fast-forward, and its frame time must stay close to the loosely-timed one.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "model/sampling/window_sampler.h"
#include "test/support/test_files.h"

namespace {

namespace fs = std::filesystem;
using strata::sim::testing::read_text;
using strata::sim::testing::TempDir;
using strata::sampling::WindowSampler;

// Small windows, so a 32x32 frame (run_frame's, unless `extra` names another) on two TMs spans
// hundreds of sampling periods.
const char* kSmallChip =
    " --set tms=2 --set tps_per_tm=8 --set memory.stream.size_bytes=524288 --set timing.quantum_cycles=500"
    " --set timing.sample_period_cycles=6000 --set timing.sample_detail_cycles=3000"
    " --set timing.sample_warmup_cycles=1000 --scene cornell:size=0.2 --quiet --check";

nlohmann::json run_frame(const TempDir& dir, const std::string& design, const std::string& mode,
                         const std::string& tag = "", const std::string& extra = "") {
  const fs::path out = dir.path() / (design + "-" + mode + tag);
  const std::string cmd = std::string("'") + STRATA_SIM_EXE + "' run --config '" + STRATA_SOURCE_DIR +
                          "/sim/configs/" + design + ".json' --set timing.mode=" + mode + kSmallChip +
                          (extra.find("--res ") == std::string::npos ? " --res 32x32" : "") + extra + " --out '" +
                          out.string() + "' >'" + (dir.path() / "log.txt").string() + "' 2>&1";
  const int status = std::system(cmd.c_str());
  EXPECT_TRUE(status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0)
      << design << " " << mode << ":\n" << read_text(dir.path() / "log.txt");
  std::ifstream in(out / "stats.json");
  if (!in) return {};
  return nlohmann::json::parse(in);
}

class SampledTiming : public ::testing::TestWithParam<const char*> {};

TEST_P(SampledTiming, KeepsTheImageAndStaysNearLooselyTimed) {
  ASSERT_TRUE(fs::exists(std::string(STRATA_BUILD_DIR) + "/firmware/kernels/streams_pipelines.elf"))
      << "the kernels were not built";
  TempDir dir;
  const nlohmann::json lt = run_frame(dir, GetParam(), "lt");
  const nlohmann::json sampled = run_frame(dir, GetParam(), "sampled");
  ASSERT_FALSE(lt.is_null());
  ASSERT_FALSE(sampled.is_null());
  EXPECT_EQ(sampled["timing"]["mode"], "sampled");
  EXPECT_EQ(sampled["rays"], lt["rays"]);  // both also equal the twin's (--check)

  const auto& s = sampled["sampling"];
  const double timed = s["timed_instructions"].get<double>();
  const double forwarded = s["fast_forward_instructions"].get<double>();
  const double retired = sampled["instructions"]["retired"].get<double>();
  EXPECT_GT(timed, 0.0);
  EXPECT_GT(forwarded, 0.2 * retired) << "half of every period should fast-forward";
  EXPECT_DOUBLE_EQ(timed + forwarded, retired);
  EXPECT_NEAR(s["extrapolation_factor"].get<double>(), retired / timed, 1e-9);

  const double lt_cycles = lt["frame"]["cycles"].get<double>();
  const double sampled_cycles = sampled["frame"]["cycles"].get<double>();
  EXPECT_NEAR(sampled_cycles / lt_cycles, 1.0, 0.10) << "LT " << lt_cycles << " vs sampled " << sampled_cycles;
  // Instruction-proportional counters are extrapolated to the whole frame.
  const double lt_l1 = lt["memory"]["l1d"]["accesses"].get<double>();
  EXPECT_NEAR(sampled["memory"]["l1d"]["accesses"].get<double>() / lt_l1, 1.0, 0.15);
  // The stream memory moves the same rays in every mode, fast-forward included, so the rays
  // it stored and took are exact; only refused pushes and empty pops (timing-dependent) are
  // estimated, and the totals include them. (TRaX has no stream memory: its counts are 0.)
  if (std::string(GetParam()) != "trax") {
    const auto& ls = lt["memory"]["stream"];
    const auto& ss = sampled["memory"]["stream"];
    EXPECT_GT(ls["rays_pushed"].get<double>(), 0.0);
    EXPECT_EQ(ss["rays_pushed"], ls["rays_pushed"]);
    EXPECT_EQ(ss["rays_popped"], ls["rays_popped"]);
    EXPECT_EQ(ss["pushes"].get<double>(), ss["rays_pushed"].get<double>() + ss["full_rejections"].get<double>());
    EXPECT_EQ(ss["pops"].get<double>(), ss["rays_popped"].get<double>() + ss["empty_pops"].get<double>());
    EXPECT_FALSE(sampled["intervals"]["stats"].contains(nlohmann::json::json_pointer("/memory/stream/rays_pushed")));
  }

  // Deterministic: the same frame again gives the same estimates, to the bit.
  const nlohmann::json again = run_frame(dir, GetParam(), "sampled", "-again");
  ASSERT_FALSE(again.is_null());
  for (const char* part : {"frame", "rays", "instructions", "memory", "xu", "energy_nj", "sampling"})
    EXPECT_EQ(again[part], sampled[part]) << part;
}

// Without warming, the caches are as the last detailed window left them, so every window
// starts with misses LT would not have: on this frame DRAM bytes come out about 70% high. With
// the fast-forward's loads and stores replayed into the tags, they come within a few percent.
TEST_P(SampledTiming, FunctionalWarmingRemovesTheStaleCacheBias) {
  TempDir dir;
  const nlohmann::json lt = run_frame(dir, GetParam(), "lt");
  const nlohmann::json cold = run_frame(dir, GetParam(), "sampled", "-cold", " --set timing.functional_warming=false");
  const nlohmann::json warm = run_frame(dir, GetParam(), "sampled", "-warm", " --set timing.functional_warming=true");
  ASSERT_FALSE(lt.is_null() || cold.is_null() || warm.is_null());
  EXPECT_EQ(cold["sampling"]["warm_requests"], 0);
  EXPECT_GT(warm["sampling"]["warm_requests"].get<double>(), 1000.0);
  EXPECT_LT(warm["sampling"]["warm_requests"].get<double>(), warm["sampling"]["fast_forward_instructions"].get<double>());
  EXPECT_EQ(warm["rays"], lt["rays"]);
  const auto error = [&](const nlohmann::json& s, const char* level, const char* what) {
    const double reference = lt["memory"][level][what].get<double>();
    return std::abs(s["memory"][level][what].get<double>() / reference - 1.0);
  };
  // The bias is about +70% cold; what is left warm is the sampling noise of a few hundred
  // misses (the frame's DRAM interval is about +-70% at this size), so compare, with margin.
  EXPECT_GT(error(cold, "dram", "bytes"), 0.3) << "the stale-cache bias this test is about is gone";
  EXPECT_LT(error(warm, "dram", "bytes"), error(cold, "dram", "bytes") / 3);
  EXPECT_LT(error(warm, "l2", "misses"), error(cold, "l2", "misses") / 3);
  // L2 accesses are mostly hits, which the stale caches barely change (cold and warm land a
  // few percent either side of LT, both well inside the +-18% interval at this size), so
  // warm is held to its own 95% interval rather than to the cold estimate.
  const double l2_half_width = warm["intervals"]["stats"]["memory"]["l2"]["accesses"]["half_width"].get<double>();
  EXPECT_GT(l2_half_width, 0.0);
  EXPECT_LE(std::abs(warm["memory"]["l2"]["accesses"].get<double>() - lt["memory"]["l2"]["accesses"].get<double>()),
            l2_half_width);
}

// Every estimate carries a 95% interval; exact figures carry none; an error target makes the
// sampler time more of the frame when it is tighter, and says whether it was met.
TEST_P(SampledTiming, EstimatesCarryIntervalsAndATighterTargetTimesMore) {
  TempDir dir;
  // On frame cycles alone: the memory figures of this small frame vary far more (the next tests).
  // The tight target is the tightest accepted: with the frame's head and drain timed apart, the
  // loose one's 36 windows already give trax +-0.25% on cycles (it was 0.5%).
  // The clock's error bound off: a target on frame cycles is then a target on the samples' spread.
  const std::string sparse = " --set timing.sample_period_cycles=24000 --set timing.sample_target_stats=frame.cycles"
                             " --set timing.sample_clock_bound=0";
  const nlohmann::json loose =
      run_frame(dir, GetParam(), "sampled", "-loose", sparse + " --set timing.sample_target_error=0.5");
  const nlohmann::json tight =
      run_frame(dir, GetParam(), "sampled", "-tight", sparse + " --set timing.sample_target_error=0.001");
  ASSERT_FALSE(loose.is_null() || tight.is_null());
  for (const nlohmann::json* j : {&loose, &tight}) {
    const auto& iv = (*j)["intervals"];
    EXPECT_EQ(iv["confidence"], 0.95);
    EXPECT_GE(iv["batches"].get<int>(), 2);
    for (const char* path : {"/frame/cycles", "/memory/l2/accesses", "/memory/dram/bytes", "/energy_nj/total"}) {
      const auto ptr = nlohmann::json::json_pointer("/stats" + std::string(path) + "/half_width");
      ASSERT_TRUE(iv.contains(ptr)) << path;
      const double hw = iv[ptr].get<double>();
      EXPECT_TRUE(std::isfinite(hw) && hw > 0) << path << " " << hw;
    }
    EXPECT_FALSE(iv["stats"].contains("rays")) << "rays are exact";
    EXPECT_FALSE(iv["stats"].contains(nlohmann::json::json_pointer("/instructions/retired"))) << "exact";
  }
  EXPECT_EQ(loose["rays"], tight["rays"]);
  EXPECT_GT(tight["sampling"]["timed_instructions"].get<double>(), 1.2 * loose["sampling"]["timed_instructions"].get<double>());
  EXPECT_GT(tight["sampling"]["period_changes"].get<int>(), 0);
  EXPECT_GT(tight["sampling"]["windows"].get<double>(), 2 * loose["sampling"]["windows"].get<double>());
  // About 44 periods of 24,000 cycles: the loose target is met with room, so the windows thin
  // out past the configured period, but never past a 32nd of the whole frame
  // (WindowSampler::max_period; the frame's length is projected from its progress, hence the
  // margin).
  const double loose_period = loose["sampling"]["last_period_cycles"].get<double>();
  EXPECT_GT(loose_period, 24000.0);
  EXPECT_LE(loose_period, 1.25 * loose["frame"]["cycles"].get<double>() / 32);
}

// A target within easy reach thins the windows out past the configured period (here 6,000
// cycles, about 180 windows on this frame), and the frame's interval still meets the target.
TEST_P(SampledTiming, ATargetWithinReachTimesLessThanTheConfiguredPeriod) {
  TempDir dir;
  const nlohmann::json fixed = run_frame(dir, GetParam(), "sampled", "-fixed");
  const nlohmann::json thin = run_frame(dir, GetParam(), "sampled", "-thin",
                                       " --set timing.sample_target_error=0.2 --set timing.sample_target_stats=frame.cycles");
  ASSERT_FALSE(fixed.is_null() || thin.is_null());
  EXPECT_EQ(thin["rays"], fixed["rays"]);
  const double fixed_timed = fixed["sampling"]["timed_instructions"].get<double>();
  EXPECT_LT(thin["sampling"]["timed_instructions"].get<double>(), 0.6 * fixed_timed);
  EXPECT_LT(thin["sampling"]["windows"].get<double>(), 0.6 * fixed["sampling"]["windows"].get<double>());
  const double cycles = thin["frame"]["cycles"].get<double>();
  const double half_width = thin["intervals"]["stats"]["frame"]["cycles"]["half_width"].get<double>();
  EXPECT_GT(half_width, 0.0);
  EXPECT_LE(half_width / cycles, 0.2);
  // Both estimate the same frame: within the two intervals of each other.
  const double fixed_half_width = fixed["intervals"]["stats"]["frame"]["cycles"]["half_width"].get<double>();
  EXPECT_LE(std::abs(cycles - fixed["frame"]["cycles"].get<double>()), half_width + fixed_half_width);
}

// A target the frame cannot reach, on a frame too short for the plan to judge it out of reach
// (fewer than kReachWindows windows), drives the period down to the shortest the sampler
// allows, and the summary says the target was missed and why (the frame ended first).
TEST(SampledTimingTargets, AnUnreachableTargetOnAShortFrameIsReportedAsMissed) {
  TempDir dir;
  const nlohmann::json j =
      run_frame(dir, "strata-pipelines", "sampled", "-unreachable", " --set timing.sample_target_error=0.001 --res 8x8");
  ASSERT_FALSE(j.is_null());
  const auto& s = j["sampling"];
  ASSERT_LT(s["windows"].get<size_t>(), WindowSampler::kReachWindows) << "the frame should be too short for a verdict";
  // Only frame cycles, at once: 0.1% is inside the clock's error bound (timing.sample_clock_bound).
  EXPECT_EQ(s["targets_out_of_reach"].get<int>(), 1);
  EXPECT_GT(s["min_period_cycles"].get<double>(), s["detail_cycles"].get<double>());
  EXPECT_EQ(s["last_period_cycles"], s["min_period_cycles"]);
  const double reached = j["intervals"]["stats"]["frame"]["cycles"]["relative"].get<double>();
  EXPECT_GT(reached, 0.001);
  const std::string summary = read_text(dir.path() / "log.txt");
  EXPECT_NE(summary.find("warning        the error target was not met: frame cycles \u00b1 0.1% asked"),
            std::string::npos)
      << summary;
  EXPECT_NE(summary.find("the shortest allowed): use timing.mode=lt"), std::string::npos) << summary;
  EXPECT_EQ(summary.find("target         frame cycles"), std::string::npos) << summary;
  EXPECT_NE(summary.find("left out of the plan: frame cycles from the start"), std::string::npos) << summary;
}

// A target on frame cycles no wider than the clock's error bound can never be met: it is out of
// reach at once, the plan has nothing left, and the frame is timed exactly as without a target
// (no pilot at the shortest period): a missed target costs nothing.
TEST(SampledTimingTargets, ATargetInsideTheClocksBoundIsOutOfReachAtOnce) {
  TempDir dir;
  const nlohmann::json plain = run_frame(dir, "strata-pipelines", "sampled", "-plain");
  const nlohmann::json j = run_frame(dir, "strata-pipelines", "sampled", "-inside",
                                     " --set timing.sample_target_error=0.02 --set timing.sample_target_stats=frame.cycles");
  ASSERT_FALSE(plain.is_null() || j.is_null());
  const std::string summary = read_text(dir.path() / "log.txt");
  EXPECT_EQ(j["sampling"]["targets_out_of_reach"].get<int>(), 1);
  EXPECT_EQ(j["sampling"]["period_changes"].get<int>(), 0) << summary;
  EXPECT_EQ(j["sampling"]["timed_instructions"], plain["sampling"]["timed_instructions"]);
  EXPECT_EQ(j["frame"]["cycles"], plain["frame"]["cycles"]);
  EXPECT_NE(summary.find("frame cycles from the start (its interval holds the clock's own error, at least "
                         "timing.sample_clock_bound = \u00b1 2.50%)"),
            std::string::npos)
      << summary;
}

// A target the shortest period cannot reach is left out of the plan once the windows show it
// (issue 38, part 3): the frame goes back to the configured period instead of paying for the
// shortest to its end and missing anyway, and the summary says which target, when, and why.
TEST_P(SampledTiming, ATargetOutOfReachCostsNoMoreThanTheConfiguredWindows) {
  TempDir dir;
  const std::string longer = " --set timing.sample_period_cycles=30000";
  const nlohmann::json plain = run_frame(dir, GetParam(), "sampled", "-plain", longer);
  const nlohmann::json j = run_frame(dir, GetParam(), "sampled", "-reach",
                                     longer + " --set timing.sample_target_error=0.001"
                                              " --set timing.sample_target_stats=memory.dram.bytes");
  ASSERT_FALSE(plain.is_null() || j.is_null());
  const std::string summary = read_text(dir.path() / "log.txt");
  const auto& s = j["sampling"];
  EXPECT_EQ(s["targets_out_of_reach"].get<int>(), 1) << summary;
  EXPECT_EQ(s["last_period_cycles"].get<double>(), 30000.0) << summary;  // back to the configured period
  // The pilot and the windows before the verdict run at the shortest period; the rest as
  // without a target. Far less timed than at the shortest period throughout (about half).
  const double timed = s["timed_instructions"].get<double>() / j["instructions"]["retired"].get<double>();
  const double plain_timed =
      plain["sampling"]["timed_instructions"].get<double>() / plain["instructions"]["retired"].get<double>();
  EXPECT_LT(timed, 0.3) << summary;
  EXPECT_LT(timed, plain_timed + 0.15) << summary;
  EXPECT_FALSE(j["intervals"]["target"]["stats"]["memory.dram.bytes"]["met"].get<bool>());
  EXPECT_NE(summary.find("out of reach at the shortest period ("), std::string::npos) << summary;
  EXPECT_NE(summary.find("left out of the plan: memory.dram.bytes at cycle "), std::string::npos) << summary;
  EXPECT_NE(summary.find("(none left: the configured period)"), std::string::npos) << summary;
  EXPECT_NE(summary.find("no windows were spent on them: use timing.mode=lt"), std::string::npos) << summary;
}

// The target holds for the statistics it names (issue 35, part 1). DRAM bytes vary between this
// frame's windows several times more than its cycles do, so a target on DRAM bytes times more
// of the frame than the same target on cycles alone; the summary and stats.json say, per
// statistic, whether the target was met. TRaX, at 30%: a DRAM target this frame can just reach
// (±29.9%; the plan judges it out of reach only late in the frame, at a projected ±30.3%). At
// 10%, and on strata-pipelines at 30%, it is out of reach early and left out of the plan
// (ATargetOutOfReachCostsNoMoreThanTheConfiguredWindows).
TEST(SampledTimingTargets, ATargetOnDramBytesTimesMoreThanOneOnCyclesAlone) {
  TempDir dir;
  const std::string target = " --set timing.sample_target_error=0.3 --set timing.sample_target_stats=";
  const nlohmann::json cycles = run_frame(dir, "trax", "sampled", "-cycles", target + "frame.cycles");
  const std::string cycles_log = read_text(dir.path() / "log.txt");
  const nlohmann::json dram = run_frame(dir, "trax", "sampled", "-dram", target + "frame.cycles,memory.dram.bytes");
  const std::string dram_log = read_text(dir.path() / "log.txt");
  ASSERT_FALSE(cycles.is_null() || dram.is_null());
  EXPECT_EQ(cycles["rays"], dram["rays"]);
  const auto relative = [](const nlohmann::json& j, const char* path) {
    return j["intervals"]["stats"][nlohmann::json::json_pointer(path)]["relative"].get<double>();
  };
  // Under the cycles-only target, DRAM is left far wider than cycles: the case the option is for.
  EXPECT_GT(relative(cycles, "/memory/dram/bytes"), 2 * relative(cycles, "/frame/cycles"));
  EXPECT_GT(dram["sampling"]["timed_instructions"].get<double>(),
            1.5 * cycles["sampling"]["timed_instructions"].get<double>());
  // Not asserted: that the DRAM interval narrows. On this frame it does not (trax, measured
  // 2026-12-06: 0.79-0.92 at 40 and at 345 windows by the jackknife, in either fast-forward
  // order; 0.38-0.49 by successive differences): the frame's cold head, several times the DRAM
  // per data op of the rest, reads as sampling error whatever the windows
  // (docs/sampled-timing.md, "STRaTA's memory bias", the frame's head).
  // Per named statistic: stats.json's intervals.target, and a line of the summary.
  const auto& t = dram["intervals"]["target"];
  EXPECT_EQ(t["error"], 0.3);
  ASSERT_TRUE(t["stats"].contains("memory.dram.bytes")) << t.dump();
  EXPECT_EQ(t["stats"].size(), 2u);
  for (const auto& [path, got] : t["stats"].items()) {
    const double reached = got["relative"].get<double>();
    EXPECT_EQ(got["met"].get<bool>(), reached >= 0 && reached <= 0.3) << path;
  }
  EXPECT_DOUBLE_EQ(t["stats"]["memory.dram.bytes"]["relative"].get<double>(), relative(dram, "/memory/dram/bytes"));
  const bool dram_met = t["stats"]["memory.dram.bytes"]["met"].get<bool>();
  EXPECT_NE(dram_log.find(dram_met ? "target         memory.dram.bytes \u00b1 30.0% asked"
                                   : "the error target was not met: memory.dram.bytes \u00b1 30.0% asked"),
            std::string::npos)
      << dram_log;
  EXPECT_NE(dram_log.find("planned for the widest of frame.cycles,memory.dram.bytes"), std::string::npos) << dram_log;
  EXPECT_EQ(cycles_log.find("memory.dram.bytes \u00b1"), std::string::npos) << cycles_log;
  EXPECT_EQ(cycles["intervals"]["target"]["stats"].size(), 1u);
}

// A target names statistics that exist and have an interval to hold: anything else stops the run
// before it starts, with the field and the entry named.
TEST(SampledTimingTargets, ABadStatisticNameIsRefusedWithTheFieldNamed) {
  TempDir dir;
  const std::pair<const char*, const char*> cases[] = {
      {"memory.dram.nope", "\"memory.dram.nope\" is not a statistic"},
      {"memory.dram", "\"memory.dram\" is a group"},
      {"rays.total", "\"rays.total\" is exact in sampled timing"},
      {"memory.l1d.hit_rate", "\"memory.l1d.hit_rate\" is a level, a ratio or a rate"},
      {"frame.cycles,,memory.dram.bytes", "an empty entry"},
      {"memory.dram.bytes,memory.dram.bytes", "\"memory.dram.bytes\" is named twice"},
  };
  for (const auto& [stats, message] : cases) {
    const fs::path log = dir.path() / "bad.txt";
    const std::string cmd = std::string("'") + STRATA_SIM_EXE + "' run --config '" + STRATA_SOURCE_DIR +
                            "/sim/configs/trax.json' --set timing.mode=sampled --scene cornell:size=0.2 --res 8x8 "
                            "--set 'timing.sample_target_stats=" + stats + "' --out '" + (dir.path() / "out").string() +
                            "' >'" + log.string() + "' 2>&1";
    const int status = std::system(cmd.c_str());
    EXPECT_TRUE(status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 1) << stats;
    const std::string text = read_text(log);
    EXPECT_NE(text.find("timing.sample_target_stats: "), std::string::npos) << text;
    EXPECT_NE(text.find(message), std::string::npos) << text;
  }
}

// A fast-forward batch runs one TP until it is timing.fast_forward_batch_quanta past its TM's
// runner-up (quanta of 500 cycles here). Longer batches switch TPs less often (the cost that
// knob trades); they compute the same rays, and the frame estimate stays where the shorter
// batches put it.
// For the STRaTA designs this holds in arrival order: in time order (the default) a batch
// mostly ends at its first stream operation dated past the TM's runner-up, whatever its length
// (strata-pipelines here: 19,916 batches of 1 quantum, 23,899 of 4).
TEST_P(SampledTiming, LongerFastForwardBatchesSwitchTpsLessOften) {
  TempDir dir;
  const std::string order = std::string(GetParam()) == "trax" ? "" : " --set timing.fast_forward_time_order=false";
  const nlohmann::json short_batches =
      run_frame(dir, GetParam(), "sampled", "-short", " --set timing.fast_forward_batch_quanta=1" + order);
  const nlohmann::json long_batches =
      run_frame(dir, GetParam(), "sampled", "-long", " --set timing.fast_forward_batch_quanta=4" + order);
  ASSERT_FALSE(short_batches.is_null() || long_batches.is_null());
  const auto& ss = short_batches["sampling"];
  const auto& ls = long_batches["sampling"];
  EXPECT_EQ(ss["fast_forward_batch_cycles"], 500);
  EXPECT_EQ(ls["fast_forward_batch_cycles"], 2000);
  EXPECT_EQ(long_batches["rays"], short_batches["rays"]);  // and both equal the twin's (--check)
  EXPECT_GT(ls["fast_forward_instructions"].get<double>(), 0.2 * long_batches["instructions"]["retired"].get<double>());
  EXPECT_GT(ss["fast_forward_batches"].get<double>(), 0.0);
  EXPECT_LT(ls["fast_forward_batches"].get<double>(), 0.5 * ss["fast_forward_batches"].get<double>());
  const double short_cycles = short_batches["frame"]["cycles"].get<double>();
  EXPECT_NEAR(long_batches["frame"]["cycles"].get<double>() / short_cycles, 1.0, 0.10);
}

// Issue 35: the fast-forward ran each TP in batches of up to 16 quanta, so its stream
// operations changed the ray buffers in arrival order; the buffers then held more rays per
// treelet than LT's, the detailed windows inherited them, and STRaTA's L2 accesses and DRAM
// bytes came out 12-33% low (Sibenik 256x256 and 512x512). In time order (the default) the
// pushes, pops and assignments reach the stream memory in date order, as in LT. Neither LT nor
// precise timing is strictly in order (on this frame about 1 in 1,000 ops is dated before one
// already served: 39 in LT, 60 in precise), so the test asks for LT's level, not for 0.
TEST(SampledTimingOrder, TheFastForwardChangesTheRayBuffersInTimeOrder) {
  TempDir dir;
  const char* design = "strata-pipelines";
  const nlohmann::json lt = run_frame(dir, design, "lt");
  const nlohmann::json ordered = run_frame(dir, design, "sampled");
  const nlohmann::json arrival =
      run_frame(dir, design, "sampled", "-arrival", " --set timing.fast_forward_time_order=false");
  ASSERT_FALSE(lt.is_null() || ordered.is_null() || arrival.is_null());
  // The share of the frame's stream accesses dated before one already served.
  const auto late = [](const nlohmann::json& r) {
    const auto& s = r["memory"]["stream"];
    return s["schedule_ops_out_of_order"].get<double>() / s["accesses"].get<double>();
  };
  EXPECT_LT(late(lt), 0.01);
  EXPECT_LT(late(ordered), 0.01);
  EXPECT_GT(late(arrival), 0.10);  // 45% on this frame
  EXPECT_GT(ordered["sampling"]["fast_forward_instructions"].get<double>(),
            0.2 * ordered["instructions"]["retired"].get<double>());
  EXPECT_EQ(ordered["rays"], lt["rays"]);  // and both equal the twin's (--check)
  EXPECT_EQ(arrival["rays"], lt["rays"]);
}

// Issue 39, F1: with a period longer than the frame (3.1 M cycles here), the frame ends before
// the sampler's first snapshot, and its tail, the first window, is its only sample. Every period
// that long samples the same cycles, so the figures must not depend on it. Before, the tail
// was weighted by its share of the period and weighted counts are whole numbers: at
// 4294967295 (the largest accepted) the trax frame reported 0 L2 accesses and a 100% L1 hit
// rate, and at 1e7 95,240 L2 accesses where the unrounded tail gives 96,134.
// (Without the head stratum, which would time such a frame in full: the next test.)
TEST_P(SampledTiming, APeriodLongerThanTheFrameKeepsTheMemoryFigures) {
  TempDir dir;
  const std::string no_head = " --set timing.sample_head_periods=0";
  const nlohmann::json ten_million =
      run_frame(dir, GetParam(), "sampled", "-1e7", " --set timing.sample_period_cycles=10000000" + no_head);
  const nlohmann::json largest =
      run_frame(dir, GetParam(), "sampled", "-max", " --set timing.sample_period_cycles=4294967295" + no_head);
  ASSERT_FALSE(ten_million.is_null() || largest.is_null());
  ASSERT_LT(ten_million["frame"]["cycles"].get<double>(), 5e6) << "the frame must end before the first snapshot";
  EXPECT_EQ(ten_million["sampling"]["windows"], 0);
  EXPECT_EQ(largest["sampling"]["windows"], 0);
  EXPECT_EQ(largest["frame"]["cycles"], ten_million["frame"]["cycles"]);
  EXPECT_EQ(largest["memory"], ten_million["memory"]);
  EXPECT_EQ(largest["energy_nj"], ten_million["energy_nj"]);
  const auto& l1d = largest["memory"]["l1d"];
  EXPECT_GT(l1d["hit_rate"].get<double>(), 0.5);
  EXPECT_LT(l1d["hit_rate"].get<double>(), 1.0);
  EXPECT_GT(l1d["misses"].get<double>(), 0.0);
  EXPECT_GT(largest["memory"]["l2"]["accesses"].get<double>(), 0.0);
  EXPECT_GT(largest["memory"]["dram"]["bytes"].get<double>(), 0.0);
}

// The frame's head is a window timed in full from cycle 0, with no warm-up (there is nothing to
// warm: LT's caches are cold there too). A frame that ends in its head is therefore timed
// exactly as LT times it: every figure equals LT's, and the summary says there was nothing to
// estimate.
TEST_P(SampledTiming, AFrameThatEndsInItsHeadIsTimedAsLtTimesIt) {
  TempDir dir;
  const nlohmann::json lt = run_frame(dir, GetParam(), "lt");
  const nlohmann::json full =
      run_frame(dir, GetParam(), "sampled", "-head", " --set timing.sample_period_cycles=10000000");
  const std::string summary = read_text(dir.path() / "log.txt");
  ASSERT_FALSE(lt.is_null() || full.is_null());
  for (const char* part : {"frame", "rays", "memory", "xu", "energy_nj"}) EXPECT_EQ(full[part], lt[part]) << part;
  EXPECT_EQ(full["sampling"]["head_cycles"], lt["frame"]["cycles"]);
  EXPECT_EQ(full["sampling"]["timed_instructions"], full["instructions"]["retired"]);
  EXPECT_NE(summary.find("no confidence intervals: the frame was timed in full as its head and drain strata"),
            std::string::npos)
      << summary;
}

// A frame whose rest, projected shortly before its head ends, is under 8 configured periods is
// too short for sampling (issue 38, part 3): its windows would give an interval from a handful
// of batches. It is timed in full from the start, exactly as LT times it, and the summary says
// so. With a period half as long the same frame is sampled as before.
TEST_P(SampledTiming, AFrameTooShortForSamplingIsTimedAsLtTimesIt) {
  TempDir dir;
  const nlohmann::json lt = run_frame(dir, GetParam(), "lt", "-short", " --res 16x16");
  const nlohmann::json sampled =
      run_frame(dir, GetParam(), "sampled", "-short", " --res 16x16 --set timing.sample_period_cycles=40000");
  const std::string summary = read_text(dir.path() / "log.txt");
  const nlohmann::json longer =
      run_frame(dir, GetParam(), "sampled", "-longer", " --res 16x16 --set timing.sample_period_cycles=20000");
  ASSERT_FALSE(lt.is_null() || sampled.is_null() || longer.is_null());
  for (const char* part : {"frame", "rays", "memory", "xu", "energy_nj"}) EXPECT_EQ(sampled[part], lt[part]) << part;
  EXPECT_EQ(sampled["sampling"]["timed_instructions"], sampled["instructions"]["retired"]);
  const double rest = sampled["sampling"]["short_frame_rest_cycles"].get<double>();
  EXPECT_GT(rest, 0.0);
  EXPECT_LT(rest, 8 * 40000.0);
  EXPECT_NE(summary.find("too short for sampling: near its head's end the frame was projected to run "), std::string::npos)
      << summary;
  EXPECT_NE(summary.find("100.0% of instructions timed: the whole frame, no windows"), std::string::npos) << summary;
  EXPECT_EQ(longer["sampling"]["short_frame_rest_cycles"].get<double>(), 0.0);
  EXPECT_LT(longer["sampling"]["timed_instructions"].get<double>(), longer["instructions"]["retired"].get<double>());
}

// The drain (docs/sampled-timing.md, "Head and drain strata"): once every pixel has been handed
// out and at most a quarter are left to finish, the rest of the frame is one window timed in
// full, estimated by its own ratio and in no batch. On this STRaTA frame every pixel is handed
// out at once (the stream memory holds more paths than the frame has pixels), so the drain is
// the last quarter of the pixels; TRaX hands its last pixels out at the very end.
TEST_P(SampledTiming, TheDrainIsAStratumTimedInFull) {
  TempDir dir;
  const nlohmann::json lt = run_frame(dir, GetParam(), "lt");
  const nlohmann::json drain = run_frame(dir, GetParam(), "sampled", "-drain");
  const std::string summary = read_text(dir.path() / "log.txt");
  const nlohmann::json none = run_frame(dir, GetParam(), "sampled", "-none", " --set timing.sample_drain_share=0");
  ASSERT_FALSE(lt.is_null() || drain.is_null() || none.is_null());
  const double cycles = drain["frame"]["cycles"].get<double>();
  const double drained = drain["sampling"]["drain_cycles"].get<double>();
  EXPECT_GT(drained, 3000.0) << "longer than a window's warm-up";
  EXPECT_LT(drained, 0.5 * cycles);
  EXPECT_EQ(none["sampling"]["drain_cycles"], 0);
  EXPECT_GT(drain["sampling"]["timed_instructions"].get<double>(), none["sampling"]["timed_instructions"].get<double>());
  EXPECT_NE(summary.find("strata         head 24000 cycles, drain " + std::to_string(uint64_t(drained)) + " cycles"),
            std::string::npos)
      << summary;
  // The summary says the frame time is the simulated clock.
  EXPECT_NE(summary.find("frame time     the simulated clock, " +
                         std::to_string(drain["intervals"]["simulated_frame_cycles"].get<uint64_t>()) + " cycles"),
            std::string::npos)
      << summary;
  // Only the middle's batches have replicates.
  EXPECT_EQ(drain["intervals"]["replicates"]["frame.cycles"].size(), drain["intervals"]["batches"].get<size_t>());
  // Near LT by the interval's measure. Twice the 95% half-width: 340 windows make it +-0.09%
  // on cycles here, and the estimate's own error (the measured parts' cycles per instruction
  // against LT's) is of that size (+0.09%; the simulated clock +0.08%).
  for (const char* path : {"/frame/cycles", "/energy_nj/total"}) {
    const auto ptr = nlohmann::json::json_pointer(path);
    const double half_width =
        drain["intervals"]["stats"][nlohmann::json::json_pointer(std::string(path) + "/half_width")].get<double>();
    EXPECT_LE(std::abs(drain[ptr].get<double>() - lt[ptr].get<double>()), 2 * half_width) << path;
  }
}

// A frame shorter than the sampler's pilot never got a plan: the warning says so, rather than
// that a plan expected the target met (issue 39, minor).
TEST_P(SampledTiming, ATargetOnAFrameTooShortToPlanSaysNoPlanWasPossible) {
  TempDir dir;
  const nlohmann::json j = run_frame(dir, GetParam(), "sampled", "-short",
                                     " --set timing.sample_period_cycles=10000000 --set timing.sample_target_error=0.05"
                                     " --set timing.sample_head_periods=0");
  ASSERT_FALSE(j.is_null());
  EXPECT_EQ(j["sampling"]["windows"], 0);
  const std::string summary = read_text(dir.path() / "log.txt");
  EXPECT_NE(summary.find("the error target was not met: frame cycles \u00b1 5.0% asked, no interval reached"),
            std::string::npos)
      << summary;
  EXPECT_NE(summary.find("no plan was possible: the frame held 0 window(s) before its last"), std::string::npos)
      << summary;
  EXPECT_EQ(summary.find("last plan expected it met"), std::string::npos) << summary;
}

std::string design_name(const ::testing::TestParamInfo<const char*>& p) {
  return std::string(p.param) == "trax" ? "trax" : "pipelines";
}

// timing.sample_interval picks how the replicates become intervals (model/stats/
// interval_method.h); the windows, and so every estimate, are the same either way. On this
// frame, whose cold head has several times the rest's DRAM bytes per data op, successive
// differences give a narrower DRAM interval than the jackknife (38% against 79%, measured
// 2026-12-06 on trax); stats.json and the summary name the method.
TEST(SampledTimingIntervals, TheMethodChangesTheIntervalsNotTheEstimates) {
  TempDir dir;
  const nlohmann::json jack = run_frame(dir, "trax", "sampled", "-jack", " --set timing.sample_interval=jackknife");
  const std::string jack_log = read_text(dir.path() / "log.txt");
  const nlohmann::json succ = run_frame(dir, "trax", "sampled", "-succ", "");  // the default
  const std::string succ_log = read_text(dir.path() / "log.txt");
  ASSERT_FALSE(jack.is_null() || succ.is_null());
  for (const char* path : {"/frame/cycles", "/memory/l2/accesses", "/memory/dram/bytes", "/energy_nj/total"}) {
    const auto ptr = nlohmann::json::json_pointer(path);
    EXPECT_EQ(jack[ptr], succ[ptr]) << path;
  }
  EXPECT_EQ(jack["intervals"]["batches"], succ["intervals"]["batches"]);
  const auto half_width = [](const nlohmann::json& j, const char* path) {
    return j["intervals"]["stats"][nlohmann::json::json_pointer(path)]["half_width"].get<double>();
  };
  EXPECT_LT(half_width(succ, "/memory/dram/bytes"), 0.8 * half_width(jack, "/memory/dram/bytes"));
  EXPECT_GT(half_width(succ, "/frame/cycles"), 0.0);
  EXPECT_NE(jack["intervals"]["method"].get<std::string>().find("by jackknife"), std::string::npos);
  EXPECT_NE(succ["intervals"]["method"].get<std::string>().find("by successive differences"), std::string::npos);
  // The share of the frame measured, and the replicates behind the main figures' intervals,
  // one per batch.
  const double share = succ["intervals"]["measured_share"].get<double>();
  EXPECT_GT(share, 0.0);
  EXPECT_LT(share, 1.0);
  // Of the simulated clock's cycles (the frame time reported).
  const double clock = succ["intervals"]["simulated_frame_cycles"].get<double>();
  EXPECT_NEAR(share, succ["sampling"]["measured_cycles"].get<double>() / clock, 1e-9);
  EXPECT_NEAR(clock / succ["frame"]["cycles"].get<double>(), 1.0, 0.05);
  // The samples' own frame-time estimate beside the clock: the same frame, within the few
  // percent the clock's fast-forward may be off (docs/sampled-timing.md, "The frame time").
  const double samples = succ["intervals"]["samples_frame_cycles"].get<double>();
  EXPECT_NEAR(samples / clock, 1.0, 0.1);
  for (const char* path : {"frame.cycles", "memory.dram.bytes", "memory.l2.accesses"})
    EXPECT_EQ(succ["intervals"]["replicates"][path].size(), succ["intervals"]["batches"].get<size_t>()) << path;
  EXPECT_NE(jack_log.find("batches (jackknife; "), std::string::npos) << jack_log;
  EXPECT_NE(succ_log.find("batches (successive differences; "), std::string::npos) << succ_log;
  EXPECT_NE(succ_log.find("% of the frame measured)"), std::string::npos) << succ_log;
}

// The frame time is the simulated clock; its own error (the windows' warm-ups and the
// fast-forward's rates, docs/sampled-timing.md, "The frame time") is taken as the larger of its
// disagreement with the samples' estimate and timing.sample_clock_bound, and the interval of the
// frame time, and of the rates that follow from it, includes it. Counts do not depend on the frame time and keep their intervals. On this
// frame (many TPs for few rays: the fast-forward's polls make the two disagree by several
// percent) a 2% target on frame cycles cannot be met, and the summary says the systematic part
// is why, not the period.
TEST(SampledTimingIntervals, TheClocksErrorIsInTheFrameTimesInterval) {
  TempDir dir;
  // The small chip's frame (run_frame), with 4 TMs of 32 TPs.
  const std::string frame =
      " --set tms=4 --set tps_per_tm=32 --set timing.sample_target_error=0.02 --set timing.sample_target_stats=frame.cycles";
  const nlohmann::json lt = run_frame(dir, "strata-pipelines", "lt", "-clock", frame);
  const nlohmann::json j = run_frame(dir, "strata-pipelines", "sampled", "-clock", frame);
  ASSERT_FALSE(lt.is_null() || j.is_null());
  const std::string summary = read_text(dir.path() / "log.txt");
  const auto& iv = j["intervals"];
  const double clock = iv["simulated_frame_cycles"].get<double>();
  const double samples = iv["samples_frame_cycles"].get<double>();
  EXPECT_DOUBLE_EQ(j["frame"]["cycles"].get<double>(), clock);  // the clock is the frame time
  ASSERT_GT(std::fabs(samples / clock - 1), 0.02) << "this frame should show the disagreement; pick another frame";
  const auto& cycles = iv["stats"]["frame"]["cycles"];
  EXPECT_NEAR(cycles["clock_systematic"].get<double>(), std::fabs(samples - clock), 1.0);  // whole cycles
  EXPECT_GT(cycles["half_width"].get<double>(), cycles["clock_systematic"].get<double>());  // plus the spread
  EXPECT_NEAR(iv["frame_time_systematic"].get<double>(), std::fabs(samples - clock) / clock, 1.0 / clock);  // whole cycles
  EXPECT_EQ(j["units"]["intervals.stats.frame.cycles.clock_systematic"], j["units"]["frame.cycles"]);
  // A rate follows the frame time; a count does not.
  EXPECT_GT(iv["stats"]["frame"]["frames_per_second"].value("clock_systematic", 0.0), 0.0);
  EXPECT_FALSE(iv["stats"]["memory"]["l2"]["accesses"].contains("clock_systematic"));
  // LT inside the widened interval.
  EXPECT_LE(std::fabs(lt["frame"]["cycles"].get<double>() - clock), cycles["half_width"].get<double>());
  // The target: missed, and the reason is the systematic part.
  EXPECT_FALSE(iv["target"]["stats"]["frame.cycles"]["met"].get<bool>());
  EXPECT_NE(summary.find("the clock's systematic error alone (frame cycles \u00b1 "), std::string::npos) << summary;
  EXPECT_NE(summary.find("the samples estimate "), std::string::npos) << summary;
  EXPECT_GT(std::fabs(samples / clock - 1), 0.025) << "the disagreement should exceed the default bound here";
  // A bound above the disagreement sets the systematic part instead (both frames are the same run
  // but for the report).
  const nlohmann::json bounded =
      run_frame(dir, "strata-pipelines", "sampled", "-bound", frame + " --set timing.sample_clock_bound=0.3");
  ASSERT_FALSE(bounded.is_null());
  EXPECT_EQ(bounded["frame"]["cycles"], j["frame"]["cycles"]);
  EXPECT_NEAR(bounded["intervals"]["frame_time_systematic"].get<double>(), 0.3, 1.0 / clock);
  EXPECT_NEAR(bounded["intervals"]["stats"]["frame"]["cycles"]["clock_systematic"].get<double>(), 0.3 * clock, 1.0);
  EXPECT_EQ(bounded["intervals"]["stats"]["memory"]["dram"]["bytes"], j["intervals"]["stats"]["memory"]["dram"]["bytes"]);
}

INSTANTIATE_TEST_SUITE_P(Chip, SampledTiming, ::testing::Values("trax", "strata-pipelines"), design_name);

}  // namespace
