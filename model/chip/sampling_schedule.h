// Where sampled timing's detailed windows fall (docs/sampled-timing.md). A window opens every
// period; its first detail cycles are timed, of which the first warm-up cycles are not
// measured. The period may change during the frame (an error target, window_sampler.h), but
// only from a window start that no TM has reached yet, so every TM sees the same windows.
// The chip owns one schedule; the TMs and the window sampler read it.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "model/chip/chip_config.h"

namespace strata::chip {

class SamplingSchedule {
 public:
  using Cycle = uint64_t;
  explicit SamplingSchedule(const TimingConfig& t)
      : detail_(t.sample_detail_cycles), warmup_(t.sample_warmup_cycles) {
    segments_.push_back({0, t.sample_period_cycles});
  }

  // The first cycle of the window `t` lies in.
  Cycle window_of(Cycle t) const {
    const Segment& s = segment_of(t);
    return t - (t - s.from) % s.period;
  }
  // The first cycle of the window after the one starting at `window`.
  Cycle next_window(Cycle window) const { return window + segment_of(window).period; }
  bool detailed(Cycle t) const { return t - window_of(t) < detail_; }
  Cycle window_end(Cycle window) const { return window + detail_ - 1; }  // its last detailed cycle
  Cycle detail() const { return detail_; }
  Cycle period_at(Cycle t) const { return segment_of(t).period; }

  // From the window starting at `from` (a window start under the current periods) on, windows
  // open every `period` cycles.
  void change_period(Cycle from, Cycle period) {
    if (segments_.back().from == from) segments_.back().period = period;
    else segments_.push_back({from, period});
  }
  size_t changes() const { return segments_.size() - 1; }

  // Cycles of the measured parts (past each window's warm-up) before `t`.
  Cycle measured_cycles_before(Cycle t) const {
    const Cycle part = detail_ - warmup_;
    Cycle total = 0;
    for (size_t i = 0; i < segments_.size() && segments_[i].from < t; ++i) {
      const Segment& s = segments_[i];
      const Cycle end = i + 1 < segments_.size() && segments_[i + 1].from < t ? segments_[i + 1].from : t;
      const Cycle span = end - s.from, into = span % s.period;  // whole periods, then the last one's start
      total += span / s.period * part + (into > warmup_ ? std::min(into - warmup_, part) : 0);
    }
    return total;
  }

 private:
  struct Segment {
    Cycle from, period;
  };
  // Nearly always the last segment: it is checked first.
  const Segment& segment_of(Cycle t) const {
    for (size_t i = segments_.size(); i-- > 1;)
      if (t >= segments_[i].from) return segments_[i];
    return segments_.front();
  }
  Cycle detail_, warmup_;
  std::vector<Segment> segments_;
};

}  // namespace strata::chip
