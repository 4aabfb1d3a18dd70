// The one functional copy of simulated DRAM. Pages are allocated on the first write that
// touches them; reads of untouched memory return zeros and allocate nothing, so the host
// footprint follows what the scene and the run touch, never the address space.
// Every level of the hierarchy reads and writes data here; caches keep tags and timing only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <unordered_map>

namespace strata::memory {

class SparseMemory {
 public:
  static constexpr uint32_t kDefaultPageBytes = 64 * 1024;
  explicit SparseMemory(uint32_t page_bytes = kDefaultPageBytes);  // a power of two

  void read(uint64_t addr, void* out, std::size_t bytes) const;
  void write(uint64_t addr, const void* in, std::size_t bytes);

  std::size_t resident_pages() const { return pages_.size(); }
  uint64_t resident_bytes() const { return uint64_t{pages_.size()} * page_bytes_; }
  uint32_t page_bytes() const { return page_bytes_; }

 private:
  const uint8_t* find_page(uint64_t page) const;  // nullptr if untouched
  uint8_t* touch_page(uint64_t page);

  uint32_t page_bytes_;
  uint32_t page_shift_;
  std::unordered_map<uint64_t, std::unique_ptr<uint8_t[]>> pages_;
  // Accesses cluster; remembering the last page skips most hash lookups.
  mutable uint64_t last_page_ = ~uint64_t{0};
  mutable uint8_t* last_data_ = nullptr;
};

}  // namespace strata::memory
