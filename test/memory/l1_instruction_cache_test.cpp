// The L1 instruction cache on its own, with misses modelled and not.
#include "memory_test_support.h"

#include "model/memory/l1_instruction_cache.h"

namespace strata::memory::test {
namespace {

struct ICacheBench {
  SparseMemory backing;
  L1InstructionCache icache;
  RawInitiator tp{"tp"};
  LatencySink below{"below", 10};
  explicit ICacheBench(const L1InstructionCacheConfig& c) : icache("l1i", c, backing) {
    tp.socket.bind(icache.target);
    icache.downstream.bind(below.socket);
  }
};

TEST(L1InstructionCache, WithoutMissModelEveryFetchHitsInOneCycle) {
  REQUIRE_FRESH_SYSTEMC();
  L1InstructionCacheConfig c;
  c.model_misses = false;
  ICacheBench b(c);
  std::vector<Sent> r;
  Script s("script", [&] {
    for (Cycle i = 0; i < 100; ++i) r.push_back(b.tp.fetch(0x1000 + 4 * i, i * 10));
  });
  sc_core::sc_start();
  for (Cycle i = 0; i < 100; ++i) EXPECT_EQ(r[i].done, i * 10 + 1);
  EXPECT_EQ(b.icache.counters().hits, 100u);
  EXPECT_EQ(b.icache.counters().misses, 0u);
  EXPECT_TRUE(b.below.seen.empty());
  EXPECT_NEAR(b.icache.counters().energy_nj, 100 * 0.014, 1e-12);
}

TEST(L1InstructionCache, MissesFillLinesAndBanksConflict) {
  REQUIRE_FRESH_SYSTEMC();
  L1InstructionCacheConfig c;  // 4 KB, 4 banks, 64 B lines
  ICacheBench b(c);
  std::vector<Sent> r;
  Script s("script", [&] {
    r.push_back(b.tp.fetch(0x0, 0));          // miss: asked at 1, back at 11
    r.push_back(b.tp.fetch(0x4, 20));         // hit: 21
    r.push_back(b.tp.fetch(0x1000, 30));      // 4 KB away: same set, conflict miss -> 41
    r.push_back(b.tp.fetch(0x0, 50));         // evicted: miss again -> 61
    r.push_back(b.tp.fetch(0x40, 100));       // bank 1, miss -> 111
    r.push_back(b.tp.fetch(0x4, 200));        // bank 0 hit at 200 -> 201
    r.push_back(b.tp.fetch(0x100, 200));      // bank 0 again (line 4): waits -> miss asked at 202 -> 212
  });
  sc_core::sc_start();
  const Cycle expected[] = {11, 21, 41, 61, 111, 201, 212};
  for (std::size_t i = 0; i < 7; ++i) EXPECT_EQ(r[i].done, expected[i]) << i;
  const auto& k = b.icache.counters();
  EXPECT_EQ(k.accesses, 7u);
  EXPECT_EQ(k.hits, 2u);
  EXPECT_EQ(k.misses, 5u);
  EXPECT_EQ(k.bank_conflicts, 1u);
  EXPECT_NEAR(k.energy_nj, (7 + 5) * 0.014, 1e-12);
}

TEST(L1InstructionCache, RejectsStores) {
  REQUIRE_FRESH_SYSTEMC();
  ICacheBench b(L1InstructionCacheConfig{});
  Sent r;
  Script s("script", [&] { r = b.tp.store(0, 0); });
  sc_core::sc_start();
  EXPECT_EQ(r.response, tlm::TLM_COMMAND_ERROR_RESPONSE);
}

}  // namespace
}  // namespace strata::memory::test
