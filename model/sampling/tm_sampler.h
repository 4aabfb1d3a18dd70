// Sampled timing inside one TM (docs/sampled-timing.md), apart from the TM that runs it: the
// sampling pattern, which instructions of a detailed window are measured, the rates measured
// there, and how a functional fast-forward batch is charged. Plain arithmetic, no SystemC;
// the TM asks it per instruction only in sampled mode (enabled() false otherwise).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

#include "model/sampling/timing_config.h"
#include "model/sampling/sampling_schedule.h"
#include "tlm/clock.h"

namespace strata::sampling {

class TmSampler {
 public:
  using Cycle = transport::Cycle;

  // `schedule`: the chip's windows (null outside sampled timing).
  TmSampler(const TimingConfig& t, const SamplingSchedule* schedule, uint32_t global_register_latency)
      : enabled_(t.mode == transport::TimingMode::kSampled && schedule != nullptr),
        schedule_(schedule),
        default_wait_(global_register_latency),
        measure_warmup_(schedule ? schedule->warmup_at(0) : 0) {}  // the schedule's head is set before the TMs exist

  // What a stream or global-register operation did. With timing.fast_forward_op_classes a
  // fast-forwarded op is charged the mean latency the last measured window showed for its kind
  // of outcome: in LT the retry loop of a TP without a ray (an assign that finds nothing, or a
  // pop that finds the buffer empty) is several times slower than a pop or push that moves a
  // ray (128 TMs: 100-300 cycles against about 50), and charging every op the mean of all of
  // them ran that loop too fast, so hungry TMs re-picked the fullest buffer too often.
  enum OpClass : unsigned { kAssignFound, kAssignNone, kPopRay, kPopEmpty, kPushStored, kPushFull, kGlobal, kOtherOp, kOpClasses };
  void set_op_classes(bool on) { by_class_ = on; }
  bool enabled() const { return enabled_; }
  Cycle window_of(Cycle t) const { return schedule_->window_of(t); }  // first cycle of t's period
  Cycle next_window(Cycle window) const { return schedule_->next_window(window); }
  bool detailed(Cycle t) const { return schedule_->detailed(t); }
  Cycle window_end(Cycle window) const { return schedule_->window_end(window); }  // its last detailed cycle

  // Whether the instruction a TP issues at t (in `window`) is measured: past the warm-up of
  // the newest window. A TP lagging in an older window does not count; the first TP in a
  // newer one restarts the measurement.
  bool count_measured(Cycle window, Cycle t) {
    if (window > measure_window_) {
      measure_window_ = window;
      measure_warmup_ = schedule_->warmup_at(window);  // the head's window has none
      measured_ = measured_waits_ = measured_wait_cycles_ = 0;
      class_waits_.fill(0);
      class_wait_cycles_.fill(0);
    }
    measuring_ = window == measure_window_ && t - window >= measure_warmup_;
    if (measuring_) ++measured_;
    return measuring_;
  }
  // The instruction being stepped is measured (false outside sampled mode and in batches).
  bool measuring() const { return measuring_; }
  // Whether the current access goes into the statistics: everything outside sampled mode,
  // only the measured parts in it.
  bool counting() const { return !enabled_ || measuring_; }
  // A measured stream or global-register operation took `cycles` from request to answer.
  void note_wait(Cycle cycles, unsigned cls) {
    ++measured_waits_;
    measured_wait_cycles_ += cycles;
    ++class_waits_[cls];
    class_wait_cycles_[cls] += cycles;
  }

