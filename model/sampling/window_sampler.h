// Sampled timing's samples (docs/sampled-timing.md, "Confidence intervals" and "An error
// target"). Once per sampling period, halfway through the fast-forward (when every TM has
// finished the period's measured part, and none has begun the next), the chip's raw statistics
// tree is handed to a BatchMeans, whose batches of windows give every estimate its interval.
//
// With an error target (timing.sample_target_error), the sampler also chooses the period: after
// a pilot of kPilotWindows windows at the shortest period, at every window it estimates the
// intervals of the statistics the target names (timing.sample_target_stats: frame cycles, DRAM
// bytes and L2 accesses by default) from the windows so far, by the report's own interval, and
// how long the frame will be (from the share of pixels done). It sets the period of the windows
// to come to the longest that still brings every named interval to the target: shorter than the
// configured one when the target needs more windows, longer when it needs fewer.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>
#include <systemc>

#include "model/sampling/sampling_schedule.h"
#include "model/sampling/timing_config.h"
#include "model/stats/batch_means.h"
#include "model/stats/stat_group.h"
#include "tlm/turn_order.h"

namespace strata::sampling {

using transport::TurnOrder;

class WindowSampler : public sc_core::sc_module {
 public:
  static constexpr size_t kPilotWindows = 4;
  static constexpr double kConfidence = 0.95;

  struct Progress {
    std::function<bool()> done;        // the frame has finished
    std::function<double()> fraction;  // share of the frame's pixels finished, 0..1
    std::function<uint64_t()> end;     // the frame's last cycle, once done() holds
    std::function<bool()> handed_out;  // every pixel has been handed out to a path
  };
  SC_HAS_PROCESS(WindowSampler);
  // `turn`: its id in the turn order (after the TMs', which run first at the same cycle).
  WindowSampler(sc_core::sc_module_name name, const TimingConfig& timing, uint32_t turn, SamplingSchedule& schedule,
                const stats::Group& root, TurnOrder& turns, Progress progress);
  const stats::BatchMeans& batches() const { return batches_; }

  // The counts a window contributes to: every extrapolated count, and the sampling group's
  // measured denominators. Exact totals (instructions, rays) stay whole in every replicate.
  static bool measured(const std::string& path, const stats::Values::Stat& s);
  // The statistics an error target holds for, parsed from timing.sample_target_stats (a
  // comma-separated list of dotted paths). Each must be an extrapolated count or a formula over
  // counts (bytes, cycles, energy); frame.cycles stands for the samples' frame time. Throws
  // std::invalid_argument naming the field and the entry otherwise.
  static std::vector<std::string> target_stats(const TimingConfig& timing, const stats::Values& tree);
  const std::vector<std::string>& targets() const { return targets_; }

  // The shortest period the schedule may take: the detailed window, and on each side of the
  // sampler's wake-up a margin no TM runs ahead of global time by.
  uint64_t min_period() const;
  static uint64_t min_period(const TimingConfig& t);
  // The frame's head (timing.sample_head_periods) as a window of its own, timed in full: set on
  // the schedule before the TMs are built (they read the first window's warm-up).
  static void plan_head(const TimingConfig& t, SamplingSchedule& schedule);
  // The longest: the configured period, or, once the target is met with room, a kMinWindows-th
  // of the whole frame (`frame_cycles`, projected), so no stretch longer than that (the frame's
  // drain, a change of phase) goes unsampled. Of the whole frame, not of its rest: a cap on the
  // rest shrinks with every window and packs the frame's end with windows, three times as many
  // as the variance asks for on a full frame (docs/sampled-timing.md).
  uint64_t max_period(double frame_cycles) const;
  static constexpr double kMinWindows = 32;
  static constexpr double kPlanningMargin = 0.85;  // plans for 85% of the target (retarget)
  static constexpr size_t kRecentWindows = 8;      // whose spread predicts the windows to come

