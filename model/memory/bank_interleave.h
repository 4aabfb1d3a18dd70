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

// Also the DRAM's channel of a block, where the count need not be a power of two: then the
// folded (or plain) index is taken modulo the count.
class BankInterleave {
 public:
  BankInterleave(uint32_t banks, bool hashed)
      : banks_(banks), pow2_((banks & (banks - 1)) == 0), hashed_(hashed && banks > 1) {
    while ((1u << bits_) < banks) ++bits_;
    mask_ = (uint64_t{1} << bits_) - 1;
  }
  uint32_t bank(uint64_t line) const {
    uint64_t h = line;
    if (hashed_) {
      h = 0;
      for (uint64_t x = line; x != 0; x >>= bits_) h ^= x;
      h &= mask_;
    }
    return static_cast<uint32_t>(pow2_ ? h & mask_ : h % banks_);
  }

 private:
  uint32_t banks_;
  bool pow2_;
  bool hashed_;
  uint32_t bits_ = 0;
  uint64_t mask_ = 0;
};

}  // namespace strata::memory
