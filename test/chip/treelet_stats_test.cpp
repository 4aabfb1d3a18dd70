// The treelet mechanism's statistics (`treelets`) on a small Cornell frame: every ray popped
// was traced in a session of its TM, every L1 data line filled was filled in a session or
// counted outside one, node and triangle sessions add up to the totals, and the rays in
// flight stay within the stream memory's capacity; in every timing mode. TRaX has none.
#include <string>
#include <tuple>

#include "chip_support.h"
#include "model/chip/chip_report.h"

namespace strata::chip::test {
namespace {

using Param = std::tuple<bool, transport::TimingMode>;  // pipelines, mode

ChipConfig frame_chip(bool streams, bool pipelines, transport::TimingMode mode) {
  ChipConfig config = small_chip(mode, 2, 8);
  config.design = design_config(streams ? (pipelines ? "strata-streams-pipelines" : "strata-streams") : "trax-baseline",
                                streams ? PathStatePlacement::kOnChip : PathStatePlacement::kDram);
  config.stream.size_bytes = 512 * 1024;
  if (mode == transport::TimingMode::kSampled) {  // windows small enough for a 32x32 frame
    config.timing.quantum_cycles = 500;
    config.timing.sample_period_cycles = 6000;
    config.timing.sample_detail_cycles = 3000;
    config.timing.sample_warmup_cycles = 1000;
  }
  config.finalize();
  return config;
}

uint64_t sum_of(const stats::Values& group) {
  uint64_t n = 0;
  for (const stats::Values::Stat& s : group.stats()) n += s.u;
  return n;
}

class TreeletStats : public ::testing::TestWithParam<Param> {};

TEST_P(TreeletStats, SessionsAccountForEveryRayAndLine) {
  const bool pipelines = std::get<0>(GetParam());
  const transport::TimingMode mode = std::get<1>(GetParam());
  const ChipConfig config = frame_chip(true, pipelines, mode);
  REQUIRE_KERNEL(kernel_of(config.design));
  SmallFrame frame(scenes::make_cornell({0.2, 1}), 32);
  const sim::PreparedFrame prepared = frame.on(config);
  Chip chip("chip", prepared.config, prepared.inputs);
  sc_core::sc_start();
  ASSERT_TRUE(chip.finished()) << chip.error();

  // The invariants hold between raw counts (sampled timing extrapolates and rounds each
  // statistic apart); the levels are read from the report.
  const stats::Values raw = stats::Values::snapshot(chip.statistics());
  const stats::Values& s = raw.group("treelets.sessions");
  uint64_t rays = 0, lines = 0;
  for (size_t t = 0; t < chip.tms().size(); ++t) {
    const stats::Values& tm = raw.group("treelets.sessions[" + std::to_string(t) + "]");
    EXPECT_GT(tm.count("sessions"), 0u) << "TM " << t;
    EXPECT_EQ(tm.count("rays"), tm.count("rays_popped")) << "TM " << t << ": a ray popped outside a session";
    EXPECT_EQ(sum_of(tm.group("rays_histogram")), tm.count("sessions")) << "TM " << t;
    // Every line the TM's L1 filled (a merged miss fills none) is in a session or outside one.
    EXPECT_EQ(tm.count("lines_filled") + tm.count("lines_outside_sessions"), chip.l1d()[t]->counters().fills)
        << "TM " << t;
    rays += tm.count("rays");
    lines += tm.count("lines_filled") + tm.count("lines_outside_sessions");
  }
  EXPECT_EQ(rays, s.count("rays"));
  EXPECT_EQ(s.count("rays"), raw.count("memory.stream.rays_popped"));
  EXPECT_EQ(sum_of(s.group("rays_histogram")), s.count("sessions"));
  EXPECT_EQ(lines, raw.count("memory.l1d.fills"));
  EXPECT_EQ(s.count("lines_filled"), s.count("lines_l2_hit") + s.count("lines_dram") + s.count("lines_l2_merged"));
  EXPECT_GT(s.count("lines_filled"), 0u);
  EXPECT_LE(s.count("lines_dram"), raw.count("memory.l2.misses"));

  // Node and triangle sessions add up to the totals, and the kernel visits both kinds.
  for (const char* n : {"sessions", "rays", "lines_filled", "lines_l2_hit", "lines_dram", "lines_l2_merged"})
    EXPECT_EQ(s.count(std::string("node.") + n) + s.count(std::string("triangle.") + n), s.count(n)) << n;
  EXPECT_GT(s.count("node.sessions"), 0u);
  EXPECT_GT(s.count("triangle.sessions"), 0u);

  const FrameReport report(chip, 1.0);
  const stats::Values& v = report.values();
  EXPECT_EQ(v.count("treelets.sessions.rays"), v.count("memory.stream.rays_popped"));  // exact in every mode
  EXPECT_GT(v.number("treelets.sessions.rays_per_session"), 0.0);
  EXPECT_GT(v.number("treelets.sessions.lines_per_session"), 0.0);

  const stats::Values& f = v.group("treelets.rays_in_flight");
  EXPECT_EQ(f.count("capacity"), chip.stream().capacity());
  EXPECT_EQ(f.count("capacity"), v.count("memory.stream.capacity"));
  EXPECT_GT(f.number("mean"), 0.0);
  EXPECT_LE(f.number("mean"), f.number("capacity"));
  EXPECT_LE(f.count("peak"), f.count("capacity"));
  EXPECT_GE(f.number("steady_state"), f.number("mean"));
  EXPECT_LE(f.number("steady_state"), double(f.count("peak")));
  EXPECT_LT(f.count("steady_begin_cycle"), f.count("steady_end_cycle"));
  EXPECT_LE(f.count("steady_end_cycle"), v.count("frame.cycles"));
  const stats::Values& b = v.group("treelets.buffers");
  EXPECT_GT(b.number("nonempty_mean"), 0.0);
  EXPECT_LE(b.number("nonempty_mean"), double(b.count("treelets")));
  EXPECT_LE(b.number("stored_mean"), f.number("mean"));
  EXPECT_GE(b.number("rays_per_nonempty_mean"), 1.0);  // a non-empty buffer holds a ray or more
  EXPECT_EQ(b.count("node_treelets"), frame.image.header().node_treelet_count);

  const std::string summary = report.summary();
  EXPECT_NE(summary.find("\ntreelets "), std::string::npos) << summary;
  EXPECT_NE(summary.find("\nrays in flight "), std::string::npos) << summary;
}

std::string param_name(const ::testing::TestParamInfo<Param>& info) {
  const transport::TimingMode mode = std::get<1>(info.param);
  return std::string(std::get<0>(info.param) ? "pipelines_" : "streams_") +
         (mode == transport::TimingMode::kPrecise ? "precise" : mode == transport::TimingMode::kSampled ? "sampled" : "lt");
}

INSTANTIATE_TEST_SUITE_P(Chip, TreeletStats,
                         ::testing::Combine(::testing::Values(false, true),
                                            ::testing::Values(transport::TimingMode::kLooselyTimed,
                                                              transport::TimingMode::kPrecise,
                                                              transport::TimingMode::kSampled)),
                         param_name);

TEST(TreeletStatsTrax, HasNoSessionsAndNoRaysInFlight) {
  REQUIRE_KERNEL("baseline");
  SmallFrame frame(scenes::make_cornell({0.2, 1}), 16);
  const sim::PreparedFrame f = frame.on(frame_chip(false, false, transport::TimingMode::kLooselyTimed));
  Chip chip("chip", f.config, f.inputs);
  sc_core::sc_start();
  ASSERT_TRUE(chip.finished()) << chip.error();
  const FrameReport report(chip, 1.0);
  const stats::Values& v = report.values();
  EXPECT_EQ(v.count("treelets.sessions.sessions"), 0u);
  EXPECT_EQ(v.count("treelets.sessions.rays"), 0u);
  EXPECT_EQ(v.count("treelets.sessions.lines_filled"), 0u);
  EXPECT_EQ(v.count("treelets.sessions.lines_outside_sessions"), 0u);  // the group is the streaming designs'
  EXPECT_GT(v.count("memory.l1d.fills"), 0u);
  EXPECT_EQ(v.number("treelets.rays_in_flight.mean"), 0.0);
  EXPECT_EQ(v.number("treelets.rays_in_flight.steady_state"), 0.0);
  EXPECT_EQ(v.number("treelets.buffers.nonempty_mean"), 0.0);
  EXPECT_EQ(report.summary().find("\ntreelets "), std::string::npos);
}

}  // namespace
}  // namespace strata::chip::test
