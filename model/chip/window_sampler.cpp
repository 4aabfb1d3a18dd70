#include "model/chip/window_sampler.h"

#include <algorithm>
#include <cmath>


namespace strata::chip {

WindowSampler::WindowSampler(sc_core::sc_module_name name, const ChipConfig& config, SamplingSchedule& schedule,
                             const stats::Group& root, TurnOrder& turns, Progress progress)
    : sc_core::sc_module(name),
      config_(config),
      schedule_(schedule),
      root_(root),
      turns_(turns),
      progress_(std::move(progress)),
      batches_(&WindowSampler::measured) {
  SC_THREAD(run);
}

bool WindowSampler::measured(const std::string& path, const stats::Values::Stat& s) {
  return s.basis != stats::Basis::kExact || path.compare(0, 9, "sampling.") == 0;
}

double WindowSampler::model_cycles(const stats::Values& v) {
  const double measured = v.number("sampling.measured_instructions");
  return measured > 0 ? v.number("instructions.retired") * v.number("sampling.measured_cycles") / measured : 0.0;
}

uint64_t WindowSampler::min_period() const {
  // When the sampler wakes, halfway through the fast-forward, no TM may have begun the next
  // window's measured part: half the fast-forward plus the next warm-up must exceed a TM's lead
  // on global time. A TM enters a window only when its earliest TP does, and that TP is within
  // a quantum of global time (a fast-forward batch runs the others ahead, but never into the
  // window), so the lead is a quantum and a TP slack; the margin of 5 quanta was sized when a
  // batch was thought to add 4 and is kept. Two quanta at least, so that a fast-forward
  // happens at all.
  const auto& t = config_.timing;
  const uint64_t ahead = 5ull * t.quantum_cycles + 2ull * t.tp_slack_cycles;
  const uint64_t gap = ahead > t.sample_warmup_cycles ? 2 * (ahead - t.sample_warmup_cycles) : 0;
  return t.sample_detail_cycles + std::max<uint64_t>(gap, 2ull * t.quantum_cycles);
}

// Never sparser than configured, nor than a 32nd of the frame: a target met early must not leave
// a long stretch of the frame unsampled.
uint64_t WindowSampler::max_period(double frame_cycles) const {
  const double spread = std::max(0.0, frame_cycles) / kMinWindows;
  return std::max<uint64_t>(config_.timing.sample_period_cycles, static_cast<uint64_t>(spread));
}

void WindowSampler::run() {
  const uint32_t id = config_.tms;  // after the TMs' turns at the same cycle
  for (uint64_t window = 0;; window = schedule_.next_window(window)) {
    // Halfway through the fast-forward: TMs run at most a few quanta ahead of global time
    // there, far less than the distance to either measured part.
    const uint64_t period = schedule_.period_at(window);
    const uint64_t at = window + schedule_.detail() + (period - schedule_.detail()) / 2;
    // The TMs resuming at `at` run first: the snapshot does not depend on how the kernel
    // orders processes woken at the same time (turn_order.h).
    turns_.wait_turn(id, at);
    if (progress_.done()) {  // the frame ended in this period: the report takes its tail
      // A frame that ended before the first window's snapshot has its tail as its only sample.
      // Its weight then scales every measured count and the denominators alike, which the
      // extrapolation (sampling_factors.cpp) divides out again, so it is 1. Weighted counts are
      // rounded to whole numbers, and the tail's share of a period far longer than the frame
      // (timing.sample_period_cycles=4294967295: 1e-5) rounded the frame's counts to a few or
      // none (0% L1 hit rate, 0 L2 accesses; issue 39, F1).
      batches_.set_tail_weight(batches_.windows() == 0
                                   ? 1.0
                                   : tail_weight(schedule_, progress_.end(), config_.timing.sample_period_cycles));
      turns_.leave();
      return;
    }
    stats::Values cumulative = stats::Values::snapshot(root_);
    // A window stands for its period of the frame: weighted against the first period.
    const double weight = double(period) / double(config_.timing.sample_period_cycles);
    batches_.add_window(cumulative, weight);
    const double cycles = cumulative.number("sampling.measured_cycles");
    const double instructions = cumulative.number("sampling.measured_instructions");
    windows_.push_back({weight, cycles - last_cycles_, instructions - last_instructions_});
    last_cycles_ = cycles;
    last_instructions_ = instructions;
    weight_sum_ += weight;
    if (config_.timing.sample_target_error > 0) retarget(at);
  }
}

double WindowSampler::relative_half_width() const {
  // The same delete-one-batch jackknife as BatchMeans, on the ratio cycles / instruction, with
  // the windows in at most 32 consecutive batches.
  const size_t n = windows_.size(), per = (n + 31) / 32, b = (n + per - 1) / per;
  if (b < 2) return 0.0;
  std::vector<std::pair<double, double>> sums(b, {0.0, 0.0});
  double c = 0, m = 0;
  for (size_t i = 0; i < n; ++i) {
    const Window& w = windows_[i];
    sums[i / per].first += w.weight * w.cycles;
    sums[i / per].second += w.weight * w.instructions;
    c += w.weight * w.cycles;
    m += w.weight * w.instructions;
  }
  if (!(m > 0)) return 0.0;
  std::vector<double> replicates;
  for (const auto& [bc, bm] : sums) replicates.push_back(m > bm ? (c - bc) / (m - bm) : c / m);
  return stats::jackknife_half_width(replicates, kConfidence) / (c / m);
}

double WindowSampler::spread_weight(const std::vector<Window>& windows, size_t recent) {
  double c = 0, m = 0;
  for (const Window& w : windows) {
    c += w.weight * w.cycles;
    m += w.weight * w.instructions;
  }
  if (windows.empty() || !(m > 0)) return 0.0;
  const double ratio = c / m;
  double past = 0, last = 0;
  const size_t first_recent = windows.size() - std::min(std::max<size_t>(recent, 1), windows.size());
  for (size_t i = 0; i < windows.size(); ++i) {
    const double residual = windows[i].cycles - ratio * windows[i].instructions;
    past += windows[i].weight * windows[i].weight * residual * residual;
    if (i >= first_recent) last += residual * residual;
  }
  last /= double(windows.size() - first_recent);
  // Recent windows all on the ratio: nothing predicts their spread, so plan as for equal
  // spreads (the sum of weight^2), not for none.
  if (!(last > 0)) {
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

void WindowSampler::retarget(uint64_t now) {
  if (windows_.size() < kPilotWindows) return;
  const double fraction = progress_.fraction();
  if (!(fraction > 0.02)) return;  // too early to tell how long the frame is
  const double relative = relative_half_width();
  if (!(relative > 0)) return;
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
  // The period grows (up to max_period) as well as shrinks.
  // Planned to a little inside the target: the half-width so far is itself an estimate, from
  // at most 32 batches (a relative standard error of about 1 / sqrt(2 x 31) = 13%), and a plan
  // that aims at the target exactly misses it about half the time.
  const double target = kPlanningMargin * config_.timing.sample_target_error;
  const double base = double(config_.timing.sample_period_cycles);
  const double frame = double(now) / std::min(1.0, fraction);
  const double remaining_cycles = std::max(0.0, frame - double(now));
  const double remaining = remaining_cycles / base;
  const double gain = target * (frame / base) / (relative * weight_sum_);
  const double weight = remaining > 0 ? spread_weight(windows_, kRecentWindows) * (gain * gain - 1.0) / remaining : 0.0;
  const double chosen = std::max(0.0, weight) * base;
  const uint64_t period =
      std::clamp<uint64_t>(static_cast<uint64_t>(std::min(chosen, 1e18)), min_period(),
                           std::max(min_period(), max_period(frame)));
  // From the next window on: no TM has reached it yet.
  const uint64_t current = schedule_.window_of(now);
  schedule_.change_period(schedule_.next_window(current), period);
  // Until the frame ends (run() then weighs the tail by what is left of the frame).
  batches_.set_tail_weight(double(period) / double(config_.timing.sample_period_cycles));
}

}  // namespace strata::chip
