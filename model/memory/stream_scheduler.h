// Which treelet buffer a TM works on. A TM asks (assign) when it starts and whenever its
// buffer runs dry; with `sticky` it keeps its treelet while that buffer still has rays.
//
//   kFullestFirst: the buffer with the most rays. Sizes change by one per push or pop, so
//                  treelets sit in doubly linked lists bucketed by size and the largest
//                  non-empty bucket is tracked: O(1) per push, pop and assign.
//   kRoundRobin:   non-empty buffers form a ring in the order they became non-empty, handed
//                  out in turn: O(1) as well.
// Ties in kFullestFirst go to the treelet that reached that size last.
#pragma once

#include "model/memory/config.h"

#include <cstdint>
#include <vector>

namespace strata::memory {

class StreamScheduler {
 public:
  static constexpr uint32_t kNone = 0xFFFFFFFFu;

  StreamScheduler(uint32_t treelets, uint32_t capacity, uint32_t tms, SchedulingPolicy policy, bool sticky);

  // The buffer of `treelet` went from old_size to new_size rays (by one).
  void resized(uint32_t treelet, uint32_t old_size, uint32_t new_size);
  // The TM's treelet: its current one (sticky, non-empty), else a newly chosen non-empty
  // buffer, else kNone when every buffer is empty.
  uint32_t assign(uint32_t tm);
  uint32_t assigned(uint32_t tm) const { return assigned_[tm]; }
  uint32_t tms() const { return static_cast<uint32_t>(assigned_.size()); }
  uint32_t fullest() const { return largest_ == 0 ? kNone : bucket_head_[largest_]; }
  uint32_t nonempty() const { return nonempty_; }  // buffers holding at least one ray

 private:
  void bucket_insert(uint32_t t, uint32_t size);
  void bucket_remove(uint32_t t, uint32_t size);
  void ring_insert(uint32_t t);
  void ring_remove(uint32_t t);

  SchedulingPolicy policy_;
  bool sticky_;
  std::vector<uint32_t> size_;
  std::vector<uint32_t> assigned_;
  uint32_t nonempty_ = 0;
  // kFullestFirst
  std::vector<uint32_t> bucket_head_;  // per size
  std::vector<uint32_t> next_, prev_;  // per treelet, within its bucket
  uint32_t largest_ = 0;
  // kRoundRobin
  std::vector<uint32_t> ring_next_, ring_prev_;
  uint32_t cursor_ = kNone;
};

}  // namespace strata::memory
