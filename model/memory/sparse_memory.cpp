#include "model/memory/sparse_memory.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace strata::memory {

SparseMemory::SparseMemory(uint32_t page_bytes) : page_bytes_(page_bytes), page_shift_(0) {
  if (page_bytes < 64 || (page_bytes & (page_bytes - 1)) != 0)
    throw std::invalid_argument("SparseMemory: page_bytes must be a power of two >= 64");
  while ((1u << page_shift_) != page_bytes) ++page_shift_;
}

const uint8_t* SparseMemory::find_page(uint64_t page) const {
  if (page == last_page_) return last_data_;
  const auto it = pages_.find(page);
  if (it == pages_.end()) return nullptr;
  last_page_ = page;
  last_data_ = it->second.get();
  return last_data_;
}

uint8_t* SparseMemory::touch_page(uint64_t page) {
  if (page == last_page_) return last_data_;
  auto& slot = pages_[page];
  if (!slot) slot.reset(new uint8_t[page_bytes_]());  // zero-filled: untouched memory reads 0
  last_page_ = page;
  last_data_ = slot.get();
  return last_data_;
}

void SparseMemory::read(uint64_t addr, void* out, std::size_t bytes) const {
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

void SparseMemory::write(uint64_t addr, const void* in, std::size_t bytes) {
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
