#include "model/iss/code_image.h"

#include <stdexcept>

namespace strata::iss {

CodeImage::CodeImage(uint32_t base, std::vector<uint32_t> words)
    : base_(base), words_(std::move(words)) {
  if (base & 3u) throw std::invalid_argument("code image base must be 4-byte aligned");
  if (uint64_t{base} + uint64_t{words_.size()} * 4 > (uint64_t{1} << 32))
    throw std::invalid_argument("code image extends past 2^32");
  decoded_.reserve(words_.size());
  for (uint32_t w : words_) decoded_.push_back(decode(w));
}

void CodeImage::update(uint32_t addr, uint32_t word) {
  const uint32_t index = (addr - base_) >> 2;
  words_[index] = word;
  decoded_[index] = decode(word);
}

}  // namespace strata::iss
