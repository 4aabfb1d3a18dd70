// When the TM's reconfigurable FP units were in which configuration, and so how many
// multipliers and adders were left for general use at any cycle. Requests from decoupled
// TPs may arrive after a mode change for a cycle before it; they must see the capacity that
// held then, so the crossbar keeps the recent history rather than just the current mode.
//
// A mode change from `start` to `usable` is a switching segment (the units of both the old
// and the new pipeline are unavailable), then an open-ended segment of the new mode.
#pragma once

#include "model/tm/cycle.h"
#include "model/tm/xu_class.h"

#include <array>
#include <cstdint>
#include <vector>

namespace strata::tm {

// The unit classes whose general capacity depends on the mode.
constexpr unsigned kReconfigurableCount = 2;  // index 0: FP multipliers, 1: FP adders
using GeneralUnits = std::array<uint32_t, kReconfigurableCount>;

class ModeTimeline {
 public:
  struct Segment {
    Cycle start;
    PipelineMode mode;  // the mode in force, or the one being switched to
    bool switching;
    GeneralUnits general;
  };

  // One open-ended general segment from cycle 0 with every unit general.
  explicit ModeTimeline(GeneralUnits all_units);

  // The current open segment ends at `start`; `during` holds until `usable`, `after` from then.
  void switch_to(PipelineMode mode, Cycle start, Cycle usable, GeneralUnits during, GeneralUnits after);

  // Units of reconfigurable class k that are general throughout [from, to).
  uint32_t general_units(unsigned k, Cycle from, Cycle to) const;
  // The mode in force at c (a switching segment counts as its target mode).
  PipelineMode mode_at(Cycle c) const;
  // From `c` on, nothing changes any more: the current segment has begun.
  bool settled_at(Cycle c) const { return c >= segments_.back().start; }
  const Segment& current() const { return segments_.back(); }
  // The first segment start after c (the capacity may change there); ~0 if none.
  Cycle next_change_after(Cycle c) const {
    Cycle next = ~Cycle{0};
    for (std::size_t i = segments_.size(); i-- > 1 && segments_[i].start > c;) next = segments_[i].start;
    return next;
  }

  // Forgets segments that ended at or before c (no request can be made for them any more).
  void forget_before(Cycle c);
  std::size_t size() const { return segments_.size(); }

 private:
  std::vector<Segment> segments_;  // by start; grows only on a mode change
};

}  // namespace strata::tm
