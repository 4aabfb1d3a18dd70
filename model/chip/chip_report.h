// The statistics of one simulated frame: a snapshot of the chip's statistics tree, taken
// when the simulation has stopped, extrapolated in sampled timing, with the simulator's own
// speed added. stats.json and the terminal summary are both written from it, never from each
// other; every number names its unit (the tree's) and the timing mode it came from.
#pragma once

#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <vector>
#include <set>
#include <string>

#include "model/chip/chip.h"
#include "model/stats/stat_values.h"

namespace strata::chip {

class FrameReport {
 public:
  // `wall_seconds`: host time of the simulation itself (for the simulator's own speed);
  // `interrupted`: the run was stopped before the frame finished (Ctrl-C). The chip must
  // outlive the report.
  FrameReport(const Chip& chip, double wall_seconds, bool interrupted = false);
  FrameReport(const FrameReport&) = delete;
  FrameReport& operator=(const FrameReport&) = delete;

  const stats::Values& values() const { return values_; }
  bool interrupted() const { return interrupted_; }

  // stats.json: the design and timing, every statistic (instance arrays listed one by one for
  // the axes named: "tm", "l2-bank", "channel"), the units of each, and the config.
  nlohmann::json to_json(const std::set<std::string>& detail = default_detail()) const;
  // A one-screen summary, each line tagged with the timing mode; warns when a fidelity
  // sentinel is not 0.
  std::string summary() const;

  static std::set<std::string> default_detail() { return {"channel"}; }

  // Sampled timing: the confidence level of the intervals, and each estimated statistic's
  // half-width by dotted path (empty in the other modes, or when the frame had too few
  // windows: then `interval_note()` says why).
  static constexpr double kConfidence = 0.95;
  const std::map<std::string, double>& half_widths() const { return half_widths_; }
  const std::string& interval_note() const { return interval_note_; }
  static const std::set<std::string>& detail_axes();  // every axis the tree has

 private:
  const Chip& chip_;
  double wall_;
  bool interrupted_;
  uint64_t resident_bytes_;
  stats::Group simulation_;
  stats::Values values_;
  std::map<std::string, double> half_widths_;  // the batches' spread plus the clock's systematic
  // The part of each half-width that is the clock's systematic error: how far the figure moves
  // when the frame time is the samples' estimate instead of the clock.
  std::map<std::string, double> clock_systematic_;
  bool timed_in_full_ = false;  // sampled, but all of it in the head and drain strata
  // Sampled timing: the simulated clock at the frame's end (frame.cycles), and the samples' own
  // estimate of the frame time (SampledEstimate); stats.json and the summary give both, and
  // their disagreement is in the frame time's interval.
  double simulated_cycles_ = 0;
  double samples_cycles_ = 0;  // the samples' own frame-time estimate (SampledEstimate)
  std::string interval_note_;
  size_t batches_ = 0, windows_ = 0;
  double measured_share_ = 0;  // of the frame's cycles, by the windows' measured parts
  std::map<std::string, std::vector<double>> replicates_;  // of the figures a comparison reads

  // Sampled timing, a finished frame: its windows weight the estimates and give them intervals.
  bool has_intervals() const { return chip_.window_batches() != nullptr && !interrupted_; }
  void estimate_intervals(const stats::Values& raw);
  // Adds the clock's systematic error to the intervals (`centre`: the estimate's figures, in
  // the order of `paths`, from the middle's raw totals).
  void add_clock_systematic(const stats::Values& raw, const std::vector<std::string>& paths,
                            const std::function<std::vector<double>(stats::Values)>& centre);
  // " ± 1.2%" for the statistic at `path` (relative), or "" when it has no interval.
  std::string pm(const std::string& path) const;
  std::string pm_points(const std::string& path) const;  // a ratio's: " ± 0.12 points"
  // Streaming designs: the treelet mechanism's lines of the summary (`ci`: the estimates' tag).
  std::string treelet_lines(const std::string& ci) const;
  // An error target's lines: each named statistic's interval against it, and why one was missed.
  std::string target_lines() const;
  // |samples' frame time - clock| / clock when it is in the intervals, else 0.
  double clock_systematic_relative() const;
  // The relative half-width a statistic reached, or -1 when it has no interval.
  double target_reached(const std::string& path) const;
};

// The same JSON, for callers that only need that (tests, tools).
nlohmann::json chip_report(const Chip& chip, double wall_seconds);

}  // namespace strata::chip
