// Bank selection (model/memory/bank_interleave.h) and the set index a hashed bank implies.
#include "model/memory/bank_interleave.h"
#include "model/memory/cache_core.h"

#include <gtest/gtest.h>

#include <set>

namespace strata::memory::test {
namespace {

TEST(BankInterleave, LowBitsWithoutTheHash) {
  const BankInterleave b(16, false);
  for (uint64_t line = 0; line < 1000; ++line) EXPECT_EQ(b.bank(line), line % 16) << line;
}

TEST(BankInterleave, OneBankIsAlwaysBankZero) {
  const BankInterleave b(1, true);
  EXPECT_EQ(b.bank(0), 0u);
  EXPECT_EQ(b.bank(0xdeadbeefULL), 0u);
}

TEST(BankInterleave, HashFoldsEveryHigherGroupOfBits) {
  const BankInterleave b(16, true);
  EXPECT_EQ(b.bank(0x0), 0u);
  EXPECT_EQ(b.bank(0x7), 7u);
  EXPECT_EQ(b.bank(0x10), 1u);           // 0 ^ 1
  EXPECT_EQ(b.bank(0x123), 0x1u ^ 0x2u ^ 0x3u);
  EXPECT_EQ(b.bank(0xF000000000000000ULL), 0xFu);  // the top group counts too
}

TEST(BankInterleave, HashedConsecutiveLinesStillCycleThroughEveryBank) {
  const BankInterleave b(16, true);
  for (uint64_t base = 0; base < (1u << 20); base += 16 * 977) {
    std::set<uint32_t> banks;
    for (uint64_t i = 0; i < 16; ++i) banks.insert(b.bank((base & ~uint64_t{15}) + i));
    EXPECT_EQ(banks.size(), 16u) << base;
  }
}

TEST(BankInterleave, HashedTreeletStridedLinesSpreadOverEveryBank) {
  // Lines 32 KB apart (512 lines of 64 B): all bank 0 without the hash.
  const BankInterleave plain(16, false), hashed(16, true);
  std::set<uint32_t> banks;
  for (uint64_t t = 0; t < 16; ++t) {
    EXPECT_EQ(plain.bank(t * 512), 0u);
    banks.insert(hashed.bank(t * 512));
  }
  EXPECT_EQ(banks.size(), 16u);
}

TEST(CacheCoreSets, HashedSetIndexMapsEachTagsLinesOntoDistinctSets) {
  // 64 KB, 16 banks, 64 B lines, direct-mapped: 1024 sets. For a fixed tag (the line's bits
  // above the set index) the lines must fill every set once, or capacity would be lost.
  const CacheCore core(CacheGeometry{64 * 1024, 16, 64, 1, 16, true});
  for (uint64_t tag = 0; tag < 64; tag += 7) {
    std::set<uint32_t> sets;
    for (uint64_t i = 0; i < core.sets(); ++i) {
      const uint64_t line = tag * core.sets() + i;
      const uint32_t set = core.set_of(line);
      EXPECT_EQ(set % 16, core.bank_of(line)) << line;  // a bank serves the sets named by its bits
      sets.insert(set);
    }
    EXPECT_EQ(sets.size(), core.sets()) << tag;
  }
}

}  // namespace
}  // namespace strata::memory::test
