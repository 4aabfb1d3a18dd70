// A statistics contract: the statistics a module must register for the code that reads them by
// path (a report, an energy total, a fidelity sentinel, a sampling target). Checked once, when
// the module is made, so a model that plugs in without one of them fails at construction with
// the path and unit it lacks, not when a frame's snapshot is first read.
#pragma once

#include <string>
#include <vector>

#include "model/stats/stat_group.h"

namespace strata::stats {

struct Requirement {
  const char* path;  // below the module's group: "bytes", "by_data" (a sub-group: unit ignored)
  Unit unit;
  bool group = false;  // the path names a sub-group, not a statistic
};

// Throws std::logic_error naming `owner`, the path and what was expected, for the first
// requirement `g` does not meet (missing, or registered with another unit).
void require_stats(const Group& g, const std::string& owner, const std::vector<Requirement>& contract);

}  // namespace strata::stats
