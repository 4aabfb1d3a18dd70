#include "model/iss/flat_memory.h"

#include <stdexcept>
#include <string>

#include "model/iss/hex_text.h"

namespace strata::iss {

FlatMemory::FlatMemory(uint32_t base, uint32_t size) : base_(base), size_(size), bytes_(size) {
  if (size < 4 || uint64_t{base} + size > (uint64_t{1} << 32))
    throw std::invalid_argument("guest memory region " + hex_text(base) + " + " + hex_text(size) +
                                " must hold at least 4 bytes and end by 2^32");
}

void FlatMemory::write(uint32_t addr, const void* data, size_t length) {
  if (!contains(addr, static_cast<uint32_t>(length)) || length > size_)
    throw std::out_of_range("guest write of " + std::to_string(length) + " bytes at " + hex_text(addr) +
                            " is outside memory " + hex_text(base_) + ".." + hex_text(end()));
  std::memcpy(bytes_.data() + (addr - base_), data, length);
}

void FlatMemory::read(uint32_t addr, void* data, size_t length) const {
  if (!contains(addr, static_cast<uint32_t>(length)) || length > size_)
    throw std::out_of_range("guest read of " + std::to_string(length) + " bytes at " + hex_text(addr) +
                            " is outside memory " + hex_text(base_) + ".." + hex_text(end()));
  std::memcpy(data, bytes_.data() + (addr - base_), length);
}

}  // namespace strata::iss
