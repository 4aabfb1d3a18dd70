// What loosely timed (LT) and precise mode must send in time order, and what that buys
// (docs/memory-system.md, "Where LT differs: cache state"):
//   - no TP of a TM falls behind global time, whatever the quantum and the TP slack: a request
//     for a cycle before global time would be moved to it by every calendar;
//   - precise mode sends every TP's request when global time reaches its cycle, even one that
//     waited for its operands, so the L1 sees its lookups in time order;
//   - stream and global-register operations reach the shared state in time order in LT too
//     (timing.sync_shared_ops), so the treelet schedule, and with it the L1 misses, is that of
//     precise mode.
#include <cmath>
#include <cstdio>

#include "chip_support.h"
#include "model/chip/chip_report.h"

namespace strata::chip::test {
namespace {

// A streaming design on `tms` TMs of 8 TPs, for the tests that need several TMs to share
// treelet buffers.
ChipConfig streams_chip(transport::TimingMode mode, uint32_t tms) {
  ChipConfig config = small_chip(mode, tms, 8);
  config.design = design_config("strata-streams-pipelines", PathStatePlacement::kOnChip);
  config.stream.size_bytes = 512 * 1024;
  config.finalize();
  return config;
}

TEST(TimingOrder, ATpSlackAboveTheQuantumKeepsLtWithinOnePercentOfPrecise) {
  // Quantum 1 with the default TP slack of 32: a TP runs up to 32 cycles past the other TPs
  // of its TM, and the TM waits for global time whenever it leads by a cycle. Before the
  // wait stopped at the TM's earliest TP, global time overtook the other TPs, every calendar
  // moved their requests to global time, and the frame took 3x precise's cycles.
  REQUIRE_KERNEL("baseline");
  const SmallFrame frame(scenes::make_cornell({0.2, 1}), 12);
  ChipConfig lt_config = small_chip(transport::TimingMode::kLooselyTimed);
  lt_config.timing.quantum_cycles = 1;
  lt_config.finalize();
  ASSERT_EQ(lt_config.timing.tp_slack_cycles, 32u);
  const sim::PreparedFrame lt_frame = frame.on(lt_config);
  Chip lt("lt", lt_frame.config, lt_frame.inputs);
  const sim::PreparedFrame precise_frame = frame.on(small_chip(transport::TimingMode::kPrecise));
  Chip precise("precise", precise_frame.config, precise_frame.inputs);
  sc_core::sc_start();
  ASSERT_TRUE(lt.finished()) << lt.error();
  ASSERT_TRUE(precise.finished()) << precise.error();
  const nlohmann::json a = chip_report(lt, 1.0), b = chip_report(precise, 1.0);
  EXPECT_NEAR(a["frame"]["cycles"].get<double>() / b["frame"]["cycles"].get<double>(), 1.0, 0.01);
}

TEST(TimingOrder, PreciseModeSendsEveryTpRequestInTimeOrder) {
  // A load whose address comes from a load still in flight issues when that data arrives.
  // Sent at the cycle the TP was stepped, it reached the L1 ahead of the other TPs'
  // lookups of the cycles in between, and the L1 had to correct it (reordered > 0).
  REQUIRE_KERNEL("streams_pipelines");
  const SmallFrame frame(scenes::make_cornell({1.0, 1}), 32);
  const sim::PreparedFrame f = frame.on(streams_chip(transport::TimingMode::kPrecise, 4));
  Chip chip("precise", f.config, f.inputs);
  sc_core::sc_start();
  ASSERT_TRUE(chip.finished()) << chip.error();
  const nlohmann::json r = chip_report(chip, 1.0);
  EXPECT_GT(r["memory"]["l1d"]["accesses"].get<uint64_t>(), 100000u);
  EXPECT_EQ(r["memory"]["l1d"]["reordered"], 0);
  // What is left are the L2's: an L1 sends its miss below at its own answer cycle, a cycle
  // or two ahead of global time.
  expect_sentinels_quiet(r, transport::TimingMode::kPrecise);
}

TEST(TimingOrder, StreamOperationsInTimeOrderKeepLtL1MissesWithPrecise) {
  // With stream operations in arrival order, a TM a quantum ahead drained the fullest
  // buffer before the other TMs asked for it: they spread over treelets instead of sharing
  // it, switched treelets less, and LT missed less in the L1 than precise.
  REQUIRE_KERNEL("streams_pipelines");
  const SmallFrame frame(scenes::make_cornell({1.0, 1}), 32);
  const ChipConfig synced = streams_chip(transport::TimingMode::kLooselyTimed, 4);
  ASSERT_TRUE(synced.timing.sync_shared_ops);
  ChipConfig arrival = synced;
  arrival.timing.sync_shared_ops = false;
  const sim::PreparedFrame lt_frame = frame.on(synced);
  Chip lt("lt", lt_frame.config, lt_frame.inputs);
  const sim::PreparedFrame lt_arrival_frame = frame.on(arrival);
  Chip lt_arrival("lt_arrival", lt_arrival_frame.config, lt_arrival_frame.inputs);
  const sim::PreparedFrame precise_frame = frame.on(streams_chip(transport::TimingMode::kPrecise, 4));
  Chip precise("precise", precise_frame.config, precise_frame.inputs);
  sc_core::sc_start();
  for (const Chip* c : {&lt, &lt_arrival, &precise}) ASSERT_TRUE(c->finished()) << c->error();
  const nlohmann::json a = chip_report(lt, 1.0), o = chip_report(lt_arrival, 1.0), b = chip_report(precise, 1.0);
  EXPECT_EQ(a["rays"], b["rays"]);
  const auto misses = [](const nlohmann::json& r) { return r["memory"]["l1d"]["misses"].get<double>(); };
  const double error_synced = misses(a) / misses(b) - 1.0, error_arrival = misses(o) / misses(b) - 1.0;
  std::printf("L1 misses against precise: %+.2f%% in time order, %+.2f%% in arrival order\n", 100 * error_synced,
              100 * error_arrival);
  // On a frame this small the LT error moves with the ray set: on this chip, Cornell 32x32 with
  // seeds 1-4 gave -3.9%, -0.4%, -1.8% and -1.2% in time order against -10.5%, -6.3%, -7.2% and
  // -6.7% in arrival order (issue 34, after the counter-based random numbers moved the rays).
  // So: within the spread in time order, and arrival order clearly further below precise.
  EXPECT_LT(std::abs(error_synced), 0.04);
  EXPECT_LT(error_arrival, -0.03);
  EXPECT_LT(error_arrival, error_synced - 0.02);
  EXPECT_NEAR(a["frame"]["cycles"].get<double>() / b["frame"]["cycles"].get<double>(), 1.0, 0.03);
}

}  // namespace
}  // namespace strata::chip::test
