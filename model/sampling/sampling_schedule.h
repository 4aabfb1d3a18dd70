// Where sampled timing's detailed windows fall (docs/sampled-timing.md). A window opens every
// period; its first detail cycles are timed, of which the first warm-up cycles are not
// measured. The period may change during the frame (an error target, window_sampler.h), but
// only from a window start that no TM has reached yet, so every TM sees the same windows.
// The frame's head and its drain may be windows of their own, timed in full.
// The chip owns one schedule; the TMs and the window sampler read it.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "model/sampling/timing_config.h"

namespace strata::sampling {

class SamplingSchedule {
 public:
  using Cycle = uint64_t;
  // A window that never ends: the frame's drain, timed in full (time_in_full).
  static constexpr Cycle kForever = Cycle{1} << 60;

  explicit SamplingSchedule(const TimingConfig& t)
      : detail_(t.sample_detail_cycles), warmup_(t.sample_warmup_cycles) {
    segments_.push_back({0, t.sample_period_cycles, detail_, warmup_});
  }

  // The frame's head as a window of its own (window_sampler.h, "head and drain strata"): its
  // first `head` cycles detailed and measured from cycle 0 (there is nothing to warm: LT's
  // caches are cold there too), then `gap` cycles of fast-forward, then the configured
  // windows. Before the frame starts only.
  void set_head(Cycle head, Cycle gap) {
    const Cycle period = segments_.front().period;
    segments_.assign({{0, head + gap, head, 0}, {head + gap, period, detail_, warmup_}});
    head_ = true;
  }
  bool has_head() const { return head_; }
  // The head lasts until the frame ends: every cycle detailed and measured, as LT times them (a
  // frame too short for sampling, window_sampler.h). Before any TM has passed the head's end.
  void extend_head_to_end() { segments_.assign({{0, kForever, kForever, 0}}); }

  // The first cycle of the window `t` lies in.
  Cycle window_of(Cycle t) const {
    const Segment& s = segment_of(t);
    return t - (t - s.from) % s.period;
  }
  // The first cycle of the window after the one starting at `window`.
  Cycle next_window(Cycle window) const { return window + segment_of(window).period; }
  bool detailed(Cycle t) const { return t - window_of(t) < segment_of(t).detail; }
  // Its last detailed cycle.
  Cycle window_end(Cycle window) const { return window + segment_of(window).detail - 1; }
  Cycle detail_at(Cycle window) const { return segment_of(window).detail; }
  Cycle warmup_at(Cycle window) const { return segment_of(window).warmup; }
  Cycle period_at(Cycle t) const { return segment_of(t).period; }

  // From the window starting at `from` (a window start under the current periods, that no TM
  // has reached) on, windows open every `period` cycles.
  void change_period(Cycle from, Cycle period) { add({from, period, detail_, warmup_}); }
  // From the window starting at `from` on, every cycle is detailed: one window that lasts
  // until the frame ends, measured past its warm-up (the frame's drain).
  void time_in_full(Cycle from) {
    add({from, kForever, kForever, warmup_});
    drain_ = true;
  }
  bool timed_in_full(Cycle t) const { return segment_of(t).period == kForever; }
  // The head's detailed cycles (0: no head); the drain window's first cycle (0: no drain).
  Cycle head_cycles() const { return head_ ? segments_.front().detail : 0; }
  Cycle drain_from() const { return drain_ ? segments_.back().from : 0; }
  // The sampling period at `t`: in the drain, the last one before it.
  Cycle sampled_period_at(Cycle t) const {
    if (!timed_in_full(t)) return period_at(t);
    return segments_.size() > 1 ? segments_[segments_.size() - 2].period : segments_.front().period;
  }
  // Period changes (the head and the drain not counted).
  size_t changes() const {
    const size_t special = size_t{head_} + size_t{drain_};
    return segments_.size() - 1 > special ? segments_.size() - 1 - special : 0;
  }

  // Cycles of the measured parts (past each window's warm-up) before `t`.
  Cycle measured_cycles_before(Cycle t) const {
    Cycle total = 0;
    for (size_t i = 0; i < segments_.size() && segments_[i].from < t; ++i) {
      const Segment& s = segments_[i];
      const Cycle part = s.detail - s.warmup;
      const Cycle end = i + 1 < segments_.size() && segments_[i + 1].from < t ? segments_[i + 1].from : t;
      const Cycle span = end - s.from, into = span % s.period;  // whole periods, then the last one's start
      total += span / s.period * part + (into > s.warmup ? std::min(into - s.warmup, part) : 0);
    }
    return total;
  }

 private:
  struct Segment {
    Cycle from, period, detail, warmup;
  };
  void add(const Segment& s) {
    if (segments_.back().from == s.from) segments_.back() = s;
    else segments_.push_back(s);
  }
  // Nearly always the last segment: it is checked first.
  const Segment& segment_of(Cycle t) const {
    for (size_t i = segments_.size(); i-- > 1;)
      if (t >= segments_[i].from) return segments_[i];
    return segments_.front();
  }
  Cycle detail_, warmup_;
  std::vector<Segment> segments_;
  bool head_ = false, drain_ = false;
};

}  // namespace strata::sampling
