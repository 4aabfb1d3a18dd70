// The chip has one clock (1 GHz by default). Modules reason in whole cycles and convert only
// at their sockets, where TLM speaks sc_time; this keeps calendars and counters integral.
#pragma once

#include <systemc>

#include <cstdint>
#include <stdexcept>

namespace strata::transport {

using Cycle = uint64_t;

class Clock {
 public:
  explicit Clock(const sc_core::sc_time& period = sc_core::sc_time(1, sc_core::SC_NS))
      : ticks_(period.value()) {
    if (ticks_ == 0) throw std::invalid_argument("Clock: period must be at least one time resolution unit");
  }

  // First cycle boundary at or after t: a request between two edges is served at the next.
  Cycle cycle_ceil(const sc_core::sc_time& t) const { return (t.value() + ticks_ - 1) / ticks_; }
  Cycle cycle_floor(const sc_core::sc_time& t) const { return t.value() / ticks_; }
  sc_core::sc_time time(Cycle c) const { return sc_core::sc_time::from_value(c * ticks_); }
  sc_core::sc_time duration(Cycle cycles) const { return time(cycles); }

  // The last cycle that global time has fully reached; nothing can be requested before it.
  Cycle now() const { return cycle_floor(sc_core::sc_time_stamp()); }
  // The absolute cycle of a b_transport request: global time plus its annotated delay.
  Cycle request_cycle(const sc_core::sc_time& delay) const {
    return cycle_ceil(sc_core::sc_time_stamp() + delay);
  }
  // The annotated delay that places an event at absolute cycle `at` (never negative).
  sc_core::sc_time delay_until(Cycle at) const {
    const uint64_t now = sc_core::sc_time_stamp().value();
    const uint64_t target = at * ticks_;
    return sc_core::sc_time::from_value(target > now ? target - now : 0);
  }
  uint64_t ticks_per_cycle() const { return ticks_; }

  // The same three, against one reading of global time (`stamp` = sc_time_stamp().value()):
  // a target that needs several of them per request reads the kernel's time once.
  Cycle now_at(uint64_t stamp) const { return stamp / ticks_; }
  Cycle request_cycle_at(uint64_t stamp, const sc_core::sc_time& delay) const {
    return (stamp + delay.value() + ticks_ - 1) / ticks_;
  }
  sc_core::sc_time delay_until_at(uint64_t stamp, Cycle at) const {
    const uint64_t target = at * ticks_;
    return sc_core::sc_time::from_value(target > stamp ? target - stamp : 0);
  }

 private:
  uint64_t ticks_;
};

}  // namespace strata::transport