  // Updates the fast-forward rates from the measured part of `window` (once per stretch).
  // The TM's TPs share its issue slots, XUs and memory, so the TP-cycles of the measured part
  // (its length times the `live_tps` running) are spread over the instructions issued in it.
  // Stream and global-register operations are charged apart, at their measured latency: a TP
  // waiting for work spends its time in them, and must not slow down a TP that has work.
  void update_rates(Cycle window, uint32_t live_tps) {
    if (rates_window_ == window) return;
    rates_window_ = window;
    const uint32_t tps = std::max<uint32_t>(live_tps, 1);
    // Fewer instructions than TPs is too little to measure (all stalled, or halting, or the
    // window was missed): keep the rates of the last window that had enough (at first, 1).
    if (window != measure_window_ || measured_ < tps) return;
    // The measured part's length: the head's whole window, the configured windows past their
    // warm-up (the drain, timed in full, has no fast-forward to set rates for).
    const double tp_cycles =
        double(schedule_->detail_at(window) - schedule_->warmup_at(window)) * double(tps);
    const double issued = double(measured_);
    const double waits = double(measured_waits_);
    const double wait_cycles = std::min(tp_cycles, double(measured_wait_cycles_));
    cpi_ = tp_cycles / issued;
    wait_cycles_ = waits > 0 ? wait_cycles / waits : double(default_wait_);
    compute_cpi_ = std::max(1.0, (tp_cycles - wait_cycles) / std::max(1.0, issued - waits));
    for (unsigned c = 0; c < kOpClasses; ++c)
      class_cycles_[c] = class_waits_[c] > 0 ? double(class_wait_cycles_[c]) / double(class_waits_[c]) : wait_cycles_;
  }
  double cpi() const { return cpi_; }  // cycles per instruction of one TP, on average

  // A fast-forward batch of one TP, from `start` (fractional cycles) towards `until`.
  void begin_batch(double start, Cycle until) {
    functional_ = true;
    measuring_ = false;
    batch_start_ = start;
    batch_until_ = until;
    batch_waits_ = 0;
    batch_wait_cycles_ = 0.0;
  }
  void end_batch() { functional_ = false; }
  bool in_batch() const { return functional_; }
  void note_batch_wait(unsigned cls) {  // a stream or global-register operation in the batch
    ++batch_waits_;
    batch_wait_cycles_ += by_class_ ? class_cycles_[cls] : wait_cycles_;
  }
  uint64_t batch_waits() const { return batch_waits_; }
  // Cycles for `instructions`, of which `waits` stream/global operations.
  double charge(uint64_t instructions, uint64_t waits) const {
    return double(instructions - waits) * compute_cpi_ + batch_wait_cycles_;
  }
  // When the batch's `retired`-th instruction issues (for dating its STRaTA operations), and
  // whether the batch has reached its end after it.
  Cycle batch_cycle(uint64_t retired) const { return static_cast<Cycle>(batch_start_ + charge(retired, batch_waits_)); }
  bool batch_done_after(uint64_t retired) const {
    return batch_start_ + charge(retired + 1, batch_waits_) >= double(batch_until_);
  }

 private:
  static std::array<double, kOpClasses> filled(double v) {
    std::array<double, kOpClasses> a{};
    a.fill(v);
    return a;
  }
  bool enabled_;
  const SamplingSchedule* schedule_;
  uint32_t default_wait_;
  Cycle measure_window_ = 0;  // the detailed window being measured (its first cycle)
  Cycle measure_warmup_;      // its warm-up (set with it)
  uint64_t measured_ = 0;               // instructions issued in its measured part
  uint64_t measured_waits_ = 0;         // of which stream and global-register operations
  uint64_t measured_wait_cycles_ = 0;   // their cycles from request to answer
  bool measuring_ = false;
  Cycle rates_window_ = ~Cycle{0};
  double cpi_ = 1.0;
  double compute_cpi_ = 1.0;  // an instruction that is not a stream/global operation
  double wait_cycles_ = 1.0;  // a stream or global-register operation
  bool functional_ = false;   // inside a fast-forward batch
  double batch_start_ = 0.0;
  Cycle batch_until_ = 0;
  uint64_t batch_waits_ = 0;
  double batch_wait_cycles_ = 0.0;
  bool by_class_ = false;
  std::array<uint64_t, kOpClasses> class_waits_{}, class_wait_cycles_{};
  std::array<double, kOpClasses> class_cycles_ = filled(1.0);  // as wait_cycles_ until measured
};

}  // namespace strata::sampling
