#include "model/memory/sparse_memory.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace strata::memory {

SparseMemory::SparseMemory(uint32_t page_bytes) : page_bytes_(page_bytes), page_shift_(0) {
  if (page_bytes < 64 || (page_bytes & (page_bytes - 1)) != 0)
    throw std::invalid_argument("SparseMemory: page_bytes must be a power of two >= 64");
  while ((1u << page_shift_) != page_bytes) ++page_shift_;
  const uint64_t low_pages = (uint64_t{1} << 32) >> page_shift_;
  if (low_pages <= 65536) direct_.assign(low_pages, nullptr);
}

const uint8_t* SparseMemory::find_page(uint64_t page) const {
  if (page < direct_.size()) return direct_[page];
  const auto it = pages_.find(page);
  return it == pages_.end() ? nullptr : it->second.get();
}

uint8_t* SparseMemory::touch_page(uint64_t page) {
  if (page < direct_.size() && direct_[page] != nullptr) return direct_[page];
  auto& slot = pages_[page];
  if (!slot) slot.reset(new uint8_t[page_bytes_]());  // zero-filled: untouched memory reads 0
  if (page < direct_.size()) direct_[page] = slot.get();
  return slot.get();
}

void SparseMemory::read_span(uint64_t addr, void* out, std::size_t bytes) const {
  auto* dst = static_cast<uint8_t*>(out);
  while (bytes > 0) {
    const uint64_t offset = addr & (page_bytes_ - 1);
    const std::size_t n = std::min<std::size_t>(bytes, page_bytes_ - offset);
    const uint8_t* page = find_page(addr >> page_shift_);
    if (page != nullptr) std::memcpy(dst, page + offset, n);
    else std::memset(dst, 0, n);
    dst += n;
    addr += n;
    bytes -= n;
  }
}

void SparseMemory::write_span(uint64_t addr, const void* in, std::size_t bytes) {
  const auto* src = static_cast<const uint8_t*>(in);
  while (bytes > 0) {
    const uint64_t offset = addr & (page_bytes_ - 1);
    const std::size_t n = std::min<std::size_t>(bytes, page_bytes_ - offset);
    std::memcpy(touch_page(addr >> page_shift_) + offset, src, n);
    src += n;
    addr += n;
    bytes -= n;
  }
}

}  // namespace strata::memory
