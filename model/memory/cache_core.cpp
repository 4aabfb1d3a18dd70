#include "model/memory/cache_core.h"

namespace strata::memory {

CacheCore::CacheCore(const CacheGeometry& g)
    : banks_(g.banks), line_bytes_(g.line_bytes), ways_(g.ways), sets_(g.size_bytes / g.line_bytes / g.ways),
      interleave_(g.banks, g.hash_banks) {
  while ((1u << line_shift_) != line_bytes_) ++line_shift_;
  const std::size_t lines = std::size_t{sets_} * ways_;
  tag_.assign(lines, 0);
  ready_.assign(lines, 0);
  requested_.assign(lines, 0);
  shadow_line_.assign(sets_, 0);
  shadow_until_.assign(sets_, 0);
  lru_.assign(lines, 0);
  dirty_.assign(lines, 0);
  data_.assign(lines, transport::DataClass::kOther);
  bank_calendars_.reserve(banks_);
  for (uint32_t b = 0; b < banks_; ++b) bank_calendars_.emplace_back(1, g.horizon_cycles);
}

uint32_t CacheCore::victim(uint32_t set) const {
  const uint32_t base = set * ways_;
  uint32_t best = 0;
  for (uint32_t w = 0; w < ways_; ++w) {
    if (tag_[base + w] == 0) return w;
    if (lru_[base + w] < lru_[base + best]) best = w;
  }
  return best;
}

CacheCore::Lookup CacheCore::classify(uint32_t set, uint64_t line, Cycle slot, Cycle answer) {
  const int found = find(set, line);
  if (found == kMiss) {
    if (shadow_line_[set] == line + 1 && slot < shadow_until_[set]) return {Outcome::kShadowHit, kMiss, answer};
    return {Outcome::kMiss, kMiss, 0};
  }
  const uint32_t i = set * ways_ + static_cast<uint32_t>(found);
  if (ready_[i] <= answer) return {Outcome::kHit, found, answer};
  if (requested_[i] <= slot) return {Outcome::kMerged, found, ready_[i]};
  // The fill was requested by an access later than this one: this one would have missed
  // first. Same latency from its own slot, and the line arrives that much earlier.
  const Cycle done = slot + (ready_[i] - requested_[i]);
  ready_[i] = done;
  requested_[i] = slot;
  return {Outcome::kTimeShifted, found, done};
}

void CacheCore::install(uint32_t set, uint32_t way, uint64_t line, Cycle slot, Cycle ready, bool dirty,
                        transport::DataClass data) {
  const uint32_t i = set * ways_ + way;
  if (tag_[i] != 0) {
    shadow_line_[set] = tag_[i];
    shadow_until_[set] = slot;
  }
  tag_[i] = line + 1;
  ready_[i] = ready;
  requested_[i] = slot;
  dirty_[i] = dirty ? 1 : 0;
  data_[i] = data;
  lru_[i] = ++use_clock_;
}

bool CacheCore::warm(uint32_t set, uint64_t line, bool store, bool allocate, transport::DataClass data) {
  const int found = find(set, line);
  if (found != kMiss) {
    const uint32_t way = static_cast<uint32_t>(found);
    touch(set, way);
    if (store) set_dirty(set, way);
    return true;
  }
  if (!allocate) return false;
  const uint32_t i = set * ways_ + victim(set);
  tag_[i] = line + 1;
  ready_[i] = 0;
  requested_[i] = 0;
  dirty_[i] = store ? 1 : 0;
  data_[i] = data;
  lru_[i] = ++use_clock_;
  return false;
}

uint64_t CacheCore::overflow_bookings() const {
  uint64_t n = 0;
  for (const auto& c : bank_calendars_) n += c.overflow_bookings();
  return n;
}

}  // namespace strata::memory
