// The kernels built as RISC-V firmware and run on the ISS compute exactly what the native twin
// computes: bit-identical images and identical ray statistics. The streaming kernels too, on
// one hart with the functional stream memory (the path order differs, the paths do not).
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "scenes/procedural/procedural.h"
#include "scenes/scene_spec.h"
#include "sim/iss_render.h"

namespace strata::sim {
namespace {

void expect_identical(const scenes::Scene& scene, uint32_t size, const std::string& kernel = "baseline",
                      PathArithmetic arithmetic = PathArithmetic::kExact, uint32_t spp = 1) {
  const std::string elf = default_kernel_elf(kernel);
  ASSERT_TRUE(std::filesystem::exists(elf)) << elf << " was not built";
  const scenes::SceneImage image = build_scene_image(scene, {}, nullptr);
  RenderSettings s;
  s.width = s.height = size;
  s.samples_per_pixel = spp;
  s.path_arithmetic = arithmetic;
  const RenderResult native = render_native(image, s);
  IssRunStats stats;
  // Bounded, so that a kernel that waits forever fails here rather than hanging the suite.
  const RenderResult iss = render_on_iss(image, s, elf, 4'000'000'000ull, &stats);
  ASSERT_EQ(native.image.size(), iss.image.size());
  EXPECT_EQ(std::memcmp(native.image.data(), iss.image.data(), native.image.size() * sizeof(kernels::Pixel)), 0)
      << "firmware image differs from the native twin";
  EXPECT_EQ(std::memcmp(&native.counters, &iss.counters, sizeof native.counters), 0)
      << "firmware ray statistics differ from the native twin";
  EXPECT_EQ(iss.counters.paths, uint64_t(size) * size * spp);
  EXPECT_GT(stats.instructions, iss.total_rays() * 100);  // it really ran the kernel
  EXPECT_GT(stats.counters.fp_reads, 0u);
}

TEST(IssRender, CornellFirmwareImageIsBitIdenticalToTheNativeTwin) {
  expect_identical(scenes::make_cornell({0.3, 1}), 64);
}

// 64x64 is more pixels than the 4,095 paths the stream memory holds at once (one ray's room is
// kept back per thread), so path records are reused as their paths end.
TEST(IssRender, StreamingKernelsOnOneHartMatchTheNativeTwin) {
  expect_identical(scenes::make_cornell({0.3, 1}), 64, "streams");
  expect_identical(scenes::make_cornell({0.3, 1}), 64, "streams_pipelines");
}

// The compact path state: each ray carries its path, packed; the twin computes with the same
// packed arithmetic. Several samples per pixel go through the framebuffer between samples.
TEST(IssRender, CompactStreamingKernelsOnOneHartMatchThePackedTwin) {
  expect_identical(scenes::make_cornell({0.3, 1}), 64, "streams_compact", PathArithmetic::kPacked);
  expect_identical(scenes::make_cornell({0.3, 1}), 64, "streams_pipelines_compact", PathArithmetic::kPacked);
  expect_identical(scenes::make_cornell({0.3, 1}), 16, "streams_compact", PathArithmetic::kPacked, 3);
}

TEST(IssRender, SibenikFirmwareImageIsBitIdenticalToTheNativeTwin) {
  if (!std::filesystem::exists(STRATA_SHARED_DIR "/scenes/sibenik/sibenik.obj"))
    GTEST_SKIP() << "../shared/scenes/sibenik is absent";
  expect_identical(scenes::load_scene("sibenik", STRATA_SOURCE_DIR), 64);
}

TEST(IssRender, AFaultingFirmwareIsReportedWithTheElfName) {
  const std::string elf = default_kernel_elf("baseline");
  ASSERT_TRUE(std::filesystem::exists(elf)) << elf << " was not built";
  const scenes::SceneImage image = build_scene_image(scenes::make_cornell({0.1, 1}), {}, nullptr);
  RenderSettings s;
  s.width = s.height = 8;
  try {
    render_on_iss(image, s, elf, 1000, nullptr);  // far too few instructions
    FAIL() << "an instruction limit was not reported";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("baseline.elf"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace strata::sim
