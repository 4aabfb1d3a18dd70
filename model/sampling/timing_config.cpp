#include "model/sampling/timing_config.h"

#include <algorithm>
#include <stdexcept>

namespace strata::sampling {

std::vector<std::string> sample_target_list(const std::string& list) {
  const std::string field = "timing.sample_target_stats";
  std::vector<std::string> out;
  for (size_t from = 0; from <= list.size();) {
    size_t comma = list.find(',', from);
    if (comma == std::string::npos) comma = list.size();
    std::string name = list.substr(from, comma - from);
    from = comma + 1;
    name.erase(0, name.find_first_not_of(' '));
    name.erase(name.find_last_not_of(' ') + 1);
    if (name.empty())
      throw std::invalid_argument(field + ": an empty entry in \"" + list +
                                  "\" (expected comma-separated statistics, e.g. frame.cycles,memory.dram.bytes)");
    if (std::find(out.begin(), out.end(), name) != out.end())
      throw std::invalid_argument(field + ": \"" + name + "\" is named twice");
    out.push_back(std::move(name));
  }
  return out;
}

}  // namespace strata::sampling
