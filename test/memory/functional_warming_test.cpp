// Functional warming (sampled timing's fast-forward, docs/sampled-timing.md): a warming request
// changes the tags of the L1 data cache and the L2 as the access would, and nothing else: it
// books no bank, counts nothing, moves no data, and never reaches DRAM. The chain is the real
// one: an L1 above an L2 above a fixed-latency sink in place of DRAM.
#include "memory_test_support.h"
#include "model/stats/stat_values.h"

#include "model/memory/l1_data_cache.h"
#include "model/memory/l2_cache.h"

namespace strata::memory::test {
namespace {

constexpr Cycle kDram = 100;

struct Chain {
  SparseMemory backing;
  L1DataCache l1;
  L2Cache l2;
  RawInitiator tp{"tp"};
  LatencySink dram{"dram", kDram};
  explicit Chain(const L2Config& c2 = {}) : l1("l1d", L1DataCacheConfig{}, backing), l2("l2", c2, backing) {
    tp.socket.bind(l1.target);
    l1.downstream.bind(l2.target);
    l2.downstream.bind(dram.socket);
  }
  // A warming request as the TM replays one (tm_fast_forward.cpp).
  void warm(uint64_t addr, bool store) {
    transport::PooledPayload gp(tp.pool);
    uint32_t scratch = 0xDEADBEEF;
    transport::prepare_access(gp, store ? AccessClass::kDataStore : AccessClass::kDataLoad, addr, &scratch, 4, 0, 0,
                              transport::kNoTreelet, true, true, false);
    gp.ext().warm = true;
    sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
    tp.socket->b_transport(*gp, delay);
    EXPECT_EQ(gp->get_response_status(), tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(delay, sc_core::SC_ZERO_TIME);
  }
};

TEST(FunctionalWarming, AWarmedLineHitsInTheL1AndCountsNothing) {
  REQUIRE_FRESH_SYSTEMC();
  Chain b;
  const uint64_t a = 0x10000;
  std::vector<Sent> r;
  Script s("script", [&] {
    b.warm(a, false);
    r.push_back(b.tp.load(a, 10));       // warm in the L1: a hit at 11
    r.push_back(b.tp.load(a + 64, 20));  // the next line was never warmed: L1 and L2 miss, DRAM
  });
  sc_core::sc_start();
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].served_by, ServedBy::kL1);
  EXPECT_EQ(r[0].done, 11u);
  EXPECT_EQ(r[1].served_by, ServedBy::kSink);
  // Only the two timed loads are counted; DRAM saw only the one real miss.
  EXPECT_EQ(b.l1.counters().accesses, 2u);
  EXPECT_EQ(b.l1.counters().hits, 1u);
  EXPECT_EQ(b.l1.counters().misses, 1u);
  EXPECT_EQ(b.l2.counters().accesses, 1u);
  EXPECT_EQ(b.l2.counters().misses, 1u);
  ASSERT_EQ(b.dram.seen.size(), 1u);
  EXPECT_EQ(b.dram.seen[0].address, a + 64);
  EXPECT_EQ(stats::Values::snapshot(b.l1.stats()).count("downstream_requests"), 1u);
}

TEST(FunctionalWarming, AnL1WarmMissWarmsTheL2Too) {
  REQUIRE_FRESH_SYSTEMC();
  Chain b;
  const uint64_t a = 0x20000, evicts_a_in_l1 = a + 32 * 1024;  // same L1 set (32 KB direct-mapped)
  std::vector<Sent> r;
  Script s("script", [&] {
    b.warm(a, false);               // into the L1 and the L2
    b.warm(evicts_a_in_l1, false);  // takes a's L1 set; both lines stay in the L2
    r.push_back(b.tp.load(a, 10));  // L1 miss, L2 hit: no DRAM
  });
  sc_core::sc_start();
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].served_by, ServedBy::kL2);
  EXPECT_TRUE(b.dram.seen.empty());
  EXPECT_EQ(b.l2.counters().hits, 1u);
  EXPECT_EQ(b.l2.counters().fills, 0u);
}

TEST(FunctionalWarming, AWarmStoreLeavesADirtyL2LineWhoseEvictionIsAWriteBack) {
  REQUIRE_FRESH_SYSTEMC();
  L2Config c;
  c.hash_banks = false;  // direct-mapped, 512 KB: a and a + 512 KB share a set
  Chain b(c);
  const uint64_t a = 0x40000, conflicting = a + 512 * 1024;
  std::vector<Sent> r;
  Script s("script", [&] {
    b.warm(a, true);                           // write-around: the L2 allocates it, dirty
    r.push_back(b.tp.load(conflicting, 10));   // evicts it: a write-back, then the fill
  });
  sc_core::sc_start();
  ASSERT_EQ(r.size(), 1u);
  ASSERT_EQ(b.dram.seen.size(), 2u);
  EXPECT_EQ(b.dram.seen[0].command, tlm::TLM_WRITE_COMMAND);
  EXPECT_EQ(b.dram.seen[0].address, a);
  EXPECT_EQ(b.dram.seen[1].address, conflicting);
  EXPECT_EQ(b.l2.counters().writebacks, 1u);
  // The warm store's data went nowhere: the backing store still holds zeros.
  uint32_t word = 1;
  b.backing.read(a, &word, 4);
  EXPECT_EQ(word, 0u);
}

TEST(FunctionalWarming, AWarmStoreDoesNotAllocateInTheL1) {
  REQUIRE_FRESH_SYSTEMC();
  Chain b;
  const uint64_t a = 0x50000;
  std::vector<Sent> r;
  Script s("script", [&] {
    b.warm(a, true);
    r.push_back(b.tp.load(a, 10));  // the L1 is write-around: a miss there, a hit in the L2
  });
  sc_core::sc_start();
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].served_by, ServedBy::kL2);
  EXPECT_EQ(b.l1.counters().misses, 1u);
  EXPECT_TRUE(b.dram.seen.empty());
}

}  // namespace
}  // namespace strata::memory::test
