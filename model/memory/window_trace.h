// VCD tracing of a module's key state per time window: rates (bytes, accesses, misses per
// cycle over the window) and levels (queue depth, occupancy). sc_trace samples plain doubles
// by reference, so no sc_signal and no per-cycle process exists; the module updates the
// values lazily when an access arrives in a later window. When tracing is off, a module pays
// one predictable branch per access.
#pragma once

#include "tlm/clock.h"

#include <systemc>

#include <cstdint>
#include <string>
#include <vector>

namespace strata::memory {

// How a VCD samples: one value per window of `cycles`, and only for windows starting in
// [start, end), so a big run's trace can be limited to the part of interest.
struct TraceWindow {
  TraceWindow(transport::Cycle window_cycles = 1000, transport::Cycle first = 0,
              transport::Cycle last = ~transport::Cycle{0})
      : cycles(window_cycles), start(first), end(last) {}
  transport::Cycle cycles;
  transport::Cycle start, end;
};

class WindowTrace {
 public:
  // Declare what is traced (before open); returns the index to update it by.
  std::size_t add_rate(std::string name);   // published as amount per cycle over a window
  std::size_t add_level(std::string name);  // published as the last value set in a window

  // Registers every declared value with the trace file; call before sc_start.
  void open(sc_core::sc_trace_file* file, const std::string& prefix, const TraceWindow& window);
  bool enabled() const { return window_ != 0; }

  // Both take the global cycle (not the request's), so windows follow simulated time.
  void count(std::size_t index, uint64_t amount, transport::Cycle now) {
    roll(now);
    accumulated_[index] += amount;
  }
  void level(std::size_t index, double value, transport::Cycle now) {
    roll(now);
    pending_level_[index] = value;
  }
  double published(std::size_t index) const { return published_[index]; }

 private:
  void roll(transport::Cycle now);

  std::vector<std::string> names_;
  std::vector<bool> is_rate_;
  std::vector<double> published_;  // traced by reference: never resized after open()
  std::vector<uint64_t> accumulated_;
  std::vector<double> pending_level_;
  transport::Cycle window_ = 0;
  transport::Cycle start_ = 0, end_ = 0;
  transport::Cycle window_start_ = 0;
};

}  // namespace strata::memory
