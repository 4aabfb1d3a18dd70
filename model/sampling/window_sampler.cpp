#include "model/sampling/window_sampler.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "model/sampling/sampling_factors.h"

namespace strata::sampling {

WindowSampler::WindowSampler(sc_core::sc_module_name name, const TimingConfig& timing, uint32_t turn,
                             SamplingSchedule& schedule, const stats::Group& root, TurnOrder& turns, Progress progress)
    : sc_core::sc_module(name),
      timing_(timing),
      turn_(turn),
      schedule_(schedule),
      root_(root),
      turns_(turns),
      progress_(std::move(progress)),
      batches_(&WindowSampler::measured, 32, timing.sample_interval) {
  // Checked when the chip is built, so a misspelt name stops the run before it starts.
  targets_ = target_stats(timing_, stats::Values::snapshot(root_));
  windows_.resize(targets_.size());
  last_counts_.assign(targets_.size(), 0.0);
  in_plan_.assign(targets_.size(), true);
  // The frame time's interval holds the clock's own error, at least timing.sample_clock_bound,
  // whatever the windows (docs/sampled-timing.md, "The clock's error in the interval"): a target
  // on frame cycles no wider than that is out of reach from the start.
  if (timing_.sample_target_error > 0)
    for (size_t k = 0; k < targets_.size(); ++k)
      if (targets_[k] == "frame.cycles" && timing_.sample_target_error <= timing_.sample_clock_bound) {
        in_plan_[k] = false;
        out_of_reach_.push_back({targets_[k], 0, timing_.sample_clock_bound});
      }
  SC_THREAD(run);
}

std::vector<std::string> WindowSampler::target_stats(const TimingConfig& timing, const stats::Values& tree) {
  const std::string field = "timing.sample_target_stats";
  std::vector<std::string> names = sample_target_list(timing.sample_target_stats);
  for (const std::string& name : names) {
    if (name == "frame.cycles") continue;  // the samples' frame time (sampled_model_cycles)
    const auto fail = [&](const std::string& why) {
      throw std::invalid_argument(field + ": \"" + name + "\" " + why);
    };
    if (!tree.has(name)) fail("is not a statistic (docs/statistics.md lists them)");
    const stats::Values::Stat* s = nullptr;
    try {
      s = &tree.stat(name);
    } catch (const std::out_of_range&) {
      fail("is a group, not a statistic");
    }
    using stats::Kind;
    using stats::Unit;
    const Unit u = s->def->unit;
    const bool additive = u == Unit::kCount || u == Unit::kBytes || u == Unit::kCycles || u == Unit::kNanojoules;
    if (s->def->kind == Kind::kCount && s->basis == stats::Basis::kExact)
      fail("is exact in sampled timing (counted in full, fast-forward included): it has no interval to hold to a target");
    if (s->def->kind == Kind::kLevel || s->def->kind == Kind::kRatio || !additive)
      fail("is a level, a ratio or a rate: a target holds for counts (events, bytes, cycles) and their sums "
           "(energy), whose interval is relative to the figure");
  }
  return names;
}

bool WindowSampler::measured(const std::string& path, const stats::Values::Stat& s) {
  return s.basis != stats::Basis::kExact || path.compare(0, 9, "sampling.") == 0;
}

uint64_t WindowSampler::min_period() const { return min_period(timing_); }

uint64_t WindowSampler::min_period(const TimingConfig& t) {
  // When the sampler wakes, halfway through the fast-forward, no TM may have begun the next
  // window's measured part: half the fast-forward plus the next warm-up must exceed a TM's lead
  // on global time. A TM enters a window only when its earliest TP does, and that TP is within
  // a quantum of global time (a fast-forward batch runs the others ahead, but never into the
  // window), so the lead is a quantum and a TP slack; the margin of 5 quanta was sized when a
  // batch was thought to add 4 and is kept. Two quanta at least, so that a fast-forward
  // happens at all.
  const uint64_t ahead = 5ull * t.quantum_cycles + 2ull * t.tp_slack_cycles;
  const uint64_t gap = ahead > t.sample_warmup_cycles ? 2 * (ahead - t.sample_warmup_cycles) : 0;
  return t.sample_detail_cycles + std::max<uint64_t>(gap, 2ull * t.quantum_cycles);
}

void WindowSampler::plan_head(const TimingConfig& t, SamplingSchedule& schedule) {
  if (t.sample_head_periods == 0) return;
  // After the head, the shortest fast-forward a window may have: the sampler wakes halfway
  // through it, before any TM reaches the next window's measured part (min_period).
  schedule.set_head(uint64_t{t.sample_head_periods} * t.sample_period_cycles, min_period(t) - t.sample_detail_cycles);
}

// Never sparser than configured, nor than a 32nd of the frame: a target met early must not leave
// a long stretch of the frame unsampled.
uint64_t WindowSampler::max_period(double frame_cycles) const {
  const double spread = std::max(0.0, frame_cycles) / kMinWindows;
  return std::max<uint64_t>(timing_.sample_period_cycles, static_cast<uint64_t>(spread));
}

bool WindowSampler::time_short_frame_in_full(uint32_t id) {
  // Shortly before the head ends, while no TM has passed it (a TM leads global time by at most
  // a few quanta, min_period), project the rest of the frame from its pace so far. Fewer than
  // kShortFramePeriods configured periods give an interval from too few batches to mean
  // anything (a 128x128 STRaTA frame: +-30% and more), for little saved: the head then lasts
  // to the frame's end, so the whole frame is timed as LT times it, and is its one stratum.
  if (!schedule_.has_head()) return false;
  const uint64_t head = schedule_.head_cycles();
  const uint64_t lead = 5ull * timing_.quantum_cycles + 2ull * timing_.tp_slack_cycles;
  if (head <= 2 * lead) return false;
  // The pace over the head's last quarter as well as over all of it: a STRaTA frame finishes
  // its first pixels late and faster and faster, and the pace so far alone projected Sibenik
  // 128x128 strata-pipelines (0.67 M cycles) at well over 1.2 M.
  const uint64_t quarter = head - head / 4;
  turns_.wait_turn(id, quarter);
  const std::vector<std::pair<double, double>> history = {{double(quarter), progress_.fraction()}};
  const uint64_t check = head - lead;
  turns_.wait_turn(id, check);
  const double fraction = progress_.fraction();
  const double rest = fraction > 0 ? planned_frame_cycles(double(check), fraction, history) - double(check) : -1.0;
  const bool short_frame =
      progress_.done() || (fraction > 0 && rest < kShortFramePeriods * double(timing_.sample_period_cycles));
  if (!short_frame) return false;
  if (!progress_.done()) {
    short_frame_rest_ = std::max<uint64_t>(1, static_cast<uint64_t>(rest));
    schedule_.extend_head_to_end();
    for (uint64_t at = check; !progress_.done();) {
      at += timing_.sample_period_cycles;
      turns_.wait_turn(id, at);
    }
  }
  batches_.set_tail_stratum(true);  // the frame ended in its head
  turns_.leave();
  return true;
}

void WindowSampler::run() {
  const uint32_t id = turn_;  // after the TMs' turns at the same cycle
  if (time_short_frame_in_full(id)) return;
  for (uint64_t window = 0;; window = schedule_.next_window(window)) {
    if (schedule_.timed_in_full(window)) return finish_drain(id, window);
    // Halfway through the fast-forward: TMs run at most a few quanta ahead of global time
    // there, far less than the distance to either measured part.
    const uint64_t period = schedule_.period_at(window);
    const uint64_t detail = schedule_.detail_at(window);
    const uint64_t at = window + detail + (period - detail) / 2;
    // The TMs resuming at `at` run first: the snapshot does not depend on how the kernel
    // orders processes woken at the same time (turn_order.h).
    turns_.wait_turn(id, at);
    const bool head = window == 0 && schedule_.has_head();
    if (progress_.done()) {  // the frame ended in this period: the report takes its tail
      if (head) {
        // It ended in its head, timed in full: the whole frame is that stratum.
        batches_.set_tail_stratum(true);
      } else {
        // A frame that ended before the first window's snapshot has its tail as its only
        // sample. Its weight then scales every measured count and the denominators alike,
        // which the extrapolation (sampling_factors.cpp) divides out again, so it is 1.
        // Weighted counts are rounded to whole numbers, and the tail's share of a period far
        // longer than the frame (timing.sample_period_cycles=4294967295: 1e-5) rounded the
        // frame's counts to a few or none (0% L1 hit rate, 0 L2 accesses; issue 39, F1).
        batches_.set_tail_weight(batches_.windows() == 0
                                     ? 1.0
                                     : tail_weight(schedule_, progress_.end(), timing_.sample_period_cycles));
      }
      turns_.leave();
      return;
    }
    stats::Values cumulative = stats::Values::snapshot(root_);
    const double instructions = cumulative.number("sampling.measured_instructions");
    if (head) {
      // The head is a stratum of its own: counted whole, in no batch, not a window the error
      // target's plan draws its spread from. It stands for its period in the plan's coverage.
      batches_.add_head_stratum(cumulative);
      head_weight_ = double(period) / double(timing_.sample_period_cycles);
      last_counts_ = target_counts(cumulative);
    } else {
      // A window stands for its period of the frame: weighted against the first period.
      const double weight = double(period) / double(timing_.sample_period_cycles);
      batches_.add_window(cumulative, weight);
      weight_sum_ += weight;
      if (timing_.sample_target_error > 0) {
        const std::vector<double> counts = target_counts(cumulative);
        for (size_t k = 0; k < targets_.size(); ++k)
          windows_[k].push_back({weight, counts[k] - last_counts_[k], instructions - last_measured_});
        last_counts_ = counts;
        retarget(at, cumulative);
      }
    }
    last_measured_ = instructions;
    // An error target's pilot runs at the shortest period: at the configured one, its windows
    // weighed 4.5 times those of the period the plan then chose, and the first batch moved
    // STRaTA's DRAM estimate by 4.2% at 512x512 where a middle batch moves it by under 1%.
    if (timing_.sample_target_error > 0 && batches_.windows() == (schedule_.has_head() ? 0u : 1u) &&
        std::any_of(in_plan_.begin(), in_plan_.end(), [](bool b) { return b; }))
      schedule_.change_period(schedule_.next_window(window),
                              std::min<uint64_t>(min_period(), timing_.sample_period_cycles));
    // The drain: once every pixel has been handed out (the rays in flight fall from then on)
    // and the pixels left to finish are at most the configured share, the rest of the frame is
    // one window timed in full (it replaces any period the plan just set).
    const double share = timing_.sample_drain_share;
    if (share > 0 && progress_.handed_out() && 1.0 - progress_.fraction() <= share)
      schedule_.time_in_full(schedule_.next_window(window));
  }
}

void WindowSampler::finish_drain(uint32_t id, uint64_t from) {
  // Every TM is timed from `from` to the frame's end: wake once a configured period to see
  // whether it has ended (no snapshot is taken on the way).
  for (uint64_t at = from;;) {
    at += timing_.sample_period_cycles;
    turns_.wait_turn(id, at);
    if (progress_.done()) break;
  }
  // The drain is a stratum if its window measured anything; a frame that ended in its warm-up
  // leaves a tail like any other. (With one middle window, making the drain a batch instead
  // would give an interval from 2 batches, Student's t with 1 degree of freedom: a 128x128 trax
  // frame, 84% of it measured and 0.5% from LT, came out at +-777% on cycles. The report says
  // instead that the middle was too short for an interval.)
  const double measured = stats::Values::snapshot(root_).number("sampling.measured_instructions");
  if (measured > last_measured_) batches_.set_tail_stratum(true);
  else batches_.set_tail_weight(tail_weight(schedule_, progress_.end(), timing_.sample_period_cycles));
  turns_.leave();
}

std::vector<double> WindowSampler::target_counts(const stats::Values& cumulative) const {
  stats::Values derived = cumulative;  // a formula (DRAM bytes = read + written) over the raw counts
  derived.derive();
  std::vector<double> out;
  out.reserve(targets_.size());
  for (const std::string& t : targets_) {
    const double v = t == "frame.cycles" ? derived.number("sampling.measured_cycles") : derived.number(t);
    out.push_back(std::isfinite(v) ? v : 0.0);
  }
  return out;
}

std::vector<double> WindowSampler::relative_half_widths(uint64_t now, const stats::Values& cumulative) const {
  // The windows so far against the instructions retired so far: the estimate of the frame up to
  // `now`, and its interval, exactly as the report would give them if the frame ended here.
  const stats::Values centre_raw = batches_.weighted_total(cumulative);
  const SampledEstimate estimate(centre_raw, batches_.strata(cumulative), double(now));
  const auto read = [this](const stats::Values& e) {
    std::vector<double> out;
    out.reserve(targets_.size());
    for (const std::string& t : targets_) out.push_back(e.number(t));
    return out;
  };
  const std::vector<double> centre = read(estimate(centre_raw));
  const std::vector<double> hw =
      batches_.half_widths(cumulative, [&](stats::Values r) { return read(estimate(std::move(r))); }, kConfidence);
  std::vector<double> relative(targets_.size(), 0.0);
  if (hw.empty()) return relative;
  for (size_t k = 0; k < targets_.size(); ++k)
    if (std::isfinite(hw[k]) && std::isfinite(centre[k]) && std::fabs(centre[k]) > 0)
      relative[k] = hw[k] / std::fabs(centre[k]);
  return relative;
}

double WindowSampler::planned_frame_cycles(double now, double fraction,
                                           const std::vector<std::pair<double, double>>& history) {
  const double paced = now / std::min(1.0, fraction);
  if (history.empty()) return paced;
  // The pace over the last kRecentWindows plans (or all, if fewer).
  const auto& [then, done_then] = history[history.size() - std::min(history.size(), kRecentWindows)];
  const double pace = now > then ? (fraction - done_then) / (now - then) : 0.0;
  if (!(pace > 0)) return paced;
  return std::min(paced, now + (1.0 - std::min(1.0, fraction)) / pace);
}

double WindowSampler::spread_weight(const std::vector<Window>& windows, size_t recent, stats::IntervalMethod method) {
  double c = 0, m = 0;
  for (const Window& w : windows) {
    c += w.weight * w.value;
    m += w.weight * w.basis;
  }
  if (windows.empty() || !(m > 0)) return 0.0;
  const double ratio = c / m;
  const auto residual = [&](size_t i) { return windows[i].value - ratio * windows[i].basis; };
  const size_t first_recent = windows.size() - std::min(std::max<size_t>(recent, 1), windows.size());
  double past = 0, last = 0;
  size_t terms = 0, recent_terms = 0;
  if (method == stats::IntervalMethod::kJackknife) {
    for (size_t i = 0; i < windows.size(); ++i) {
      const double r = residual(i);
      past += windows[i].weight * windows[i].weight * r * r;
      if (i >= first_recent) last += r * r, ++recent_terms;
    }
    terms = windows.size();
  } else {
    // The interval counts how much neighbours differ, not how far each lies from the ratio: a
    // trend in the residuals (DRAM bytes per instruction rising over a STRaTA frame) adds only
    // its slope. Half the squared difference of neighbours stands for one window's e^2; the
    // n - 1 differences are scaled to n windows below.
    for (size_t i = 1; i < windows.size(); ++i) {
      const double d = windows[i].weight * residual(i) - windows[i - 1].weight * residual(i - 1);
      past += 0.5 * d * d;
      if (i >= first_recent) {
        const double u = residual(i) - residual(i - 1);
        last += 0.5 * u * u, ++recent_terms;
      }
    }
    terms = windows.size() - 1;
    if (terms > 0) past *= double(windows.size()) / double(terms);
  }
  if (recent_terms > 0) last /= double(recent_terms);
  // Recent windows all on the ratio (or too few to differ): nothing predicts their spread, so
  // plan as for equal spreads (the sum of weight^2), not for none.
  if (!(last > 0) || terms == 0) {
    double squares = 0;
    for (const Window& w : windows) squares += w.weight * w.weight;
    return squares;
  }
  return past / last;
}

double WindowSampler::tail_weight(const SamplingSchedule& schedule, uint64_t frame_end, uint64_t base_period) {
  const uint64_t start = schedule.window_of(frame_end);
  const uint64_t span = std::min(frame_end - start, schedule.period_at(start));
  return double(span) / double(base_period);
}

void WindowSampler::retarget(uint64_t now, const stats::Values& cumulative) {
  if (targets_.empty() || windows_.front().size() < kPilotWindows) return;
  const double fraction = progress_.fraction();
  if (!(fraction > 0.02)) return;  // too early to tell how long the frame is
  const std::vector<double> relative = relative_half_widths(now, cumulative);
  // In units of the first period: a window of weight w stands for w periods, and its measured
  // counts are scaled by w. So window i adds w_i^2 e_i^2 to the frame total's variance (e_i its
  // residual, spread_weight) and w_i to the total. If the windows to come all have weight W
  // and the recent windows' spread e^2, they cover the remaining R periods with R / W windows
  // and add R W e^2, so the frame's half-width will be relative * (covered / frame) *
  // sqrt((P + R W) / P), with covered = sum w and P = sum w_i^2 e_i^2 / e^2 so far. For the
  // target: W = P ((target frame / (relative covered))^2 - 1) / R. With windows of one spread
  // P is the sum of w^2, and with equal weights this is the 1/sqrt(windows) rule. The frame's
  // first windows, with cold caches and the first rays, spread several times more than the
  // rest (Sibenik 1024x1024: a standard deviation of about 20% of a window's cycles over the
  // first 14 windows, under 3% later). Planning the rest of the frame by the spread of all
  // windows so far (P = sum w^2) packed the next fifth of the frame with 28 windows where the
  // cap allows 6, and their unequal weights widened every interval.
  // The period grows (up to max_period) as well as shrinks. Each named statistic asks for its
  // own period; the shortest is taken, so the widest interval decides. (A window's residual is
  // taken against its measured instructions for every statistic: the estimator scales some
  // counts by data or stream operations instead, which move with the instructions closely
  // enough for a plan, and the interval it plans from is the estimator's own.)
  // Planned to a little inside the target: the half-width so far is itself an estimate, from
  // at most 32 batches (a relative standard error of about 1 / sqrt(2 x 31) = 13%), and a plan
  // that aims at the target exactly misses it about half the time.
  // A target out of reach: even windows at the shortest period to the frame's end would leave
  // its interval wider than asked, for the frame as long as its pace so far projects (the longer
  // of the two projections: more windows to come).
  // The plan then leaves it out for good, rather than paying for the shortest period to the
  // frame's end and missing it anyway; the report says so. With none left in the plan, the
  // configured period: a missed target costs no more than the default windows.
  const double target = kPlanningMargin * timing_.sample_target_error;
  const double base = double(timing_.sample_period_cycles);
  const double paced = double(now) / std::min(1.0, fraction);
  const double planned = planned_frame_cycles(double(now), fraction, paces_);
  paces_.emplace_back(double(now), fraction);
  // The frame time's interval holds the clock's error bound beside the spread: its spread is
  // planned to what the target leaves of it.
  const auto spread_target = [&](size_t k) {
    return targets_[k] == "frame.cycles"
               ? kPlanningMargin * std::max(0.0, timing_.sample_target_error - timing_.sample_clock_bound)
               : target;
  };
  const auto period_for = [&](size_t k, double frame) {
    const double remaining = std::max(0.0, frame - double(now)) / base;
    const double gain = spread_target(k) * (frame / base) / (relative[k] * (head_weight_ + weight_sum_));
    const double weight =
        remaining > 0 ? spread_weight(windows_[k], kRecentWindows, timing_.sample_interval) * (gain * gain - 1.0) / remaining : 0.0;
    return std::max(0.0, weight) * base;
  };
  // The relative half-width the frame would end with at windows of `period` from here on (the
  // plan's relation solved the other way).
  const auto reach_at = [&](size_t k, double frame, double period) {
    const double remaining = std::max(0.0, frame - double(now)) / base;
    const double spread = spread_weight(windows_[k], kRecentWindows, timing_.sample_interval);
    const double grow = spread > 0 ? std::sqrt(1.0 + remaining * (period / base) / spread) : 1.0;
    return relative[k] * (head_weight_ + weight_sum_) / (frame / base) * grow;
  };
  double chosen = std::numeric_limits<double>::infinity();
  bool any_in_plan = false;
  for (size_t k = 0; k < targets_.size(); ++k) {
    if (!in_plan_[k]) continue;
    any_in_plan = true;
    if (!(relative[k] > 0)) continue;  // no interval yet, or an exact figure
    if (windows_[k].size() >= kReachWindows) {
      // Judged against the target asked, not the plan's margin inside it.
      // The frame time's interval also holds the clock's error, at least the bound.
      const double best = reach_at(k, paced, double(min_period())) +
                          (targets_[k] == "frame.cycles" ? timing_.sample_clock_bound : 0.0);
      if (best > timing_.sample_target_error) {
        in_plan_[k] = false;
        out_of_reach_.push_back({targets_[k], now, best});
        continue;
      }
    }
    chosen = std::min(chosen, period_for(k, planned));
  }
  if (!std::isfinite(chosen)) {
    if (any_in_plan && std::none_of(in_plan_.begin(), in_plan_.end(), [](bool b) { return b; }))
      chosen = base;  // the last target just left the plan
    else
      return;
  }
  const double frame = planned;
  const uint64_t period =
      std::clamp<uint64_t>(static_cast<uint64_t>(std::min(chosen, 1e18)), min_period(),
                           std::max(min_period(), max_period(frame)));
  // From the next window on: no TM has reached it yet.
  const uint64_t current = schedule_.window_of(now);
  schedule_.change_period(schedule_.next_window(current), period);
  // Until the frame ends (run() then weighs the tail by what is left of the frame).
  batches_.set_tail_weight(double(period) / double(timing_.sample_period_cycles));
}

}  // namespace strata::sampling
