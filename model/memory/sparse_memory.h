// The one functional copy of simulated DRAM. Pages are allocated on the first write that
// touches them; reads of untouched memory return zeros and allocate nothing, so the host
// footprint follows what the scene and the run touch, never the address space.
// Every level of the hierarchy reads and writes data here; caches keep tags and timing only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <unordered_map>
#include <vector>

namespace strata::memory {

class SparseMemory {
 public:
  static constexpr uint32_t kDefaultPageBytes = 64 * 1024;
  explicit SparseMemory(uint32_t page_bytes = kDefaultPageBytes);  // a power of two

  // Inline: every load and store of every hart comes here. An access inside one page below
  // 4 GiB (all guest memory) is one table lookup and a copy the compiler sizes.
  void read(uint64_t addr, void* out, std::size_t bytes) const {
    const uint64_t page = addr >> page_shift_, offset = addr & (page_bytes_ - 1);
    if (page < direct_.size() && offset + bytes <= page_bytes_) {
      if (const uint8_t* p = direct_[page]) std::memcpy(out, p + offset, bytes);
      else std::memset(out, 0, bytes);
      return;
    }
    read_span(addr, out, bytes);
  }
  void write(uint64_t addr, const void* in, std::size_t bytes) {
    const uint64_t page = addr >> page_shift_, offset = addr & (page_bytes_ - 1);
    if (page < direct_.size() && offset + bytes <= page_bytes_ && direct_[page] != nullptr) {
      std::memcpy(direct_[page] + offset, in, bytes);
      return;
    }
    write_span(addr, in, bytes);
  }

  std::size_t resident_pages() const { return pages_.size(); }
  uint64_t resident_bytes() const { return uint64_t{pages_.size()} * page_bytes_; }
  uint32_t page_bytes() const { return page_bytes_; }

 private:
  void read_span(uint64_t addr, void* out, std::size_t bytes) const;  // any range
  void write_span(uint64_t addr, const void* in, std::size_t bytes);
  const uint8_t* find_page(uint64_t page) const;  // nullptr if untouched
  uint8_t* touch_page(uint64_t page);

  uint32_t page_bytes_;
  uint32_t page_shift_;
  std::unordered_map<uint64_t, std::unique_ptr<uint8_t[]>> pages_;  // owns every page
  // The pages below 4 GiB by number (nullptr: untouched), when that table is small (pages of
  // 64 KiB or more); empty otherwise, and then every access takes the map.
  std::vector<uint8_t*> direct_;
};

}  // namespace strata::memory
