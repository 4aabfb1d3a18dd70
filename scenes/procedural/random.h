// Deterministic RNG for the procedural scenes: PCG32 (O'Neill, pcg-random.org) seeded through
// splitmix64 (Vigna). Hand-written because the std:: distributions differ between standard
// libraries, and a scene must come out bit-identical for a given seed on every platform.
#pragma once

#include <cstdint>

namespace strata::scenes {

// Advances `state` and returns the next splitmix64 output.
constexpr uint64_t splitmix64(uint64_t& state) {
  uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

class Pcg32 {
 public:
  // Same seeding as the reference pcg32_srandom_r, so the reference test vectors apply.
  constexpr Pcg32(uint64_t initstate, uint64_t initseq) : inc_((initseq << 1u) | 1u) {
    next_u32();
    state_ += initstate;
    next_u32();
  }

  // One independent generator per (seed, key). Generators keyed by item index make an item's
  // geometry independent of how many items come before it or how many numbers they drew.
  static constexpr Pcg32 keyed(uint64_t seed, uint64_t key) {
    uint64_t k = key;
    uint64_t mix = seed ^ splitmix64(k);
    const uint64_t initstate = splitmix64(mix);
    const uint64_t initseq = splitmix64(mix);
    return Pcg32(initstate, initseq);
  }

  constexpr uint32_t next_u32() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ull + inc_;
    const auto xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }

  // Uniform in [0,1): the top 24 bits exactly fill a float mantissa, so no rounding up to 1.
  constexpr float uniform() { return static_cast<float>(next_u32() >> 8) * 0x1p-24f; }

  constexpr float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }

  // Uniform integer in [0, bound), bound > 0, without modulo bias.
  constexpr uint32_t below(uint32_t bound) {
    const uint32_t threshold = (0u - bound) % bound;
    for (;;) {
      const uint32_t r = next_u32();
      if (r >= threshold) return r % bound;
    }
  }

 private:
  uint64_t state_ = 0;
  uint64_t inc_;
};

}  // namespace strata::scenes
