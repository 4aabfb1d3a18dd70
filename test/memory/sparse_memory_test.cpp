// The backing store is sparse: pages exist only where something was written.
#include "model/memory/sparse_memory.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

namespace {

using strata::memory::SparseMemory;

TEST(SparseMemory, FootprintFollowsTouchedPagesAcrossFourGiB) {
  SparseMemory mem;  // 64 KiB pages
  const uint64_t gib = 1ull << 30;
  const uint32_t v = 0xDEADBEEF;
  mem.write(0, &v, 4);
  mem.write(1 * gib + 12, &v, 4);
  mem.write(3 * gib + 100, &v, 4);
  mem.write(4 * gib - 4, &v, 4);
  EXPECT_EQ(mem.resident_pages(), 4u);
  // A write that straddles a page boundary touches both pages.
  const uint8_t bytes[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  mem.write(2 * gib + 65536 - 4, bytes, 8);
  EXPECT_EQ(mem.resident_pages(), 6u);
  EXPECT_EQ(mem.resident_bytes(), 6u * 65536u);

  uint8_t back[8] = {};
  mem.read(2 * gib + 65536 - 4, back, 8);
  EXPECT_EQ(std::memcmp(back, bytes, 8), 0);
  uint32_t r = 0;
  mem.read(4 * gib - 4, &r, 4);
  EXPECT_EQ(r, v);
}

TEST(SparseMemory, UntouchedMemoryReadsZeroWithoutAllocating) {
  SparseMemory mem;
  uint8_t buf[256];
  std::memset(buf, 0xAB, sizeof buf);
  mem.read(0x12345678900ull, buf, sizeof buf);
  for (uint8_t b : buf) EXPECT_EQ(b, 0);
  EXPECT_EQ(mem.resident_pages(), 0u);
}

TEST(SparseMemory, RejectsPageSizesThatAreNotPowersOfTwo) {
  EXPECT_THROW(SparseMemory(3000), std::invalid_argument);
}

}  // namespace
