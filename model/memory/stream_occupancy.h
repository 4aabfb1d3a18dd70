// Where the rays are over the frame: the stream memory hands in its levels after every push
// and pop, and this keeps their time-weighted means, the peak in flight, and a coarse history
// from which the steady state before the drain is read.
//
//   in flight   rays stored + rays held by threads (a popped ray's credit, stream_sram.h)
//   stored      rays waiting in the buffers
//   non-empty   buffers holding at least one ray
//
// A level holds from the cycle of the operation that set it to the next operation's. Cycles
// are clamped to be non-decreasing (loosely timed without timing.sync_shared_ops may deliver
// an operation a few cycles before one already seen). Every level is 0 from cycle 0 to the
// first operation; the means run to the frame's end (summary()).
//
// Steady state. P is the peak in flight: the highest level held for at least one cycle. The
// steady span runs from the first moment the level reaches 0.9 P to the last moment it is at
// or above 0.9 P (after which it stays below: the drain); the steady state is the
// time-weighted mean in flight over that span, so the fill at the start and the drain at the
// end are left out and dips inside the span are kept. The span is read from a history of at
// most kMaxBins bins of equal width (the width doubles, and neighbours merge, when the frame
// outgrows them), so its ends are known to one bin: within frame cycles / kMaxBins x 2.
//
// Per operation: a few adds, and a walk over the bins the last level spanned (one, but for
// idle stretches); the history is allocated once, at construction.
#pragma once

#include "tlm/clock.h"

#include <cstdint>
#include <vector>

namespace strata::memory {

class StreamOccupancy {
 public:
  using Cycle = transport::Cycle;
  static constexpr uint32_t kMaxBins = 4096;
  static constexpr Cycle kFirstBinCycles = 16;
  static constexpr double kSteadyShareOfPeak = 0.9;

  StreamOccupancy();

  // The levels after an operation at cycle t.
  void record(Cycle t, uint32_t in_flight, uint32_t stored, uint32_t nonempty) {
    if (t > last_) advance(t);
    in_flight_ = in_flight;
    stored_ = stored;
    nonempty_ = nonempty;
  }

  struct Summary {
    Cycle end = 0;  // the cycle the means run to
    double in_flight_mean = 0, stored_mean = 0, nonempty_mean = 0;
    double rays_per_nonempty = 0;  // stored_mean / nonempty_mean (0 when no buffer held a ray)
    uint32_t peak = 0;
    double steady_mean = 0;
    Cycle steady_begin = 0, steady_end = 0;  // the steady span [begin, end), to a bin
  };
  // Means from cycle 0 to `end` (the frame's end; at least the last operation's cycle).
  Summary summary(Cycle end) const;

 private:
  struct Bin {
    double area = 0;     // in-flight level x cycles
    uint32_t peak = 0;   // the highest in-flight level held in the bin
  };
  void advance(Cycle to);  // the current levels held over [last_, to)
  void halve_resolution();

  Cycle last_ = 0;
  uint32_t in_flight_ = 0, stored_ = 0, nonempty_ = 0;
  double in_flight_area_ = 0, stored_area_ = 0, nonempty_area_ = 0;
  uint32_t peak_ = 0;
  Cycle bin_cycles_ = kFirstBinCycles;
  std::vector<Bin> bins_;  // bin i covers [i, i + 1) x bin_cycles_
};

}  // namespace strata::memory
