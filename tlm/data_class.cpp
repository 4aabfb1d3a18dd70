#include "tlm/data_class.h"

#include <stdexcept>
#include <string>

namespace strata::transport {

void DataClassMap::add(uint64_t begin, uint64_t end, DataClass c) {
  if (end <= begin) return;
  size_t i = 0;
  while (i < begins_.size() && begins_[i] < begin) ++i;
  if ((i > 0 && ends_[i - 1] > begin) || (i < begins_.size() && begins_[i] < end))
    throw std::logic_error("data class map: range [" + std::to_string(begin) + ", " + std::to_string(end) +
                           ") of " + data_class_name(c) + " overlaps another");
  begins_.insert(begins_.begin() + static_cast<std::ptrdiff_t>(i), begin);
  ends_.insert(ends_.begin() + static_cast<std::ptrdiff_t>(i), end);
  classes_.insert(classes_.begin() + static_cast<std::ptrdiff_t>(i), c);
}

}  // namespace strata::transport
