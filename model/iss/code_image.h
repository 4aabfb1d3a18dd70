// The predecoded program: one Decoded record per 4-byte word of the executable range.
// Decoding happens once, up front; a store into the range re-decodes just that word. One
// image can be shared by every hart that runs the same program.
#pragma once

#include "model/iss/decoder.h"

#include <cstdint>
#include <vector>

namespace strata::iss {

class CodeImage {
 public:
  CodeImage() = default;
  CodeImage(uint32_t base, std::vector<uint32_t> words);  // base must be 4-byte aligned

  uint32_t base() const { return base_; }
  uint32_t size_bytes() const { return static_cast<uint32_t>(words_.size() * 4); }
  bool contains(uint32_t addr) const { return addr - base_ < size_bytes(); }

  const Decoded* entries() const { return decoded_.data(); }
  const Decoded& at(uint32_t addr) const { return decoded_[(addr - base_) >> 2]; }
  uint32_t word_at(uint32_t addr) const { return words_[(addr - base_) >> 2]; }

  // After guest code wrote the word containing addr.
  void update(uint32_t addr, uint32_t word);

 private:
  uint32_t base_ = 0;
  std::vector<uint32_t> words_;
  std::vector<Decoded> decoded_;
};

}  // namespace strata::iss
