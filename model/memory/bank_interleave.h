// Which bank of a banked cache holds a line. Lines are interleaved over the banks; with
// `hashed`, the bank index is the low bits of the line XOR-folded with every higher group of
// as many bits, as banked L2s are built so that a power-of-two stride does not camp on one
// bank. Our scene images align each treelet to its 32 KB buffer size, so without the hash the
// first line of every treelet (the hottest: every ray entering it reads its root) lands in
// bank 0 (docs/memory-system.md, "Bank selection"). The L2 and the crossbar that routes to its
// banks share this one function.
#pragma once

#include <cstdint>

namespace strata::memory {

class BankInterleave {
 public:
  BankInterleave(uint32_t banks, bool hashed) : mask_(banks - 1), hashed_(hashed && banks > 1) {
    while ((1u << bits_) < banks) ++bits_;
  }
  uint32_t bank(uint64_t line) const {
    if (!hashed_) return static_cast<uint32_t>(line & mask_);
    uint64_t h = 0;
    for (uint64_t x = line; x != 0; x >>= bits_) h ^= x;
    return static_cast<uint32_t>(h & mask_);
  }

 private:
  uint32_t mask_;
  uint32_t bits_ = 0;
  bool hashed_;
};

}  // namespace strata::memory
