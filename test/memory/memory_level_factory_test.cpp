// The shared levels made through their interfaces (model/memory/memory_levels.h): the factory
// makes the model each config names, its statistics meet its level's contract, and the chip's
// wiring (target, downstream) goes through the interface alone.
#include <gtest/gtest.h>

#include <string>

#include "model/memory/dram.h"
#include "model/memory/memory_level_factory.h"

namespace strata::memory {
namespace {

bool lists(const std::vector<stats::Requirement>& contract, const std::string& path) {
  for (const stats::Requirement& r : contract)
    if (path == r.path) return true;
  return false;
}

TEST(MemoryLevelFactory, MakesTheDramModelTheConfigNamesWithItsContract) {
  SparseMemory backing;
  DramConfig channel;
  DramConfig banked;
  banked.model = DramModel::kBanked;
  const std::unique_ptr<DramLevel> a = make_dram_level("dram_channel", channel, backing);
  const std::unique_ptr<DramLevel> b = make_dram_level("dram_banked", banked, backing);
  // Both are the Dram module; the banked one times its requests with BankedDram.
  const auto* da = dynamic_cast<const Dram*>(a.get());
  const auto* db = dynamic_cast<const Dram*>(b.get());
  ASSERT_NE(da, nullptr);
  ASSERT_NE(db, nullptr);
  EXPECT_EQ(da->banked(), nullptr);
  EXPECT_NE(db->banked(), nullptr);
  // What the chip reads of a DRAM is there (the factory checked it; this checks the list).
  EXPECT_NO_THROW(stats::require_stats(a->stats(), "channel", DramLevel::contract()));
  EXPECT_NO_THROW(stats::require_stats(b->stats(), "banked", DramLevel::contract()));
  for (const char* path : {"bytes", "energy_nj", "calendar_overflow_bookings", "by_data"})
    EXPECT_TRUE(lists(DramLevel::contract(), path)) << path;
}

TEST(MemoryLevelFactory, TheL2AndTheStreamMemoryMeetTheirContractsAndWireThroughTheInterface) {
  SparseMemory backing;
  const std::unique_ptr<L2Level> l2 = make_l2_level("l2", L2Config{}, backing);
  const std::unique_ptr<DramLevel> dram = make_dram_level("dram", DramConfig{}, backing);
  const std::unique_ptr<StreamLevel> stream = make_stream_level("stream", StreamMemoryConfig{});
  l2->downstream_socket().bind(dram->target_socket());
  EXPECT_EQ(stream->stored(), 0u);
  EXPECT_GT(stream->capacity(), 0u);
  for (const char* path : {"accesses", "reordered", "energy_nj", "calendar_overflow_bookings", "by_data"})
    EXPECT_TRUE(lists(L2Level::contract(), path)) << path;
  for (const char* path : {"accesses", "capacity", "sram_bytes_per_ray", "energy_nj", "by_data"})
    EXPECT_TRUE(lists(StreamLevel::contract(), path)) << path;
}

}  // namespace
}  // namespace strata::memory