  // A named statistic whose target the shortest period cannot reach, even if the frame runs as
  // long as its pixels so far project: the plan leaves it out from `cycle` on (docs/sampled-
  // timing.md, "A target out of reach"), so it costs no more windows than the configured
  // period gives. `best`: the relative half-width the shortest period would have ended with,
  // as projected then.
  struct OutOfReach {
    std::string stat;
    uint64_t cycle;
    double best;
  };
  const std::vector<OutOfReach>& out_of_reach() const { return out_of_reach_; }
  // Windows after which a target may be judged out of reach: the pilot, then enough windows for
  // their spread to rest on kRecentWindows of the planned ones.
  static constexpr size_t kReachWindows = kPilotWindows + kRecentWindows;
  // The frame's length for the plan, from the share of pixels done: `now / fraction` (the pace
  // so far), or, when pixels finish faster lately than on average (a STRaTA frame, whose first
  // paths take many bounces before any pixel is done), `now` plus the rest at the recent pace,
  // whichever is shorter. Planning for a frame longer than it is leaves too few windows (a
  // 128x128 frame projected at 1.0 M cycles ended at 0.67 M). `history`: (cycle, fraction)
  // at earlier windows, oldest first.
  static double planned_frame_cycles(double now, double fraction, const std::vector<std::pair<double, double>>& history);
  // A frame whose rest after its head projects to fewer configured periods than this is timed
  // in full, as LT times it: so few windows give no useful interval.
  static constexpr double kShortFramePeriods = 8;
  // The rest of the frame as projected shortly before its head's end, when that made it too
  // short for sampling (0: it was sampled).
  uint64_t short_frame_rest() const { return short_frame_rest_; }

  // One window's weight and, for one target statistic, its measured count (its measured part,
  // not scaled by its weight) and the measured instructions it came with.
  struct Window {
    double weight, value, basis;
  };
  // The error target's plan needs the spread the windows to come will add. A window's
  // contribution to an estimate's variance is weight^2 x residual^2, its residual being its
  // measured count less what its instructions give at the ratio so far (for frame cycles: its
  // cycles less the cycles its instructions take). This
  // returns the windows' sum of weight^2 x residual^2 over the mean residual^2 of the last
  // `recent`: for windows of one spread it is the sum of weight^2 they would have under the
  // old rule; when the spread has fallen since the frame's start (cold caches, the first
  // rays), it is larger, and the period may grow sooner. By successive differences (the
  // interval's default method), residual^2 is half the squared difference of neighbouring
  // windows' (weighted) residuals, as the interval will count them.
  static double spread_weight(const std::vector<Window>& windows, size_t recent,
                              stats::IntervalMethod method = stats::IntervalMethod::kJackknife);
  // The weight of the frame's tail, the window the frame ended in: it stands for the cycles
  // from its start to the frame's end, not for a whole period (a frame that ends a few cycles
  // into a 1.2 M-cycle period would otherwise weigh its drain, where few TPs still run, as a
  // whole period). In units of `base_period`.
  static double tail_weight(const SamplingSchedule& schedule, uint64_t frame_end, uint64_t base_period);

 private:
  void run();
  // A frame too short for sampling is timed in full from its start; true if it was.
  bool time_short_frame_in_full(uint32_t id);
  // The drain, from the window `from` on, timed in full: wait for the frame's end.
  void finish_drain(uint32_t id, uint64_t from);
  void retarget(uint64_t now, const stats::Values& cumulative);
  // Each target's relative half-width from the windows so far, by the report's estimator
  // (SampledEstimate and the batches' interval); 0 where no interval can be given yet.
  std::vector<double> relative_half_widths(uint64_t now, const stats::Values& cumulative) const;
  // The target statistics' measured counts in a raw cumulative tree (frame.cycles: the
  // measured cycles).
  std::vector<double> target_counts(const stats::Values& cumulative) const;

  const TimingConfig& timing_;
  uint32_t turn_;
  SamplingSchedule& schedule_;
  const stats::Group& root_;
  TurnOrder& turns_;  // it wakes in turn with the TMs, after those at the same cycle
  Progress progress_;
  stats::BatchMeans batches_;
  std::vector<std::string> targets_;
  std::vector<std::vector<Window>> windows_;  // per target statistic, for the error target
  std::vector<double> last_counts_;
  double last_measured_ = 0;  // measured instructions at the last snapshot
  double weight_sum_ = 0;     // of the windows so far
  std::vector<bool> in_plan_;                      // per target: not (yet) out of reach
  std::vector<OutOfReach> out_of_reach_;
  std::vector<std::pair<double, double>> paces_;  // (cycle, share of pixels done) at each plan
  uint64_t short_frame_rest_ = 0;
  double head_weight_ = 0;    // the head's span, in configured periods (0: no head)
};

}  // namespace strata::sampling
