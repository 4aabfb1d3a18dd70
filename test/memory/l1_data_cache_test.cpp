// The L1 data cache on its own: a scripted initiator above, a fixed-latency sink below.
// Geometry: 32 KB, 8 banks, 64 B lines, hit latency 1; the sink answers after 20 cycles.
#include "memory_test_support.h"
#include "model/stats/stat_values.h"

#include "model/memory/l1_data_cache.h"

#include <cstring>

namespace strata::memory::test {
namespace {

constexpr Cycle kBelow = 20;

struct L1Bench {
  SparseMemory backing;
  L1DataCacheConfig config;
  L1DataCache l1;
  RawInitiator tp{"tp"};
  LatencySink below{"below", kBelow};

  explicit L1Bench(const L1DataCacheConfig& c = {}) : config(c), l1("l1d", c, backing) {
    tp.socket.bind(l1.target);
    l1.downstream.bind(below.socket);
  }
};

TEST(L1DataCache, DirectMappedHitMissAndConflictMissSequence) {
  REQUIRE_FRESH_SYSTEMC();
  L1Bench b;
  const uint64_t a = 0x10000, conflicting = a + 32 * 1024;  // same set, other tag
  std::vector<Sent> r;
  Script s("script", [&] {
    r.push_back(b.tp.load(a, 0));            // cold miss: bank at 0, L2 asked at 1, back at 21
    r.push_back(b.tp.load(a, 30));           // hit: 31
    r.push_back(b.tp.load(a + 60, 40));      // same line: hit at 41
    r.push_back(b.tp.load(conflicting, 50)); // evicts a: asked at 51, back at 71
    r.push_back(b.tp.load(a, 80));           // conflict miss: asked at 81, back at 101
  });
  sc_core::sc_start();
  ASSERT_EQ(r.size(), 5u);
  const Cycle expected[] = {21, 31, 41, 71, 101};
  const ServedBy by[] = {ServedBy::kSink, ServedBy::kL1, ServedBy::kL1, ServedBy::kSink, ServedBy::kSink};
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(r[i].response, tlm::TLM_OK_RESPONSE) << i;
    EXPECT_EQ(r[i].done, expected[i]) << i;
    EXPECT_EQ(r[i].served_by, by[i]) << i;
  }
  const auto& c = b.l1.counters();
  EXPECT_EQ(c.loads, 5u);
  EXPECT_EQ(c.hits, 2u);
  EXPECT_EQ(c.misses, 3u);
  EXPECT_EQ(c.merged_misses, 0u);
  EXPECT_EQ(c.fills, 3u);
  EXPECT_EQ(c.bank_conflicts, 0u);
  stats::Values v = stats::Values::snapshot(b.l1.stats());
  EXPECT_EQ(v.count("downstream_requests"), 3u);
  EXPECT_EQ(v.count("downstream_bytes"), 3u * 64u);
  EXPECT_DOUBLE_EQ(c.energy_nj, (5 + 3) * 0.066);  // 5 lookups + 3 fills
  ASSERT_EQ(b.below.seen.size(), 3u);
  EXPECT_EQ(b.below.seen[0].address, a);
  EXPECT_EQ(b.below.seen[0].bytes, 64u);
  EXPECT_EQ(b.below.seen[0].cycle, 1u);
  EXPECT_TRUE(b.below.seen[0].timing_only);
  EXPECT_EQ(b.below.seen[1].address, conflicting);
  EXPECT_EQ(b.below.seen[2].cycle, 81u);
}

TEST(L1DataCache, BankConflictCostsACycleAndOutOfOrderArrivalsKeepTheirSlots) {
  REQUIRE_FRESH_SYSTEMC();
  L1Bench b;
  // Lines 0 and 8 share bank 0 (8 banks, line-interleaved); line 1 is in bank 1.
  const uint64_t l0 = 0, l1 = 64, l8 = 8 * 64;
  std::vector<Sent> r;
  Script s("script", [&] {
    b.tp.load(l0, 0);
    b.tp.load(l1, 0);
    b.tp.load(l8, 0);  // warm all three (misses; bank 0 serialises the first and third)
    r.push_back(b.tp.load(l0, 100));  // bank 0 at 100: 101
    r.push_back(b.tp.load(l1, 100));  // bank 1 at 100: 101, no conflict
    r.push_back(b.tp.load(l8, 100));  // bank 0 busy at 100: 101, so 102 (a conflict)
    r.push_back(b.tp.load(l0, 300));  // bank 0 at 300
    r.push_back(b.tp.load(l8, 299));  // arrives later for an earlier cycle: still 299 -> 300
    r.push_back(b.tp.load(l0, 299));  // 299 and 300 taken: 301 -> 302
  });
  sc_core::sc_start();
  ASSERT_EQ(r.size(), 6u);
  EXPECT_EQ(r[0].done, 101u);
  EXPECT_EQ(r[1].done, 101u);
  EXPECT_EQ(r[2].done, 102u);
  EXPECT_EQ(r[3].done, 301u);
  EXPECT_EQ(r[4].done, 300u);
  EXPECT_EQ(r[5].done, 302u);
  const auto& c = b.l1.counters();
  EXPECT_EQ(c.hits, 6u);
  EXPECT_EQ(c.misses, 3u);
  // Warm-up: line 8 waits for line 0 at cycle 0 (1 cycle); then 100 (1) and 299 (2 cycles).
  EXPECT_EQ(c.bank_conflicts, 3u);
  EXPECT_EQ(c.conflict_cycles, 1u + 1u + 2u);
}

TEST(L1DataCache, MissesToALineInFlightAreMerged) {
  REQUIRE_FRESH_SYSTEMC();
  L1Bench b;
  std::vector<Sent> r;
  Script s("script", [&] {
    r.push_back(b.tp.load(0x400, 0));   // miss, line back at 21
    r.push_back(b.tp.load(0x408, 5));   // same line, in flight: waits for that fill
    r.push_back(b.tp.load(0x43C, 21));  // the fill holds bank 0 at 21: slot 22, done 23
  });
  sc_core::sc_start();
  EXPECT_EQ(r[0].done, 21u);
  EXPECT_EQ(r[1].done, 21u);
  EXPECT_EQ(r[1].served_by, ServedBy::kL1Merged);
  EXPECT_EQ(r[2].done, 23u);
  EXPECT_EQ(b.l1.counters().misses, 1u);
  EXPECT_EQ(b.l1.counters().merged_misses, 1u);
  EXPECT_EQ(b.l1.counters().hits, 1u);
  EXPECT_EQ(b.below.seen.size(), 1u);  // one request for the line
}

TEST(L1DataCache, StoresWriteAroundAndDataStaysCoherentInTheBackingStore) {
  REQUIRE_FRESH_SYSTEMC();
  L1Bench b;
  uint32_t loaded = 0;
  std::vector<Sent> r;
  Script s("script", [&] {
    uint32_t v = 0x12345678;
    r.push_back(b.tp.send(AccessClass::kDataStore, 0x2000, &v, 4, 0));  // absent: not allocated
    r.push_back(b.tp.send(AccessClass::kDataLoad, 0x2000, &loaded, 4, 10));  // so this misses
    uint32_t w = 0xCAFEF00D;
    r.push_back(b.tp.send(AccessClass::kDataStore, 0x2004, &w, 4, 40));  // present: stays valid
    r.push_back(b.tp.load(0x2004, 50));                                  // hit
  });
  sc_core::sc_start();
  EXPECT_EQ(r[0].done, 1u);  // posted: the TP waits for the bank only
  EXPECT_EQ(r[1].done, 31u);
  EXPECT_EQ(r[1].served_by, ServedBy::kSink);
  EXPECT_EQ(loaded, 0x12345678u);  // the data went to the backing store, not into the L1
  EXPECT_EQ(r[2].done, 41u);
  EXPECT_EQ(r[3].done, 51u);
  EXPECT_EQ(r[3].served_by, ServedBy::kL1);
  uint32_t in_memory = 0;
  b.backing.read(0x2004, &in_memory, 4);
  EXPECT_EQ(in_memory, 0xCAFEF00Du);
  const auto& c = b.l1.counters();
  EXPECT_EQ(c.stores, 2u);
  EXPECT_EQ(c.loads, 2u);
  EXPECT_EQ(c.misses, 1u);
  EXPECT_EQ(c.hits, 1u);
  ASSERT_EQ(b.below.seen.size(), 3u);  // write-through, line fill, write-through
  EXPECT_EQ(b.below.seen[0].command, tlm::TLM_WRITE_COMMAND);
  EXPECT_EQ(b.below.seen[0].bytes, 4u);
  EXPECT_EQ(b.below.seen[0].cycle, 1u);
  EXPECT_EQ(b.below.seen[1].command, tlm::TLM_READ_COMMAND);
  EXPECT_EQ(b.below.seen[2].command, tlm::TLM_WRITE_COMMAND);
}

TEST(L1DataCache, RejectsAccessesThatCrossALineOrAreNotData) {
  REQUIRE_FRESH_SYSTEMC();
  L1Bench b;
  std::vector<Sent> r;
  Script s("script", [&] {
    r.push_back(b.tp.load(60, 0, 8));
    uint8_t ray[48] = {};
    r.push_back(b.tp.send(AccessClass::kStreamPush, 0, ray, 48, 0, 1));
  });
  sc_core::sc_start();
  EXPECT_EQ(r[0].response, tlm::TLM_BURST_ERROR_RESPONSE);
  EXPECT_EQ(r[1].response, tlm::TLM_COMMAND_ERROR_RESPONSE);
  EXPECT_EQ(b.l1.counters().accesses, 0u);
}

TEST(L1DataCache, InvalidGeometryIsNamed) {
  L1DataCacheConfig c;
  c.banks = 6;
  try {
    c.validate();
    FAIL() << "accepted 6 banks";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("l1d.banks"), std::string::npos) << e.what();
  }
}

TEST(L1DataCache, StatisticsTreeNamesEveryCounter) {
  REQUIRE_FRESH_SYSTEMC();
  L1Bench b;
  Script s("script", [&] { b.tp.load(0, 0); b.tp.load(0, 50); });
  sc_core::sc_start();
  stats::Values v = stats::Values::snapshot(b.l1.stats());
  v.derive();
  const nlohmann::json j = v.to_json({});
  EXPECT_EQ(j.at("hits"), 1);
  EXPECT_EQ(j.at("misses"), 1);
  EXPECT_EQ(j.at("bytes_read"), 8);
  EXPECT_DOUBLE_EQ(j.at("hit_rate").get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(j.at("energy_nj").get<double>(), 3 * 0.066);
  EXPECT_EQ(v.count("fills"), 1u);
  EXPECT_EQ(v.units().at("conflict_cycles"), "cycles");
  EXPECT_THROW(v.number("no_such_counter"), std::out_of_range);
}

}  // namespace
}  // namespace strata::memory::test
