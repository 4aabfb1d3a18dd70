// DRAM channels on their own: unloaded latency, queueing, interleaving, per-channel counts,
// and saturation at the configured peak bandwidth (256 B/cycle = 256 GB/s at 1 GHz).
#include "memory_test_support.h"
#include "model/stats/stat_values.h"

#include "model/memory/dram.h"

#include <cstdio>
#include <cstring>

#include <set>

namespace strata::memory::test {
namespace {

TEST(Dram, UnloadedLatencyQueueingAndPerChannelCounts) {
  REQUIRE_FRESH_SYSTEMC();
  SparseMemory backing;
  DramConfig plain;
  plain.hash_channels = false;  // the plain interleave, where the channel of each block is easy to see
  Dram dram("dram", plain, backing);  // 8 channels x 32 B/cycle, latency 100, 256 B interleave
  RawInitiator l2("l2");
  l2.socket.bind(dram.target);
  std::vector<Sent> r;
  Script s("script", [&] {
    uint8_t line[128] = {};
    r.push_back(l2.send(AccessClass::kDataLoad, 0, line, 64, 0));      // ch0: data 100..101
    r.push_back(l2.send(AccessClass::kDataLoad, 64, line, 64, 0));     // ch0 again: queued, 104
    r.push_back(l2.send(AccessClass::kDataLoad, 256, line, 64, 0));    // ch1: 102
    r.push_back(l2.send(AccessClass::kDataStore, 512, line, 128, 10)); // ch2: 2 bursts, 110..113
    r.push_back(l2.send(AccessClass::kDataLoad, 8 * 256, line, 64, 0)); // wraps to ch0: 106
  });
  sc_core::sc_start();
  const Cycle expected[] = {102, 104, 102, 114, 106};
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(r[i].done, expected[i]) << i;
    EXPECT_EQ(r[i].served_by, ServedBy::kDram) << i;
  }
  EXPECT_EQ(dram.channel(0).requests, 3u);
  EXPECT_EQ(dram.channel(0).bytes_read, 192u);
  EXPECT_EQ(dram.channel(0).queued_cycles, 2u + 4u);
  EXPECT_EQ(dram.channel(1).bytes_read, 64u);
  EXPECT_EQ(dram.channel(2).accesses, 2u);
  EXPECT_EQ(dram.channel(2).bytes_written, 128u);
  EXPECT_EQ(dram.counters().accesses, 6u);
  EXPECT_NEAR(dram.counters().energy_nj, 6 * 16.3, 1e-9);
  stats::Values v = stats::Values::snapshot(dram.stats());
  v.derive();
  EXPECT_NEAR(v.number("channels[2].energy_nj"), 2 * 16.3, 1e-9);
  EXPECT_EQ(v.count("bytes"), 64u * 4 + 128u);
}

// The default XOR-folds the block index: the first blocks of 32 KB-aligned treelets spread over
// every channel (plain: all in channel 0), and 8 consecutive blocks still use all 8 channels.
TEST(Dram, HashedChannelsSpreadTreeletAlignedBlocks) {
  REQUIRE_FRESH_SYSTEMC();
  SparseMemory backing;
  DramConfig plain;
  plain.hash_channels = false;
  Dram hashed("hashed", DramConfig{}, backing), low("low", plain, backing);
  std::set<uint32_t> treelet_starts;
  for (uint64_t t = 0; t < 8; ++t) {
    EXPECT_EQ(low.channel_of(t * 32 * 1024), 0u);
    treelet_starts.insert(hashed.channel_of(t * 32 * 1024));
  }
  EXPECT_EQ(treelet_starts.size(), 8u);
  for (uint64_t base = 0; base < (64u << 20); base += 8 * 256 * 131) {
    std::set<uint32_t> run;
    for (uint64_t b = 0; b < 8; ++b) run.insert(hashed.channel_of(base + b * 256));
    EXPECT_EQ(run.size(), 8u) << base;
  }
}

TEST(Dram, SaturatesAtConfiguredPeakBandwidthWithinOnePercent) {
  REQUIRE_FRESH_SYSTEMC();
  SparseMemory backing;
  const DramConfig config;  // 256 B/cycle in total
  Dram dram("dram", config, backing);
  RawInitiator port("port");
  port.socket.bind(dram.target);
  // Four decoupled request streams together offer 1.25x the peak (5 lines per cycle). Each
  // stream is sent whole before the next starts, so the DRAM sees requests far out of time
  // order, as under temporal decoupling; the calendars must still pack the bus.
  constexpr uint64_t kStreams = 4, kLines = 40000;
  Cycle last_done = 0;
  uint64_t bytes = 0;
  Script s("script", [&] {
    uint8_t line[64];
    for (uint64_t stream = 0; stream < kStreams; ++stream) {
      for (uint64_t k = stream; k < kLines; k += kStreams) {
        const Sent r = port.send(AccessClass::kDataLoad, k * 64, line, 64, k / 5, transport::kNoTreelet, true);
        last_done = std::max(last_done, r.done);
        bytes += 64;
      }
    }
  });
  sc_core::sc_start();
  // Data starts flowing one unloaded latency after the first request at cycle 0.
  const double busy = static_cast<double>(last_done - config.latency_cycles);
  const double bandwidth = static_cast<double>(bytes) / busy;
  std::printf("DRAM saturation: %.3f B/cycle of 256 configured\n", bandwidth);
  EXPECT_NEAR(bandwidth, 256.0, 2.56) << "bytes per cycle over the busy period";
  EXPECT_EQ(dram.counters().bytes_read, bytes);
  for (uint32_t c = 0; c < config.channels; ++c) EXPECT_EQ(dram.channel(c).bytes_read, bytes / config.channels);
  EXPECT_EQ(dram.overflow_bookings(), 0u);
}

TEST(Dram, BelowSaturationLatencyStaysNearUnloaded) {
  REQUIRE_FRESH_SYSTEMC();
  SparseMemory backing;
  Dram dram("dram", DramConfig{}, backing);
  RawInitiator port("port");
  port.socket.bind(dram.target);
  double total = 0;
  constexpr uint64_t kLines = 20000;
  Script s("script", [&] {
    uint8_t line[64];
    for (uint64_t k = 0; k < kLines; ++k) {  // half the peak: 2 lines per cycle
      const Sent r = port.send(AccessClass::kDataLoad, k * 64, line, 64, k / 2, transport::kNoTreelet, true);
      total += static_cast<double>(r.done - k / 2);
    }
  });
  sc_core::sc_start();
  const double mean = total / kLines;
  EXPECT_GE(mean, 102.0);  // unloaded: 100 + 64 B / 32 B per cycle
  EXPECT_LT(mean, 106.0);  // 4-line bursts into one channel queue a little
}

TEST(Dram, DataGoesToTheSparseBackingStore) {
  REQUIRE_FRESH_SYSTEMC();
  SparseMemory backing;
  Dram dram("dram", DramConfig{}, backing);
  RawInitiator port("port");
  port.socket.bind(dram.target);
  uint8_t out[64], in[64] = {};
  for (int i = 0; i < 64; ++i) out[i] = static_cast<uint8_t>(i * 3);
  Script s("script", [&] {
    port.send(AccessClass::kDataStore, 0xC0000000ull, out, 64, 0);
    port.send(AccessClass::kDataLoad, 0xC0000000ull, in, 64, 200);
    uint8_t timing_only_buf[64] = {};
    port.send(AccessClass::kDataStore, 0x1000, timing_only_buf, 64, 300, transport::kNoTreelet, true);
  });
  sc_core::sc_start();
  EXPECT_EQ(std::memcmp(in, out, 64), 0);
  EXPECT_EQ(backing.resident_pages(), 1u);  // the timing-only store touched nothing
}

}  // namespace
}  // namespace strata::memory::test
