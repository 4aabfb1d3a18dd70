// What every statistic says about itself: its unit, how it combines over instances and how
// sampled timing extrapolates it. Shared by the live registration tree (stat_group.h) and
// the snapshot the reports are written from (stat_values.h).
#pragma once

#include <cstdint>

namespace strata::stats {

enum class Unit : uint8_t {
  kCount,              // events or items
  kBytes,
  kCycles,             // chip clock cycles
  kNanojoules,
  kSeconds,
  kRatio,              // dimensionless, 0..1 unless stated
  kGigabytesPerSecond,
  kPerSecond,          // events per host or simulated second, as described
  kGigahertz,
};
const char* unit_name(Unit u);

enum class Kind : uint8_t {
  kCount,    // additive events: sums over instances; sampled timing scales it by its basis
  kLevel,    // a size or state (capacity, rays stored, cycles a mode was usable): sums over
             // instances, never scaled
  kRatio,    // numerator / denominator of statistics of its own group, recomputed after
             // merging and scaling, so a ratio is never summed or multiplied
  kDerived,  // a formula over the finished snapshot (rates, totals), computed last
};
const char* kind_name(Kind k);

// What causes a count, and so what sampled timing extrapolates it by (the whole frame's
// count of the cause over the count in the measured windows). kExact counts are complete in
// every timing mode (the ISS counts every instruction, fast-forwarded or not).
enum class Basis : uint8_t {
  kInherit,             // the enclosing group's
  kExact,               // never scaled
  kTimedInstructions,   // instructions timed in detail (XU use, stalls)
  kMeasuredInstructions,// instructions of the measured window parts (instruction fetch)
  kDataOps,             // loads, stores and pipeline loads of the measured parts
  kStreamOps,           // stream-memory operations of the measured parts
  kStreamMoves,         // ray pushes and pops of the measured parts (not the idle TPs' polls)
  kCount
};
constexpr unsigned kBasisCount = static_cast<unsigned>(Basis::kCount);
const char* basis_name(Basis b);

// The extrapolation factor of each basis (1 outside sampled timing).
struct Factors {
  double of[kBasisCount] = {1, 1, 1, 1, 1, 1, 1};
  double operator[](Basis b) const { return of[static_cast<unsigned>(b)]; }
  double& operator[](Basis b) { return of[static_cast<unsigned>(b)]; }
};

}  // namespace strata::stats
