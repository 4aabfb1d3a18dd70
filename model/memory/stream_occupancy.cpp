#include "model/memory/stream_occupancy.h"

#include <algorithm>

namespace strata::memory {

StreamOccupancy::StreamOccupancy() { bins_.reserve(kMaxBins); }

void StreamOccupancy::advance(Cycle to) {
  const double held = double(to - last_);
  in_flight_area_ += double(in_flight_) * held;
  stored_area_ += double(stored_) * held;
  nonempty_area_ += double(nonempty_) * held;
  peak_ = std::max(peak_, in_flight_);
  while (last_ < to) {
    Cycle bin = last_ / bin_cycles_;
    while (bin >= kMaxBins) {
      halve_resolution();
      bin = last_ / bin_cycles_;
    }
    if (bins_.size() <= bin) bins_.resize(bin + 1);  // within the reserved history: no allocation
    const Cycle end = std::min(to, (bin + 1) * bin_cycles_);
    Bin& b = bins_[bin];
    b.area += double(in_flight_) * double(end - last_);
    b.peak = std::max(b.peak, in_flight_);
    last_ = end;
  }
}

void StreamOccupancy::halve_resolution() {
  const size_t n = (bins_.size() + 1) / 2;
  for (size_t i = 0; i < n; ++i) {
    Bin merged = bins_[2 * i];
    if (2 * i + 1 < bins_.size()) {
      merged.area += bins_[2 * i + 1].area;
      merged.peak = std::max(merged.peak, bins_[2 * i + 1].peak);
    }
    bins_[i] = merged;
  }
  bins_.resize(n);
  bin_cycles_ *= 2;
}

StreamOccupancy::Summary StreamOccupancy::summary(Cycle end) const {
  // The levels hold on to the frame's end: a copy takes the tail, so the record goes on.
  StreamOccupancy o = *this;
  if (end > o.last_) o.advance(end);
  Summary s;
  s.end = o.last_;
  if (s.end == 0) return s;
  const double cycles = double(s.end);
  s.in_flight_mean = o.in_flight_area_ / cycles;
  s.stored_mean = o.stored_area_ / cycles;
  s.nonempty_mean = o.nonempty_area_ / cycles;
  s.rays_per_nonempty = o.nonempty_area_ > 0 ? o.stored_area_ / o.nonempty_area_ : 0.0;
  s.peak = o.peak_;
  if (s.peak == 0) return s;
  const double threshold = kSteadyShareOfPeak * double(s.peak);
  size_t first = o.bins_.size(), last = 0;
  for (size_t i = 0; i < o.bins_.size(); ++i)
    if (double(o.bins_[i].peak) >= threshold) {
      first = std::min(first, i);
      last = i;
    }
  double area = 0;
  for (size_t i = first; i <= last; ++i) area += o.bins_[i].area;
  s.steady_begin = first * o.bin_cycles_;
  s.steady_end = std::min(s.end, (last + 1) * o.bin_cycles_);
  s.steady_mean = s.steady_end > s.steady_begin ? area / double(s.steady_end - s.steady_begin) : double(s.peak);
  return s;
}

}  // namespace strata::memory
