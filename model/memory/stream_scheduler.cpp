#include "model/memory/stream_scheduler.h"

namespace strata::memory {

StreamScheduler::StreamScheduler(uint32_t treelets, uint32_t capacity, uint32_t tms, SchedulingPolicy policy,
                                 bool sticky)
    : policy_(policy), sticky_(sticky), size_(treelets, 0), assigned_(tms, kNone) {
  if (policy_ == SchedulingPolicy::kFullestFirst) {
    bucket_head_.assign(uint64_t{capacity} + 1, kNone);
    next_.assign(treelets, kNone);
    prev_.assign(treelets, kNone);
  } else {
    ring_next_.assign(treelets, kNone);
    ring_prev_.assign(treelets, kNone);
  }
}

void StreamScheduler::bucket_insert(uint32_t t, uint32_t size) {
  const uint32_t h = bucket_head_[size];
  next_[t] = h;
  prev_[t] = kNone;
  if (h != kNone) prev_[h] = t;
  bucket_head_[size] = t;
  if (size > largest_) largest_ = size;
}

void StreamScheduler::bucket_remove(uint32_t t, uint32_t size) {
  if (prev_[t] != kNone) next_[prev_[t]] = next_[t];
  else bucket_head_[size] = next_[t];
  if (next_[t] != kNone) prev_[next_[t]] = prev_[t];
}

void StreamScheduler::ring_insert(uint32_t t) {
  if (cursor_ == kNone) {
    ring_next_[t] = ring_prev_[t] = t;
    cursor_ = t;
    return;
  }
  // Just before the cursor: the new buffer's turn comes after every waiting one.
  const uint32_t before = ring_prev_[cursor_];
  ring_next_[before] = t;
  ring_prev_[t] = before;
  ring_next_[t] = cursor_;
  ring_prev_[cursor_] = t;
}

void StreamScheduler::ring_remove(uint32_t t) {
  if (ring_next_[t] == t) {
    cursor_ = kNone;
  } else {
    ring_next_[ring_prev_[t]] = ring_next_[t];
    ring_prev_[ring_next_[t]] = ring_prev_[t];
    if (cursor_ == t) cursor_ = ring_next_[t];
  }
  ring_next_[t] = ring_prev_[t] = kNone;
}

void StreamScheduler::resized(uint32_t treelet, uint32_t old_size, uint32_t new_size) {
  size_[treelet] = new_size;
  if (old_size == 0 && new_size > 0) ++nonempty_;
  if (old_size > 0 && new_size == 0) --nonempty_;
  if (policy_ == SchedulingPolicy::kFullestFirst) {
    if (old_size > 0) bucket_remove(treelet, old_size);
    if (new_size > 0) bucket_insert(treelet, new_size);
    // Sizes move by one and the treelet is already in its new bucket, so the largest
    // non-empty bucket is at most one step down.
    while (largest_ > 0 && bucket_head_[largest_] == kNone) --largest_;
  } else {
    if (old_size == 0 && new_size > 0) ring_insert(treelet);
    if (old_size > 0 && new_size == 0) ring_remove(treelet);
  }
}

uint32_t StreamScheduler::assign(uint32_t tm) {
  const uint32_t current = assigned_[tm];
  if (sticky_ && current != kNone && size_[current] > 0) return current;
  uint32_t chosen = kNone;
  if (policy_ == SchedulingPolicy::kFullestFirst) {
    chosen = fullest();
  } else if (cursor_ != kNone) {
    chosen = cursor_;
    cursor_ = ring_next_[cursor_];
  }
  assigned_[tm] = chosen;
  return chosen;
}

}  // namespace strata::memory
