// The L2 on its own: a scripted initiator in place of the interconnect, a fixed-latency sink
// in place of DRAM (100 cycles). 512 KB, 16 banks, 64 B lines, hit latency 3.
#include "memory_test_support.h"
#include "model/stats/stat_values.h"

#include "model/memory/l2_cache.h"

namespace strata::memory::test {
namespace {

constexpr Cycle kDram = 100;

struct L2Bench {
  SparseMemory backing;
  L2Cache l2;
  RawInitiator tm{"tm"};
  LatencySink dram{"dram", kDram};
  explicit L2Bench(const L2Config& c) : l2("l2", c, backing) {
    tm.socket.bind(l2.target);
    l2.downstream.bind(dram.socket);
  }
};

// The tests of sets and banks use the plain low-bit interleave, where which lines share a set
// or a bank is easy to see; the hashed default has tests of its own below.
L2Config low_bit_banks() {
  L2Config c;
  c.hash_banks = false;
  return c;
}

TEST(L2Cache, DirectMappedHitMissAndConflictMisses) {
  REQUIRE_FRESH_SYSTEMC();
  L2Config c = low_bit_banks();  // direct-mapped
  L2Bench b(c);
  const uint64_t a = 0x40000, conflicting = a + 512 * 1024;
  std::vector<Sent> r;
  Script s("script", [&] {
    r.push_back(b.tm.load(a, 0, 64));            // miss: DRAM at 3, back at 103
    r.push_back(b.tm.load(a, 200, 64));          // hit: 203
    r.push_back(b.tm.load(conflicting, 300, 64));  // conflict: 403
    r.push_back(b.tm.load(a, 500, 64));          // evicted: 603
  });
  sc_core::sc_start();
  const Cycle expected[] = {103, 203, 403, 603};
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(r[i].done, expected[i]) << i;
  const auto& k = b.l2.counters();
  EXPECT_EQ(k.hits, 1u);
  EXPECT_EQ(k.misses, 3u);
  EXPECT_EQ(k.writebacks, 0u);
  stats::Values v = stats::Values::snapshot(b.l2.stats());
  EXPECT_EQ(v.count("dram_requests"), 3u);
  EXPECT_EQ(v.count("dram_bytes"), 192u);
  EXPECT_NEAR(k.energy_nj, (4 + 3) * 0.524, 1e-12);  // 4 accesses + 3 fills, 512 KB entry
}

TEST(L2Cache, SetAssociativeKeepsConflictingLinesAndEvictsLeastRecentlyUsed) {
  REQUIRE_FRESH_SYSTEMC();
  L2Config c = low_bit_banks();
  c.ways = 4;  // 2048 sets: lines 128 KB apart share a set
  L2Bench b(c);
  const uint64_t stride = 128 * 1024;
  std::vector<Sent> r;
  Script s("script", [&] {
    for (uint64_t i = 0; i < 4; ++i) b.tm.load(i * stride, 10 * i, 64);  // fill the set's 4 ways
    r.push_back(b.tm.load(0, 1000, 64));           // all four still there: hit (and most recent)
    r.push_back(b.tm.load(4 * stride, 1100, 64));  // fifth: evicts way of line 1*stride (LRU)
    r.push_back(b.tm.load(0, 1300, 64));           // hit
    r.push_back(b.tm.load(stride, 1400, 64));      // was evicted: miss
  });
  sc_core::sc_start();
  EXPECT_EQ(r[0].served_by, ServedBy::kL2);
  EXPECT_EQ(r[1].served_by, ServedBy::kSink);
  EXPECT_EQ(r[2].served_by, ServedBy::kL2);
  EXPECT_EQ(r[3].served_by, ServedBy::kSink);
  EXPECT_EQ(b.l2.counters().hits, 2u);
  EXPECT_EQ(b.l2.counters().misses, 6u);
}

TEST(L2Cache, WriteBackAllocatesFullLineStoresAndWritesDirtyVictimsBack) {
  REQUIRE_FRESH_SYSTEMC();
  L2Bench b(low_bit_banks());
  const uint64_t d = 0x8000, conflicting = d + 512 * 1024;
  std::vector<Sent> r;
  Script s("script", [&] {
    r.push_back(b.tm.store(d, 0, 64));            // whole line: allocated dirty, no fetch: 3
    r.push_back(b.tm.load(d + 8, 10, 4));         // hit: 13
    r.push_back(b.tm.load(conflicting, 20, 64));  // evicts dirty d: write-back + fill: 123
    r.push_back(b.tm.store(conflicting + 4, 200, 4));  // partial store hit: dirty, 203
    r.push_back(b.tm.store(d + 4, 300, 4));       // partial store miss: write back, fetch, 403
  });
  sc_core::sc_start();
  const Cycle expected[] = {3, 13, 123, 203, 403};
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(r[i].done, expected[i]) << i;
  ASSERT_EQ(b.dram.seen.size(), 4u);
  EXPECT_EQ(b.dram.seen[0].command, tlm::TLM_WRITE_COMMAND);  // write-back of d
  EXPECT_EQ(b.dram.seen[0].address, d);
  EXPECT_EQ(b.dram.seen[1].command, tlm::TLM_READ_COMMAND);   // fill of conflicting
  EXPECT_EQ(b.dram.seen[2].command, tlm::TLM_WRITE_COMMAND);  // write-back of conflicting
  EXPECT_EQ(b.dram.seen[2].address, conflicting);
  EXPECT_EQ(b.dram.seen[3].command, tlm::TLM_READ_COMMAND);   // fetch for the partial store
  EXPECT_EQ(b.l2.counters().writebacks, 2u);
  EXPECT_EQ(b.l2.counters().fills, 2u);
}

TEST(L2Cache, BankConflictsSerialiseOneAccessPerBankPerCycle) {
  REQUIRE_FRESH_SYSTEMC();
  L2Bench b(low_bit_banks());
  std::vector<Sent> r;
  Script s("script", [&] {
    b.tm.load(0, 0, 64);
    b.tm.load(16 * 64, 0, 64);  // line 16: bank 0 too (16 banks)
    b.tm.load(64, 0, 64);       // line 1: bank 1
    r.push_back(b.tm.load(0, 500, 64));
    r.push_back(b.tm.load(16 * 64, 500, 64));
    r.push_back(b.tm.load(64, 500, 64));
  });
  sc_core::sc_start();
  EXPECT_EQ(r[0].done, 503u);
  EXPECT_EQ(r[1].done, 504u);
  EXPECT_EQ(r[2].done, 503u);
  EXPECT_EQ(b.l2.counters().bank_conflicts, 2u);  // one at warm-up, one here
}

// 16 lines 32 KB apart, the stride of the scene image's treelets, asked for at once: with the
// low-bit interleave all are in bank 0 and queue one per cycle; hashed, each has its own bank.
Cycle last_of_strided_burst(const L2Config& c, uint64_t* conflicts) {
  L2Bench b(c);
  std::vector<Sent> r;
  Script s("script", [&] {
    for (uint64_t i = 0; i < 16; ++i) r.push_back(b.tm.load(i * 32 * 1024, 0, 64));
  });
  sc_core::sc_start();
  *conflicts = b.l2.counters().bank_conflicts;
  Cycle last = 0;
  for (const Sent& x : r) last = std::max(last, x.done);
  return last;
}

TEST(L2Cache, LowBitInterleaveQueuesTreeletStridedLinesOnOneBank) {
  REQUIRE_FRESH_SYSTEMC();
  uint64_t conflicts = 0;
  EXPECT_EQ(last_of_strided_burst(low_bit_banks(), &conflicts), 15u + 3 + kDram);
  EXPECT_EQ(conflicts, 15u);
}

TEST(L2Cache, HashedBanksServeTreeletStridedLinesInParallel) {
  REQUIRE_FRESH_SYSTEMC();
  uint64_t conflicts = 0;
  EXPECT_EQ(last_of_strided_burst(L2Config{}, &conflicts), 3u + kDram);
  EXPECT_EQ(conflicts, 0u);
}

TEST(L2Cache, EnergyPerAccessFollowsTheCactiTableBySize) {
  L2Config c;
  c.size_bytes = 16 * 1024 * 1024;
  EXPECT_DOUBLE_EQ(c.energy_per_access_nj(), 1.61);
  c.size_bytes = 4 * 1024 * 1024;
  EXPECT_DOUBLE_EQ(c.energy_per_access_nj(), 0.901);
  c.access_energy_nj = 0.5;
  EXPECT_DOUBLE_EQ(c.energy_per_access_nj(), 0.5);
  c.access_energy_nj.reset();
  c.size_bytes = 64 * 1024;
  EXPECT_THROW(c.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace strata::memory::test
