#include "model/memory/window_trace.h"

namespace strata::memory {

std::size_t WindowTrace::add_rate(std::string name) {
  names_.push_back(std::move(name));
  is_rate_.push_back(true);
  return names_.size() - 1;
}

std::size_t WindowTrace::add_level(std::string name) {
  names_.push_back(std::move(name));
  is_rate_.push_back(false);
  return names_.size() - 1;
}

void WindowTrace::open(sc_core::sc_trace_file* file, const std::string& prefix, const TraceWindow& window) {
  if (file == nullptr || window.cycles == 0) return;
  window_ = window.cycles;
  start_ = window.start;
  end_ = window.end;
  published_.assign(names_.size(), 0.0);
  accumulated_.assign(names_.size(), 0);
  pending_level_.assign(names_.size(), 0.0);
  for (std::size_t i = 0; i < names_.size(); ++i) sc_core::sc_trace(file, published_[i], prefix + "." + names_[i]);
}

void WindowTrace::roll(transport::Cycle now) {
  if (now < window_start_ + window_) return;
  // Outside [start, end) nothing changes in the trace, so the VCD stays small.
  const bool shown = window_start_ >= start_ && window_start_ < end_;
  for (std::size_t i = 0; i < names_.size(); ++i) {
    if (!shown) {
      accumulated_[i] = 0;
      continue;
    }
    if (is_rate_[i]) {
      published_[i] = static_cast<double>(accumulated_[i]) / static_cast<double>(window_);
      accumulated_[i] = 0;
    } else {
      published_[i] = pending_level_[i];
    }
  }
  window_start_ = now - now % window_;
}

}  // namespace strata::memory
