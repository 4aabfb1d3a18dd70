// The shared execution units (XUs) of one TM and the crossbar through which its TPs reach
// them, including the reconfiguration of FP multipliers and adders into the fused box and
// triangle pipelines. Plain timing bookkeeping, no SystemC process: the TM module calls it
// for each instruction its TPs issue, in (roughly) local-time order.
//
// Every unit class, and each fused pipeline, books its issue slots in a reservation
// calendar in absolute cycles, so requests from TPs that run ahead of one another (loosely
// timed) still see contention exactly. docs/tm-timing.md states the rules; in short:
//   - issue_* return the start cycle; the result is ready at start + latency.
//   - a pipelined unit takes one op per unit per cycle; a non-pipelined one is busy for
//     its whole latency.
//   - in box mode 6+6 of the 8+8 FP multipliers/adders form the box pipeline, in triangle
//     mode 4+2 form the triangle pipeline; the rest stay general.
//   - configure() waits until the units that change are drained, then takes
//     reconfigure_cycles; fused ops wait for the mode to be usable.
//
// Fused ops issued outside their mode throw std::logic_error: the functional side (the
// StrataHook) already turns them into illegal-instruction traps, so reaching the timing
// model with one is a bug in the caller, not in the firmware.
#pragma once

#include "model/tm/cycle.h"
#include "model/tm/mode_timeline.h"
#include "model/tm/tm_config.h"
#include "model/tm/xu_class.h"
#include "model/tm/xu_stats.h"
#include "tlm/reservation_calendar.h"

#include <cstdint>
#include <vector>

namespace strata::tm {

class XuCrossbar {
 public:
  // Validates the config (std::invalid_argument naming the field). Starts in general mode.
  explicit XuCrossbar(const TmConfig& config);

  // A general operation on one unit of `cls`, at or after `earliest`; returns its start.
  Cycle issue_general(XuClass cls, Cycle earliest);
  // fmadd.s and friends: a multiplier at the start, then an adder exactly fp_mul latency
  // later (the product is forwarded); ready at start + fused_multiply_add_latency().
  Cycle issue_fused_multiply_add(Cycle earliest);

  // Fused operations; each needs its mode (else std::logic_error) and waits until the mode
  // is usable. strata.tridiv runs on the shared FP divider.
  Cycle issue_box_test(Cycle earliest);
  Cycle issue_triangle_test(Cycle earliest);
  Cycle issue_triangle_divide(Cycle earliest);

  // Switches the reconfigurable units to `mode`; returns the first cycle the new mode can
  // be used. Asking for the current mode changes nothing and returns max(earliest, the
  // cycle it became usable). Mode changes are applied in the order they are requested.
  Cycle configure(PipelineMode mode, Cycle earliest);

  PipelineMode mode() const { return mode_; }
  Cycle mode_usable_at() const { return usable_at_; }
  uint32_t latency(XuClass cls) const { return unit(cls).latency; }
  uint32_t fused_multiply_add_latency() const { return latency(XuClass::kFpMul) + latency(XuClass::kFpAdd); }
  uint32_t box_latency() const { return box_.latency; }
  uint32_t triangle_latency() const { return triangle_.latency; }
  uint32_t triangle_divide_latency() const { return config_.pipelines.triangle_divide_latency; }
  // Units of `cls` available for general use in cycle c (as currently booked modes say).
  uint32_t general_units(XuClass cls, Cycle c) const;

  // Global time has reached `now`: forget the past. The crossbar also slides its window
  // by itself, keeping xu_history_cycles behind the newest request, but not past the floor.
  void retire_before(Cycle now);
  // No user will ask for a cycle before `floor` (its TPs' earliest next issue): the window
  // may slide up to it by itself. Without a floor it slides freely (kept for tools that
  // issue in time order).
  void set_floor(Cycle floor) { floor_ = floor; }

  // Counters as of `now` (the current mode's cycles are counted up to it).
  XuStats stats(Cycle now) const;
  // Bookings its calendars had to place beyond their horizon (should be 0).
  uint64_t overflow_bookings() const;
  const TmConfig& config() const { return config_; }

 private:
  struct Unit {
    transport::ReservationCalendar calendar;  // units_per_cycle = all units of the class
    const char* name;
    uint32_t count;
    uint32_t latency;
    uint32_t occupancy;  // cycles one op holds its unit's issue slot
    int reconfigurable;  // index into GeneralUnits, or -1 if the mode never changes it
  };

  static Unit make_unit(const char* name, const XuUnitConfig& c, int reconfigurable, uint32_t horizon);
  static Unit make_pipeline(const char* name, const FusedPipelineConfig& c, uint32_t horizon);

  const Unit& unit(XuClass cls) const { return units_[static_cast<unsigned>(cls)]; }
  Unit& unit(XuClass cls) { return units_[static_cast<unsigned>(cls)]; }

  // Whether an op of u can start at c; if not, `retry` is the next start worth trying.
  bool fits(const Unit& u, Cycle c, Cycle& retry) const;
  Cycle find(const Unit& u, Cycle from) const;
  void book(Unit& u, Cycle start);
  Cycle place(Unit& u, Cycle from);  // find + book
  // The earliest cycle >= from after which at most `keep` units of u are still in use.
  Cycle drain_end(const Unit& u, uint32_t keep, Cycle from) const;
  GeneralUnits taken_by(PipelineMode mode) const;
  // Inline: every request passes here, and almost all fall inside the window.
  void slide_window(Cycle earliest) {
    if (earliest >= window_base_ && earliest < window_base_ + 2 * history_) return;
    slide_window_slow(earliest);
  }
  void slide_window_slow(Cycle earliest);
  void retire_to(Cycle now);
  void require_mode(PipelineMode mode, const char* op) const;
  void count(XuClass cls, Cycle start);

  TmConfig config_;
  std::vector<Unit> units_;  // indexed by XuClass
  Unit box_;
  Unit triangle_;
  ModeTimeline timeline_;
  PipelineMode mode_ = PipelineMode::kGeneral;
  Cycle usable_at_ = 0;    // first cycle of the current mode
  Cycle fused_drain_ = 0;  // when the last fused op issued so far has left its pipeline
  Cycle window_base_ = 0;  // oldest cycle the calendars remember
  Cycle history_;
  Cycle floor_ = ~Cycle{0};
  XuStats stats_;
};

}  // namespace strata::tm
