// A TP's memory policy (model/tm/tp_memory.h): the block load the hart uses for a STRaTA op's
// operands must have exactly the effect of the single-word loads it replaces (data, access
// record, functional-warming log), and must refuse a block that leaves the TP's memory
// without touching anything, so the hart's word-by-word fallback finds the faulting word.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "model/tm/tp_memory.h"

namespace {

using strata::tm::TpMemory;
using strata::tm::WarmLog;
using strata::memory::SparseMemory;

constexpr uint32_t kLow = 0x1000;
constexpr uint64_t kHigh = 0x40000;

WarmLog make_log() {
  WarmLog log;
  log.known.assign(64, 0);
  return log;
}

void fill(SparseMemory& m) {
  for (uint32_t a = kLow; a < 0x3000; a += 4) m.write(a, &a, 4);
}

struct Effect {
  std::vector<uint32_t> words;
  strata::tm::AccessRecord record;
  std::vector<uint64_t> entries;
};

// Loads n words from addr on a fresh memory, word by word or as one block, and returns what
// that did.
Effect run_load(uint32_t addr, unsigned n, const WarmLog& start, bool block) {
  SparseMemory m;
  fill(m);
  TpMemory mem(m, kLow, kHigh);
  WarmLog log = start;
  mem.set_warm_log(&log);
  Effect e;
  e.words.assign(n, 0);
  if (block) {
    EXPECT_TRUE(mem.load_words(addr, e.words.data(), n));
  } else {
    for (unsigned i = 0; i < n; ++i) EXPECT_TRUE(mem.load<4>(addr + 4 * i, e.words[i]));
  }
  e.record = mem.record();
  e.entries = log.entries;
  return e;
}
Effect by_words(uint32_t addr, unsigned n, const WarmLog& start) { return run_load(addr, n, start, false); }
Effect by_block(uint32_t addr, unsigned n, const WarmLog& start) { return run_load(addr, n, start, true); }

void expect_same(const Effect& a, const Effect& b) {
  EXPECT_EQ(a.words, b.words);
  EXPECT_EQ(a.record.any, b.record.any);
  EXPECT_EQ(a.record.first, b.record.first);
  EXPECT_EQ(a.record.last, b.record.last);
  EXPECT_EQ(a.record.store, b.record.store);
  EXPECT_EQ(a.entries, b.entries);
}

TEST(TpMemory, ABlockLoadEqualsItsWordLoadsAcrossLines) {
  const WarmLog log = make_log();
  // 12 words from 8 bytes before a line boundary: two lines, one entry each.
  const Effect words = by_words(0x1038, 12, log);
  expect_same(words, by_block(0x1038, 12, log));
  EXPECT_EQ(words.entries.size(), 2u);
  EXPECT_EQ(words.words[0], 0x1038u);
}

TEST(TpMemory, ABlockLoadSkipsWhatItsWordsWouldSkip) {
  WarmLog log = make_log();
  // A skipped range (a stack) that begins inside the block: the words below it are logged,
  // the ones in it are not, exactly as word by word.
  log.skip_lo[0] = 0x1048;
  log.skip_hi[0] = 0x2000;
  const Effect words = by_words(0x1030, 12, log);
  expect_same(words, by_block(0x1030, 12, log));
  ASSERT_EQ(words.entries.size(), 2u);  // lines 0x1000 and 0x1040; 0x1048.. is skipped
  // A block wholly inside it logs nothing either way.
  expect_same(by_words(0x1100, 6, log), by_block(0x1100, 6, log));
  EXPECT_TRUE(by_block(0x1100, 6, log).entries.empty());
}

TEST(TpMemory, ABlockLoadRemembersLinesTheL1IsKnownToHold) {
  WarmLog log = make_log();
  log.known[(0x1040 >> 6) & 63] = (0x1040 >> 6) + 1;  // the L1 already holds line 0x1040
  const Effect words = by_words(0x1038, 12, log);
  expect_same(words, by_block(0x1038, 12, log));
  EXPECT_EQ(words.entries.size(), 1u);
}

TEST(TpMemory, ABlockLeavingTheMemoryIsRefusedAndTouchesNothing) {
  SparseMemory m;
  TpMemory mem(m, kLow, kHigh);
  WarmLog log = make_log();
  mem.set_warm_log(&log);
  uint32_t out[6] = {7, 7, 7, 7, 7, 7};
  EXPECT_FALSE(mem.load_words(static_cast<uint32_t>(kHigh) - 8, out, 6));  // the last 4 words are outside
  EXPECT_FALSE(mem.load_words(kLow - 4, out, 6));
  EXPECT_FALSE(mem.load_words(kLow, out, 0));
  EXPECT_FALSE(mem.record().any);
  EXPECT_TRUE(log.entries.empty());
  EXPECT_EQ(out[0], 7u);
  EXPECT_TRUE(mem.load_words(static_cast<uint32_t>(kHigh) - 24, out, 6));  // exactly to the end
}

}  // namespace
