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
  rebuild_pages();
}

void DataClassMap::rebuild_pages() {
  const uint64_t page_bytes = uint64_t{1} << kPageShift;
  const uint64_t pages = (ends_.back() + page_bytes - 1) >> kPageShift;
  pages_.assign(pages, static_cast<uint8_t>(DataClass::kOther));
  std::vector<uint8_t> owners(pages, 0);  // 0: none yet, 1: one range, 2: several
  for (std::size_t r = 0; r < begins_.size(); ++r) {
    const uint64_t first = begins_[r] >> kPageShift, last = (ends_[r] - 1) >> kPageShift;
    for (uint64_t p = first; p <= last; ++p) {
      const bool whole = begins_[r] <= (p << kPageShift) && ends_[r] >= ((p + 1) << kPageShift);
      if (owners[p] == 0 && whole) {
        pages_[p] = static_cast<uint8_t>(classes_[r]);
        owners[p] = 1;
      } else {
        pages_[p] = kMixed;  // part of the page belongs elsewhere (or to nothing)
        owners[p] = 2;
      }
    }
  }
}

}  // namespace strata::transport
