// What a run retired, by instruction class, and how often it touched the register files.
// The hart keeps raw per-op and per-access-slot counts; this folds them into a report.
#pragma once

#include "model/iss/decoder.h"
#include "model/iss/ops.h"

#include <array>
#include <cstdint>
#include <string>

namespace strata::iss {

constexpr unsigned kClassCount = static_cast<unsigned>(InstrClass::kCount);

struct Counters {
  uint64_t retired = 0;
  std::array<uint64_t, kClassCount> by_class{};
  uint64_t int_reads = 0, int_writes = 0;  // x0 excluded
  uint64_t fp_reads = 0, fp_writes = 0;

  uint64_t of(InstrClass c) const { return by_class[static_cast<unsigned>(c)]; }
  Counters& operator+=(const Counters& other);
};

const char* class_name(InstrClass c);  // snake_case, for JSON keys and reports

Counters fold_counters(const std::array<uint64_t, kOpCount>& op_counts,
                       const std::array<uint64_t, kRfSlotCount>& rf_counts);

// A multi-line human-readable table; classes that never retired are left out.
std::string format_counters(const Counters& c);

}  // namespace strata::iss
