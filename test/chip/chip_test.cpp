// The whole chip running the baseline firmware on 2 TMs, in both timing modes at once: both
// must finish with the native twin's image and ray statistics, and agree with each other.
#include <cstring>

#include "chip_support.h"
#include "model/chip/chip_report.h"

namespace strata::chip::test {
namespace {

TEST(Chip, BaselineFirmwareOnTwoTmsMatchesTheTwinInBothTimingModes) {
  REQUIRE_KERNEL("baseline");
  const SmallFrame frame(scenes::make_cornell({0.2, 1}), 12);
  const sim::PreparedFrame lt_frame = frame.on(small_chip(transport::TimingMode::kLooselyTimed));
  const sim::PreparedFrame precise_frame = frame.on(small_chip(transport::TimingMode::kPrecise));
  Chip lt("lt", lt_frame.config, lt_frame.inputs);
  Chip precise("precise", precise_frame.config, precise_frame.inputs);
  sc_core::sc_start();
  ASSERT_TRUE(lt.finished()) << lt.error();
  ASSERT_TRUE(precise.finished()) << precise.error();

  const sim::RenderResult twin = sim::render_native(frame.image, frame.settings);
  for (const Chip* chip : {&lt, &precise}) {
    const std::vector<kernels::Pixel> image = chip->framebuffer();
    EXPECT_EQ(std::memcmp(image.data(), twin.image.data(), image.size() * sizeof(kernels::Pixel)), 0)
        << chip->name() << ": image differs from the native twin";
    const kernels::RayCounters rays = chip->ray_counters();
    EXPECT_EQ(std::memcmp(&rays, &twin.counters, sizeof rays), 0) << chip->name() << ": ray statistics differ";
    // Every thread took part: the pixel counter handed out work to all 16 TPs.
    int busy_threads = 0;
    for (const kernels::RayCounters& c : chip->ray_counters_per_thread()) busy_threads += c.paths > 0;
    EXPECT_EQ(busy_threads, 16) << chip->name();
  }

  const nlohmann::json a = chip_report(lt, 1.0), b = chip_report(precise, 1.0);
  expect_sentinels_quiet(a, transport::TimingMode::kLooselyTimed);
  expect_sentinels_quiet(b, transport::TimingMode::kPrecise);
  expect_by_data_sums_to_totals(b);
  EXPECT_EQ(a["timing"]["mode"], "loosely-timed");
  EXPECT_EQ(b["timing"]["mode"], "precise");
  // Functional results do not depend on timing: same instructions, same rays.
  EXPECT_EQ(a["instructions"]["retired"], b["instructions"]["retired"]);
  EXPECT_EQ(a["rays"], b["rays"]);
  EXPECT_GT(a["instructions"]["retired"].get<uint64_t>(), 100000u);
  // Timing may differ only through the order decoupled TMs reach shared resources. Stated
  // bounds: cycles within 2%, L1 hit rate within 1 point, DRAM bytes within 5%.
  const double ca = a["frame"]["cycles"].get<double>(), cb = b["frame"]["cycles"].get<double>();
  EXPECT_NEAR(ca / cb, 1.0, 0.02);
  EXPECT_NEAR(a["memory"]["l1d"]["hit_rate"].get<double>(), b["memory"]["l1d"]["hit_rate"].get<double>(), 0.01);
  EXPECT_NEAR(a["memory"]["dram"]["bytes"].get<double>() / b["memory"]["dram"]["bytes"].get<double>(), 1.0, 0.05);
  // Sanity of the statistics themselves.
  EXPECT_GT(cb, 1000.0);
  EXPECT_GT(b["memory"]["l1d"]["hits"].get<uint64_t>(), 0u);
  EXPECT_GT(b["memory"]["dram"]["bytes"].get<uint64_t>(), 0u);
  EXPECT_GT(b["energy_nj"]["register_file"].get<double>(), 0.0);
  EXPECT_GT(b["energy_nj"]["instruction_fetch"].get<double>(), 0.0);
  const double parts = b["energy_nj"]["l1_data"].get<double>() + b["energy_nj"]["l2_and_stream"].get<double>() +
                       b["energy_nj"]["dram"].get<double>() + b["energy_nj"]["instruction_fetch"].get<double>() +
                       b["energy_nj"]["register_file"].get<double>() + b["energy_nj"]["xu"].get<double>();
  EXPECT_NEAR(parts, b["energy_nj"]["total"].get<double>(), 1e-6 * parts);
  // Register-file energy is exactly accesses x the configured energy per access.
  const auto& rf = b["instructions"]["register_file"];
  const double rf_accesses = rf["int_reads"].get<double>() + rf["int_writes"].get<double>() +
                             rf["fp_reads"].get<double>() + rf["fp_writes"].get<double>();
  EXPECT_NEAR(b["energy_nj"]["register_file"].get<double>(), rf_accesses * 0.008, 1e-6 * rf_accesses);
}

TEST(Chip, AFirmwareFaultIsReportedWithTheTmTpAndPc) {
  REQUIRE_KERNEL("baseline");
  SmallFrame frame(scenes::make_cornell({0.2, 1}), 4);
  ChipConfig config = small_chip(transport::TimingMode::kLooselyTimed, 1, 2);
  config.tp_stack_bytes = 256;  // far too small for the kernel's frames
  const sim::PreparedFrame f = frame.on(config);
  Chip chip("chip", f.config, f.inputs);
  sc_core::sc_start();
  EXPECT_FALSE(chip.finished());
  EXPECT_NE(chip.error().find("TM 0, TP"), std::string::npos) << chip.error();
  EXPECT_NE(chip.error().find("stack"), std::string::npos) << chip.error();
}

TEST(Chip, McycleCountsTheTpsCyclesNotItsInstructions) {
  SmallFrame frame(scenes::make_cornell({0.2, 1}), 4);
  const sim::PreparedFrame f =
      frame.on(small_chip(transport::TimingMode::kPrecise, 1, 1), std::string(STRATA_ISS_FIRMWARE_DIR) + "/mcycle.elf");
  Chip chip("chip", f.config, f.inputs);
  sc_core::sc_start();
  ASSERT_TRUE(chip.finished()) << chip.error();
  const kernels::RayCounters c = chip.ray_counters_per_thread()[0];
  ASSERT_EQ(c.rays[2], 1u) << "the divides went wrong";
  const uint64_t mcycle = c.rays[0], minstret = c.rays[1];
  EXPECT_GT(minstret, 64u * 3);
  // 64 dependent divides of latency 16 (docs/tm-timing.md): at least 15 waiting cycles each.
  EXPECT_GE(mcycle, minstret + 64 * 15);
  EXPECT_LE(mcycle, chip.cycles());
}

}  // namespace
}  // namespace strata::chip::test
