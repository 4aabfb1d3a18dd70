// Guest memory for the ISS: one flat, bounds-checked region, with an optional pair of plain
// function pointers for accesses outside it (device registers, or a TLM socket).
//
// The hart is a template on its memory policy, so a policy's load/store calls inline. A
// policy provides:
//   template <unsigned N> bool load(uint32_t addr, uint32_t& value);   // N = 1, 2, 4; zero-extended
//   template <unsigned N> bool store(uint32_t addr, uint32_t value);   // low N bytes
// returning false for an access fault. Alignment is checked by the hart beforehand.
// Optionally, a policy may also provide
//   bool load_words(uint32_t addr, uint32_t* out, unsigned n);  // n aligned words, all or none
// which the hart uses for a STRaTA op's memory operands (a box, a triangle, a ray) when it
// returns true, and which must then have the effect of the n single-word loads in order. On
// false the hart falls back to single words, which find the faulting word for the trap.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <utility>
#include <vector>

namespace strata::iss {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "the ISS copies little-endian guest words directly; add byte swaps for this host");

struct MemoryFallback {
  void* context = nullptr;
  bool (*load)(void* context, uint32_t addr, unsigned size, uint32_t& value) = nullptr;
  bool (*store)(void* context, uint32_t addr, unsigned size, uint32_t value) = nullptr;
};

// Zeroed bytes from calloc, which takes fresh pages from the OS already zero: a program with a
// large .bss or data region (up to 3 GiB for `render --engine iss`) costs only the pages it
// touches, where std::vector's value-initialisation wrote every byte up front (a fuzz-found
// "hang": a 1.75 GiB p_memsz took over 10 s to zero under ASan).
template <class T>
struct ZeroedAllocator {
  using value_type = T;
  ZeroedAllocator() = default;
  template <class U>
  ZeroedAllocator(const ZeroedAllocator<U>&) noexcept {}
  T* allocate(size_t n) {
    if (void* p = std::calloc(n, sizeof(T))) return static_cast<T*>(p);
    throw std::bad_alloc();
  }
  void deallocate(T* p, size_t) noexcept { std::free(p); }
  // Value-initialisation leaves calloc's zeros; copies construct as usual.
  template <class U>
  void construct(U*) noexcept {}
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  friend bool operator==(const ZeroedAllocator&, const ZeroedAllocator&) { return true; }
  friend bool operator!=(const ZeroedAllocator&, const ZeroedAllocator&) { return false; }
};

class FlatMemory {
 public:
  // size must be at least 4; base + size must not exceed 2^32.
  FlatMemory(uint32_t base, uint32_t size);

  uint32_t base() const { return base_; }
  uint32_t size() const { return size_; }
  uint64_t end() const { return uint64_t{base_} + size_; }
  bool contains(uint32_t addr, uint32_t length) const {
    return addr >= base_ && uint64_t{addr} - base_ + length <= size_;
  }
  uint8_t* host(uint32_t addr) { return bytes_.data() + (addr - base_); }

  // Loader and test access; throws std::out_of_range outside the region.
  void write(uint32_t addr, const void* data, size_t length);
  void read(uint32_t addr, void* data, size_t length) const;
  void write32(uint32_t addr, uint32_t value) { write(addr, &value, 4); }
  uint32_t read32(uint32_t addr) const {
    uint32_t v;
    read(addr, &v, 4);
    return v;
  }

  void set_fallback(const MemoryFallback& fallback) { fallback_ = fallback; }

  template <unsigned N>
  bool load(uint32_t addr, uint32_t& value) {
    const uint32_t offset = addr - base_;
    if (offset <= size_ - N) {
      if constexpr (N == 1) {
        value = bytes_[offset];
      } else if constexpr (N == 2) {
        uint16_t v;
        std::memcpy(&v, bytes_.data() + offset, 2);
        value = v;
      } else {
        std::memcpy(&value, bytes_.data() + offset, 4);
      }
      return true;
    }
    return fallback_.load && fallback_.load(fallback_.context, addr, N, value);
  }

  template <unsigned N>
  bool store(uint32_t addr, uint32_t value) {
    const uint32_t offset = addr - base_;
    if (offset <= size_ - N) {
      std::memcpy(bytes_.data() + offset, &value, N);  // little-endian: low bytes first
      return true;
    }
    return fallback_.store && fallback_.store(fallback_.context, addr, N, value);
  }

 private:
  uint32_t base_;
  uint32_t size_;
  std::vector<uint8_t, ZeroedAllocator<uint8_t>> bytes_;
  MemoryFallback fallback_;
};

}  // namespace strata::iss
