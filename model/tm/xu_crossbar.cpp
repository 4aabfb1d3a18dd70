#include "model/tm/xu_crossbar.h"

#include "tlm/clock.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace strata::tm {

static_assert(std::is_same_v<Cycle, transport::Cycle>, "model/tm/cycle.h must match tlm/clock.h");

namespace {

const TmConfig& validated(const TmConfig& config) {
  config.validate();
  return config;
}

// A booking that would fall past a calendar's window: the horizon is too short for the run.
[[noreturn]] void beyond_window_error(const char* unit) {
  throw std::runtime_error(std::string("XuCrossbar: ") + unit +
                           " bookings reach beyond the calendar window; raise TmConfig::xu_horizon_cycles "
                           "or call retire_before() as global time advances");
}

constexpr unsigned kMul = 0;  // GeneralUnits indices
constexpr unsigned kAdd = 1;

}  // namespace

XuCrossbar::Unit XuCrossbar::make_unit(const char* name, const XuUnitConfig& c, int reconfigurable,
                                       uint32_t horizon) {
  return Unit{transport::ReservationCalendar(c.count, horizon), name, c.count, c.latency,
              c.pipelined ? 1u : c.latency, reconfigurable};
}

// A fused pipeline is issue_width lanes, each taking one op per initiation interval.
XuCrossbar::Unit XuCrossbar::make_pipeline(const char* name, const FusedPipelineConfig& c, uint32_t horizon) {
  return Unit{transport::ReservationCalendar(c.issue_width, horizon), name, c.issue_width, c.latency,
              c.initiation_interval, -1};
}

XuCrossbar::XuCrossbar(const TmConfig& config)
    : config_(validated(config)),
      box_(make_pipeline("box pipeline", config.pipelines.box, config.xu_horizon_cycles)),
      triangle_(make_pipeline("triangle pipeline", config.pipelines.triangle, config.xu_horizon_cycles)),
      timeline_(GeneralUnits{config.xu.fp_mul.count, config.xu.fp_add.count}),
      history_(config.xu_history_cycles) {
  const uint32_t h = config.xu_horizon_cycles;
  const XuConfig& xu = config.xu;
  units_.reserve(kXuClassCount);
  // In XuClass order.
  units_.push_back(make_unit("fp_mul", xu.fp_mul, kMul, h));
  units_.push_back(make_unit("fp_add", xu.fp_add, kAdd, h));
  units_.push_back(make_unit("fp_cmp", xu.fp_cmp, -1, h));
  units_.push_back(make_unit("fp_div", xu.fp_div, -1, h));
  units_.push_back(make_unit("fp_inv_sqrt", xu.fp_inv_sqrt, -1, h));
  units_.push_back(make_unit("int_mul", xu.int_mul, -1, h));
  units_.push_back(make_unit("int_div", xu.int_div, -1, h));
}

// ---- Booking ----

bool XuCrossbar::fits(const Unit& u, Cycle c, Cycle& retry) const {
  const Cycle window_end = u.calendar.base() + u.calendar.horizon();
  if (c + u.occupancy > window_end) beyond_window_error(u.name);
  // A reconfigurable op needs a unit that stays general for as long as the op is in it.
  const uint32_t capacity =
      u.reconfigurable < 0 ? u.count
                           : timeline_.general_units(static_cast<unsigned>(u.reconfigurable), c, c + u.latency);
  for (Cycle t = c; t < c + u.occupancy; ++t) {
    if (u.calendar.used(t) >= capacity) {
      // With a fixed capacity no start up to t can fit; with a mode-dependent one a later
      // start may see more units, so try the next cycle.
      retry = u.reconfigurable < 0 ? t + 1 : c + 1;
      return false;
    }
  }
  return true;
}

Cycle XuCrossbar::find(const Unit& u, Cycle from) const {
  Cycle c = std::max(from, u.calendar.base());
  Cycle retry = c;
  if (u.reconfigurable < 0) {
    // A fixed capacity: an op fits where its occupancy finds room in every cycle, which the
    // calendar's full-cycle bits answer a word at a time (a busy divider has a long backlog).
    const Cycle f = u.calendar.first_gap(c, u.occupancy);
    if (f == transport::ReservationCalendar::kNone)
      beyond_window_error(u.name);
    return f;
  }
  if (u.occupancy != 1) {
    while (!fits(u, c, retry)) c = retry;
    return c;
  }
  // A pipelined reconfigurable unit: its capacity is piecewise constant, changing only where
  // an op's [start, start + latency) meets a mode change. Inside a stretch of one capacity the
  // calendar scans for the first cycle below it; only the few starts that straddle a change
  // are tried one by one (fits()). Same answer as trying every cycle, without the cost.
  const unsigned k = static_cast<unsigned>(u.reconfigurable);
  const Cycle window_end = u.calendar.base() + u.calendar.horizon();
  for (;;) {
    const Cycle change = timeline_.settled_at(c) ? window_end : std::min(window_end, timeline_.next_change_after(c));
    if (c + u.latency <= change) {
      // Starts in [c, change - latency] all see one segment's capacity.
      const Cycle stop = change - u.latency + 1;
      const Cycle f = u.calendar.first_below(c, timeline_.general_units(k, c, c + u.latency), stop);
      if (f != transport::ReservationCalendar::kNone) return f;
      c = stop;
      if (c >= window_end)
        beyond_window_error(u.name);
    }
    if (fits(u, c, retry)) return c;  // a start whose op straddles a change (fits throws past the window)
    c = retry;
  }
}

