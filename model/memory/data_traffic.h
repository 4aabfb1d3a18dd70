// Accesses, misses and bytes of one memory level, split by what the bytes hold
// (tlm/data_class.h). Each level adds to the split where it adds to its totals, so the
// classes sum exactly to them; registered as a "by_data" group with one child per class.
#pragma once

#include "model/stats/stat_group.h"
#include "tlm/data_class.h"

#include <array>
#include <cstdint>
#include <memory>

namespace strata::memory {

struct ClassTraffic {
  uint64_t accesses = 0, misses = 0, bytes = 0;
};
using DataTraffic = std::array<ClassTraffic, transport::kDataClassCount>;

inline ClassTraffic& traffic(DataTraffic& t, transport::DataClass c) { return t[static_cast<unsigned>(c)]; }

// The "by_data" group of a level; `misses` false for a level without misses.
class DataTrafficStats {
 public:
  DataTrafficStats(const DataTraffic& t, bool misses, const char* accesses_are, const char* bytes_are);
  const stats::Group& group() const { return group_; }

 private:
  stats::Group group_;
  std::array<std::unique_ptr<stats::Group>, transport::kDataClassCount> classes_;
};

}  // namespace strata::memory
