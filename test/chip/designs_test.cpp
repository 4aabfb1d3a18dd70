// The three designs (TRaX baseline, STRaTA streams, STRaTA streams + pipelines), the STRaTA
// ones with each path-state placement (compact, on-chip records, DRAM records), rendering a
// frame on a small chip, in both timing modes, on Cornell and on a small Sibenik view: the
// image and the ray statistics equal the native twin's (with the design's path arithmetic),
// every ray generated was completed, and no ray is left in the stream memory.
#include <cstring>
#include <tuple>

#include "chip_support.h"
#include "model/chip/chip_report.h"
#include "scenes/scene_spec.h"

namespace strata::chip::test {
namespace {

// Each design with each path state, and the kernel it must run (design.h's kernel_of).
struct Case {
  const char* label;
  const char* design;
  PathStatePlacement path_state;
  const char* kernel;
};
const Case kCases[] = {{"trax", "trax-baseline", PathStatePlacement::kDram, "baseline"},
                       {"streams_compact", "strata-streams", PathStatePlacement::kCompact, "streams_compact"},
                       {"streams", "strata-streams", PathStatePlacement::kOnChip, "streams"},
                       {"streams_pathdram", "strata-streams", PathStatePlacement::kDram, "streams"},
                       {"pipelines_compact", "strata-streams-pipelines", PathStatePlacement::kCompact,
                        "streams_pipelines_compact"},
                       {"pipelines", "strata-streams-pipelines", PathStatePlacement::kOnChip, "streams_pipelines"},
                       {"pipelines_pathdram", "strata-streams-pipelines", PathStatePlacement::kDram,
                        "streams_pipelines"}};

using Param = std::tuple<int, transport::TimingMode, const char*>;

class Designs : public ::testing::TestWithParam<Param> {};

TEST_P(Designs, FrameMatchesTheNativeTwinAndConservesRays) {
  const Case& c = kCases[std::get<0>(GetParam())];
  const DesignConfig d = design_config(c.design, c.path_state);
  const transport::TimingMode mode = std::get<1>(GetParam());
  const std::string scene_name = std::get<2>(GetParam());
  REQUIRE_KERNEL(c.kernel);
  scenes::Scene scene;
  if (scene_name == "sibenik") {
    if (!std::filesystem::exists(STRATA_SHARED_DIR "/scenes/sibenik/sibenik.obj"))
      GTEST_SKIP() << "../shared/scenes/sibenik is absent";
    scene = scenes::load_scene("sibenik", STRATA_SOURCE_DIR);
  } else {
    scene = scenes::make_cornell({0.2, 1});
  }
  SmallFrame frame(scene, 32);
  const sim::PreparedFrame f = frame.on(small_design_chip(mode, d));
  EXPECT_EQ(f.kernel, c.kernel);
  Chip chip("chip", f.config, f.inputs);
  sc_core::sc_start();
  ASSERT_TRUE(chip.finished()) << chip.error();

  expect_equals_native_twin(chip, frame, d.path_state);
  const kernels::RayCounters rays = chip.ray_counters();
  EXPECT_EQ(rays.paths, 32u * 32u);

  const nlohmann::json r = chip_report(chip, 1.0);
  expect_by_data_sums_to_totals(r);
  expect_sentinels_quiet(r, mode);
  if (d.streams) {
    // Conservation: every ray stored in the stream memory was popped again, none is left.
    EXPECT_EQ(chip.stream().stored(), 0u);
    const auto& s = r["memory"]["stream"];
    const uint64_t stored = s["pushes"].get<uint64_t>() - s["full_rejections"].get<uint64_t>();
    const uint64_t popped = s["pops"].get<uint64_t>() - s["empty_pops"].get<uint64_t>();
    EXPECT_EQ(stored, popped);
    // Every ray generated went through the stream memory at least once.
    EXPECT_GE(stored, rays.rays[0] + rays.rays[1] + rays.rays[2]);
    // Path state lives where the design says, and nowhere else.
    const uint64_t on_chip = s["by_data"]["path_state"]["accesses"].get<uint64_t>();
    uint64_t off_chip = 0;
    for (const char* level : {"l1d", "l2", "dram"})
      off_chip += r["memory"][level]["by_data"]["path_state"]["accesses"].get<uint64_t>();
    if (d.path_state == PathStatePlacement::kOnChip) {
      EXPECT_GT(on_chip, 0u);
      EXPECT_EQ(on_chip, s["path_reads"].get<uint64_t>() + s["path_writes"].get<uint64_t>());
      EXPECT_EQ(off_chip, 0u) << "path state reached the L1, L2 or DRAM";
      EXPECT_EQ(s["path_record_bytes"], kernels::kPathRecordBytes);
      EXPECT_EQ(s["ray_bytes"], 48);
    } else if (d.path_state == PathStatePlacement::kCompact) {
      EXPECT_EQ(on_chip, 0u);
      EXPECT_EQ(off_chip, 0u) << "the compact path state lives in the rays alone";
      EXPECT_EQ(s["path_record_bytes"], 0);
      EXPECT_EQ(s["ray_bytes"], 64);
      EXPECT_EQ(s["sram_bytes_per_ray"], 68);
    } else {
      EXPECT_EQ(on_chip, 0u);
      EXPECT_GT(off_chip, 0u);
      EXPECT_EQ(s["path_record_bytes"], 0);
    }
  } else {
    EXPECT_EQ(r["memory"]["stream"]["pushes"], 0);
  }
  if (d.pipelines) {
    EXPECT_GT(r["xu"]["box_tests"].get<uint64_t>(), rays.node_visits);  // two children per visit, mostly
    EXPECT_GE(r["xu"]["triangle_tests"].get<uint64_t>(), rays.triangle_tests);
    EXPECT_GT(r["xu"]["reconfigurations"].get<uint64_t>(), 0u);
  } else {
    EXPECT_EQ(r["xu"]["box_tests"], 0);
    EXPECT_EQ(r["xu"]["triangle_tests"], 0);
  }
}

std::string param_name(const ::testing::TestParamInfo<Param>& info) {
  return std::string(kCases[std::get<0>(info.param)].label) + "_" +
         (std::get<1>(info.param) == transport::TimingMode::kPrecise ? "precise" : "lt") + "_" +
         std::get<2>(info.param);
}

INSTANTIATE_TEST_SUITE_P(Chip, Designs,
                         ::testing::Combine(::testing::Values(0, 1, 2, 3, 4, 5, 6),
                                            ::testing::Values(transport::TimingMode::kLooselyTimed,
                                                              transport::TimingMode::kPrecise),
                                            ::testing::Values("cornell", "sibenik")),
                         param_name);

}  // namespace
}  // namespace strata::chip::test