void XuCrossbar::book(Unit& u, Cycle start) {
  // fits() checked every cycle has room, so each booking lands exactly where asked.
  for (Cycle t = start; t < start + u.occupancy; ++t)
    if (u.calendar.book(t, 1).first != t) throw std::logic_error(std::string("XuCrossbar: booking moved on ") + u.name);
}

Cycle XuCrossbar::place(Unit& u, Cycle from) {
  const Cycle c = std::max(from, u.calendar.base());
  const bool full_capacity =
      u.reconfigurable < 0 ||
      (timeline_.settled_at(c) && timeline_.current().general[static_cast<unsigned>(u.reconfigurable)] == u.count);
  if (u.occupancy == 1 && full_capacity) {
    // Every unit usable from c on: the calendar's own search (which skips full cycles a
    // word at a time) gives the answer.
    const Cycle start = u.calendar.book(c, 1).first;
    if (start >= u.calendar.base() + u.calendar.horizon())
      beyond_window_error(u.name);
    return start;
  }
  if (u.occupancy == 1 && timeline_.settled_at(c)) {
    // The current mode holds from c on, so the capacity is one number: the calendar finds the
    // first cycle below it, skipping the backlog it already knows (box mode leaves few
    // general units, and a TM's TPs queue long behind them).
    const Cycle start =
        u.calendar.book_below(c, timeline_.current().general[static_cast<unsigned>(u.reconfigurable)]);
    if (start == transport::ReservationCalendar::kNone)
      beyond_window_error(u.name);
    return start;
  }
  const Cycle start = find(u, c);
  book(u, start);
  return start;
}

void XuCrossbar::count(XuClass cls, Cycle start) {
  XuUse& use = stats_.by_mode[static_cast<unsigned>(timeline_.mode_at(start))][static_cast<unsigned>(cls)];
  ++use.ops;
  use.busy_unit_cycles += unit(cls).occupancy;
}

void XuCrossbar::slide_window_slow(Cycle earliest) {
  // Slide in steps of history_ rather than every cycle: retiring touches every calendar. The
  // window never passes the floor (the oldest cycle a user may still ask for) unless a
  // request would otherwise fall beyond the horizon.
  if (earliest < window_base_) {
    ++stats_.late_requests;
    return;
  }
  if (earliest < window_base_ + 2 * history_) return;
  const Cycle wanted = earliest - history_;
  // Bookings reach at most an occupancy (<= horizon / 16, validated) past their start.
  const Cycle room = Cycle{config_.xu_horizon_cycles} - Cycle{config_.xu_horizon_cycles} / 8;
  const Cycle must = earliest > room ? earliest - room : 0;
  retire_to(std::max(std::min(wanted, floor_), must));
}

void XuCrossbar::retire_before(Cycle now) {
  // In steps of history_, as the window slides by itself: retiring touches every calendar,
  // and the TM calls this after every wait for global time. No user asks for a cycle before
  // the floor, so a window base up to history_ behind it times every request the same.
  const Cycle to = std::min(now, floor_);
  if (to < window_base_ + history_) return;
  retire_to(to);
}

void XuCrossbar::retire_to(Cycle now) {
  if (now <= window_base_) return;
  window_base_ = now;
  for (Unit& u : units_) u.calendar.retire_before(now);
  box_.calendar.retire_before(now);
  triangle_.calendar.retire_before(now);
  timeline_.forget_before(now);
}

// ---- General operations ----

Cycle XuCrossbar::issue_general(XuClass cls, Cycle earliest) {
  slide_window(earliest);
  const Cycle start = place(unit(cls), earliest);
  count(cls, start);
  return start;
}

Cycle XuCrossbar::issue_fused_multiply_add(Cycle earliest) {
  slide_window(earliest);
  Unit& mul = unit(XuClass::kFpMul);
  Unit& add = unit(XuClass::kFpAdd);
  // The first start with a multiplier free then and an adder free mul.latency later. An adder
  // found only at a > m + latency rules out every start before a - latency: skip to there.
  Cycle c = earliest;
  for (;;) {
    const Cycle m = find(mul, c);
    const Cycle a = find(add, m + mul.latency);
    if (a == m + mul.latency) {
      book(mul, m);
      book(add, a);
      count(XuClass::kFpMul, m);
      count(XuClass::kFpAdd, a);
      ++stats_.fused_multiply_adds;
      return m;
    }
    c = a - mul.latency;
  }
}

