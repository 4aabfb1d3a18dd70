#include "model/iss/flat_memory.h"

#include <cstdio>
#include <stdexcept>
#include <string>

namespace strata::iss {

namespace {
std::string hex(uint64_t v) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "0x%08llx", static_cast<unsigned long long>(v));
  return buf;
}
}  // namespace

FlatMemory::FlatMemory(uint32_t base, uint32_t size) : base_(base), size_(size), bytes_(size) {
  if (size < 4 || uint64_t{base} + size > (uint64_t{1} << 32))
    throw std::invalid_argument("guest memory region " + hex(base) + " + " + hex(size) +
                                " must hold at least 4 bytes and end by 2^32");
}

void FlatMemory::write(uint32_t addr, const void* data, size_t length) {
  if (!contains(addr, static_cast<uint32_t>(length)) || length > size_)
    throw std::out_of_range("guest write of " + std::to_string(length) + " bytes at " + hex(addr) +
                            " is outside memory " + hex(base_) + ".." + hex(end()));
  std::memcpy(bytes_.data() + (addr - base_), data, length);
}

void FlatMemory::read(uint32_t addr, void* data, size_t length) const {
  if (!contains(addr, static_cast<uint32_t>(length)) || length > size_)
    throw std::out_of_range("guest read of " + std::to_string(length) + " bytes at " + hex(addr) +
                            " is outside memory " + hex(base_) + ".." + hex(end()));
  std::memcpy(data, bytes_.data() + (addr - base_), length);
}

}  // namespace strata::iss
