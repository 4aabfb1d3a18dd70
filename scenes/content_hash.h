// A fast, deterministic 64-bit hash for cache keys and image checksums. Not cryptographic:
// it guards against truncation, corruption and stale inputs, not against an adversary.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace strata::scenes {

class ContentHash {
 public:
  void add_bytes(const void* data, size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    size_t i = 0;
    for (; i + 8 <= size; i += 8) {
      uint64_t w;
      std::memcpy(&w, p + i, 8);
      mix(w);
    }
    uint64_t tail = 0;
    std::memcpy(&tail, p + i, size - i);
    mix(tail ^ (uint64_t(size - i) << 56));
    length_ += size;
  }
  template <class T>
  void add(const T& value) {
    add_bytes(&value, sizeof value);
  }
  void add_string(const std::string& s) {
    add(uint64_t(s.size()));
    add_bytes(s.data(), s.size());
  }
  uint64_t value() const {
    uint64_t h = state_ ^ length_;
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 33;
    h *= 0xc4ceb9fe1a85ec53ull;
    h ^= h >> 33;
    return h;
  }

 private:
  void mix(uint64_t w) {
    w *= 0x87c37b91114253d5ull;
    w = (w << 31) | (w >> 33);
    w *= 0x4cf5ad432745937full;
    state_ ^= w;
    state_ = ((state_ << 27) | (state_ >> 37)) * 5 + 0x52dce729;
  }
  uint64_t state_ = 0x9e3779b97f4a7c15ull;
  uint64_t length_ = 0;
};

}  // namespace strata::scenes