uint32_t XuCrossbar::general_units(XuClass cls, Cycle c) const {
  const Unit& u = unit(cls);
  return u.reconfigurable < 0 ? u.count : timeline_.general_units(static_cast<unsigned>(u.reconfigurable), c, c + 1);
}

// ---- Fused operations ----

void XuCrossbar::require_mode(PipelineMode mode, const char* op) const {
  if (mode_ != mode)
    throw std::logic_error(std::string("XuCrossbar: ") + op + " issued while the XUs are in " + mode_name(mode_) +
                           " mode; the firmware must configure the " + mode_name(mode) +
                           " pipeline first (the StrataHook should have trapped it)");
}

Cycle XuCrossbar::issue_box_test(Cycle earliest) {
  require_mode(PipelineMode::kBox, "strata.boxtest");
  slide_window(earliest);
  const Cycle start = place(box_, std::max(earliest, usable_at_));
  fused_drain_ = std::max(fused_drain_, start + box_.latency);
  ++stats_.box_tests;
  stats_.box_busy_cycles += box_.occupancy;
  return start;
}

Cycle XuCrossbar::issue_triangle_test(Cycle earliest) {
  require_mode(PipelineMode::kTriangle, "strata.tritest");
  slide_window(earliest);
  const Cycle start = place(triangle_, std::max(earliest, usable_at_));
  fused_drain_ = std::max(fused_drain_, start + triangle_.latency);
  ++stats_.triangle_tests;
  stats_.triangle_busy_cycles += triangle_.occupancy;
  return start;
}

Cycle XuCrossbar::issue_triangle_divide(Cycle earliest) {
  require_mode(PipelineMode::kTriangle, "strata.tridiv");
  slide_window(earliest);
  const Cycle start = place(unit(XuClass::kFpDiv), std::max(earliest, usable_at_));
  // It reads the triangle pipeline's latched partial result, so it holds the mode too.
  fused_drain_ = std::max(fused_drain_, start + config_.pipelines.triangle_divide_latency);
  count(XuClass::kFpDiv, start);
  ++stats_.triangle_divides;
  return start;
}

// ---- Reconfiguration ----

GeneralUnits XuCrossbar::taken_by(PipelineMode mode) const {
  switch (mode) {
    case PipelineMode::kBox: return {config_.pipelines.box.multipliers, config_.pipelines.box.adders};
    case PipelineMode::kTriangle: return {config_.pipelines.triangle.multipliers, config_.pipelines.triangle.adders};
    default: return {0, 0};
  }
}

Cycle XuCrossbar::drain_end(const Unit& u, uint32_t keep, Cycle from) const {
  // An op booked in cycle c holds its unit until c + tail: a pipelined op until its result
  // leaves (latency), a non-pipelined one is booked in every cycle it holds the unit.
  const Cycle tail = u.latency - u.occupancy + 1;
  const Cycle lo = std::max(u.calendar.base(), from >= tail ? from - tail + 1 : 0);
  for (Cycle c = u.calendar.backlog_end(); c > lo;) {
    --c;
    if (u.calendar.used(c) > keep) return std::max(from, c + tail);
  }
  return from;
}

Cycle XuCrossbar::configure(PipelineMode mode, Cycle earliest) {
  if (mode >= PipelineMode::kCount) throw std::invalid_argument("XuCrossbar::configure: invalid mode");
  slide_window(earliest);
  if (mode == mode_) return std::max(earliest, usable_at_);

  // The fused units are chosen nested (a pipeline takes units from the top of the index
  // range), so during a switch the units of the larger of the two pipelines are out of
  // general use, and the rest keep working throughout.
  const GeneralUnits taken_old = taken_by(mode_);
  const GeneralUnits taken_new = taken_by(mode);
  GeneralUnits during{};
  GeneralUnits after{};
  Cycle start = std::max({earliest, usable_at_, fused_drain_});
  for (unsigned k : {kMul, kAdd}) {
    const Unit& u = unit(k == kMul ? XuClass::kFpMul : XuClass::kFpAdd);
    during[k] = u.count - std::max(taken_old[k], taken_new[k]);
    after[k] = u.count - taken_new[k];
    start = drain_end(u, during[k], start);
  }
  const Cycle usable = start + config_.pipelines.reconfigure_cycles;
  timeline_.switch_to(mode, start, usable, during, after);

  stats_.mode_cycles[static_cast<unsigned>(mode_)] += start - usable_at_;
  stats_.reconfiguring_cycles += config_.pipelines.reconfigure_cycles;
  ++stats_.reconfigurations;
  mode_ = mode;
  usable_at_ = usable;
  return usable;
}

XuStats XuCrossbar::stats(Cycle now) const {
  XuStats s = stats_;
  if (now > usable_at_) s.mode_cycles[static_cast<unsigned>(mode_)] += now - usable_at_;
  return s;
}

uint64_t XuCrossbar::overflow_bookings() const {
  uint64_t n = box_.calendar.overflow_bookings() + triangle_.calendar.overflow_bookings();
  for (const Unit& u : units_) n += u.calendar.overflow_bookings();
  return n;
}

}  // namespace strata::tm
