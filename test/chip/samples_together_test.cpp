// The compact path state at more than one sample per pixel: a pixel's samples are separate
// paths in flight together, each writes its radiance to its own slot, and the pixels are summed
// from the slots in sample order once every sample is done. So a small frame with many samples
// fills the stream memory beyond its pixel count, and the image still equals the native twin's
// bit for bit, in every timing mode.
#include <cstring>
#include <tuple>

#include "chip_support.h"
#include "model/chip/chip_report.h"
#include "model/chip/guest_layout.h"

namespace strata::chip::test {
namespace {

const char* const kDesigns[] = {"strata-streams", "strata-streams-pipelines"};  // compact path state

using Param = std::tuple<int, transport::TimingMode>;
class SamplesTogether : public ::testing::TestWithParam<Param> {};

TEST_P(SamplesTogether, ManySamplesOfAPixelAreInFlightAndTheImageIsTheTwins) {
  const DesignConfig design = design_config(kDesigns[std::get<0>(GetParam())], PathStatePlacement::kCompact);
  const transport::TimingMode mode = std::get<1>(GetParam());
  REQUIRE_KERNEL(kernel_of(design));
  constexpr uint32_t kSize = 8, kSpp = 8, kPixels = kSize * kSize;
  SmallFrame frame(scenes::make_cornell({0.2, 1}), kSize);
  frame.settings.samples_per_pixel = kSpp;
  const sim::PreparedFrame f = frame.on(small_design_chip(mode, design));
  Chip chip("chip", f.config, f.inputs);
  sc_core::sc_start();
  ASSERT_TRUE(chip.finished()) << chip.error();
  ASSERT_TRUE(chip.samples_together());
  EXPECT_EQ(chip.work_items(), uint64_t{kPixels} * kSpp);
  EXPECT_EQ(chip.pixels_done(), kPixels);

  expect_equals_native_twin(chip, frame, PathStatePlacement::kCompact);
  const kernels::RayCounters rays = chip.ray_counters();
  EXPECT_EQ(rays.paths, uint64_t{kPixels} * kSpp);

  const nlohmann::json r = chip_report(chip, 1.0);
  EXPECT_EQ(chip.stream().stored(), 0u);
  // More paths than pixels at once: with one sample of a pixel at a time, the peak would be at
  // most the 64 pixels' rays (one ray per path in flight).
  const auto& flight = r["treelets"]["rays_in_flight"];
  EXPECT_GT(flight["peak"].get<uint64_t>(), 4u * kPixels);
  EXPECT_LE(flight["peak"].get<uint64_t>(), uint64_t{kPixels} * kSpp + f.config.threads());
  if (mode == transport::TimingMode::kSampled) return;  // the traffic below is estimated there
  expect_by_data_sums_to_totals(r);
  // Each sample's slot is written once and read once by the resolve, each pixel written once:
  // framebuffer traffic at the L1 covers at least the slots' bytes both ways.
  const uint64_t fb_bytes = r["memory"]["l1d"]["by_data"]["framebuffer"]["bytes"].get<uint64_t>();
  EXPECT_GE(fb_bytes, 2u * kPixels * kSpp * sizeof(kernels::Pixel));
}

std::string param_name(const ::testing::TestParamInfo<Param>& info) {
  const transport::TimingMode mode = std::get<1>(info.param);
  const char* m = mode == transport::TimingMode::kPrecise ? "precise" : mode == transport::TimingMode::kSampled ? "sampled" : "lt";
  return kernel_of(design_config(kDesigns[std::get<0>(info.param)])) + "_" + m;
}

INSTANTIATE_TEST_SUITE_P(Chip, SamplesTogether,
                         ::testing::Combine(::testing::Values(0, 1),
                                            ::testing::Values(transport::TimingMode::kLooselyTimed,
                                                              transport::TimingMode::kPrecise,
                                                              transport::TimingMode::kSampled)),
                         param_name);

// One sample per pixel needs no slots (the sample is the pixel); the record path states sum
// their pixel's samples in the record and never get any.
TEST(SampleSlots, OnlyWhenAPixelHasMoreThanOneSample) {
  EXPECT_EQ(sample_slots_for(100, 1), 0u);
  EXPECT_EQ(sample_slots_for(100, 3), 300u);
  FrameFootprint f;
  f.scene_image_bytes = 4096;
  f.pixels = 100;
  const GuestLayout none = plan_frame_layout(0x10000, f);
  EXPECT_EQ(none.sample_slots, 0u);
  EXPECT_EQ(boot_block(none).sample_slots, 0u);
  f.sample_slots = sample_slots_for(100, 3);
  const GuestLayout some = plan_frame_layout(0x10000, f);
  EXPECT_GE(some.sample_slots, some.framebuffer + 100 * sizeof(kernels::Pixel));
  EXPECT_GE(some.counters, some.sample_slots + 300 * sizeof(kernels::Pixel));
  EXPECT_EQ(boot_block(some).sample_slots, some.sample_slots);
  // The slots are framebuffer data in the traffic statistics.
  SceneImageHeader h{};
  const transport::DataClassMap m = data_class_map(some, h);
  EXPECT_EQ(m.of(some.sample_slots + 16), transport::DataClass::kFramebuffer);
  // Too many samples for the 32-bit guest: the error says the slots are why.
  f.pixels = 1024 * 1024;
  f.sample_slots = sample_slots_for(f.pixels, 400);
  try {
    plan_frame_layout(0x10000, f);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("per-sample slots"), std::string::npos) << e.what();
  }
}

TEST(PathsInFlight, BoundByTheStreamMemoryOrByTheFramesWorkItems) {
  EXPECT_EQ(paths_in_flight_for(10000, 100, 64), 64u);            // 64 pixels, one sample each
  EXPECT_EQ(paths_in_flight_for(10000, 100, 64 * 64), 4096u);     // their samples, together
  EXPECT_EQ(paths_in_flight_for(10000, 100, 1u << 20), 9900u);    // the stream memory, less a ray per thread
  EXPECT_EQ(paths_in_flight_for(10000, 100, uint64_t{1} << 40), 9900u);
}

}  // namespace
}  // namespace strata::chip::test
