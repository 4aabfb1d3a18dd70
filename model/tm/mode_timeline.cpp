#include "model/tm/mode_timeline.h"

#include <algorithm>
#include <limits>

namespace strata::tm {

ModeTimeline::ModeTimeline(GeneralUnits all_units) {
  segments_.reserve(8);
  segments_.push_back({0, PipelineMode::kGeneral, false, all_units});
}

void ModeTimeline::switch_to(PipelineMode mode, Cycle start, Cycle usable, GeneralUnits during,
                             GeneralUnits after) {
  segments_.push_back({start, mode, true, during});
  segments_.push_back({usable, mode, false, after});
}

uint32_t ModeTimeline::general_units(unsigned k, Cycle from, Cycle to) const {
  uint32_t least = std::numeric_limits<uint32_t>::max();
  Cycle end = std::numeric_limits<Cycle>::max();  // end of segment i: start of i + 1
  for (std::size_t i = segments_.size(); i-- > 0;) {
    const Segment& s = segments_[i];
    // The oldest remembered segment stands for everything before it as well.
    const Cycle start = i == 0 ? 0 : s.start;
    if (start < end && start < to && end > from) least = std::min(least, s.general[k]);
    if (start <= from) break;
    end = start;
  }
  return least;
}

PipelineMode ModeTimeline::mode_at(Cycle c) const {
  for (std::size_t i = segments_.size(); i-- > 1;)
    if (segments_[i].start <= c) return segments_[i].mode;
  return segments_.front().mode;
}

void ModeTimeline::forget_before(Cycle c) {
  // Keep the segment that contains c and everything after it.
  std::size_t keep = 0;
  for (std::size_t i = segments_.size(); i-- > 0;)
    if (segments_[i].start <= c) {
      keep = i;
      break;
    }
  if (keep > 0) segments_.erase(segments_.begin(), segments_.begin() + static_cast<std::ptrdiff_t>(keep));
}

}  // namespace strata::tm
