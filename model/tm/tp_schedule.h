// Which TP of a TM issues next: a tournament tree over the TPs' keys (next issue cycle << 6 |
// TP index), so the earliest TP (ties: the lower index) is at the root, an update costs one
// min per level, and the runner-up is the least sibling along the winner's path. Cheaper than
// a heap or a scan for the 32 TPs of a TM, and branch-free.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace strata::tm {

class TpSchedule {
 public:
  static constexpr uint64_t kDone = ~uint64_t{0};

  explicit TpSchedule(uint32_t tps) {
    while (leaves_ < tps) leaves_ *= 2;
    tree_.assign(2 * leaves_, kDone);
    for (uint32_t i = 0; i < tps; ++i) set(i, 0);
  }

  static uint64_t key(uint64_t cycle, uint32_t tp) { return (cycle << 6) | tp; }

  // TP `tp` issues next at `cycle`, or never again (done).
  void set(uint32_t tp, uint64_t cycle) { update(tp, key(cycle, tp)); }
  void done(uint32_t tp) { update(tp, kDone); }

  uint64_t top() const { return tree_[1]; }
  // The least key among all TPs but the winner.
  uint64_t runner_up() const {
    uint64_t best = kDone;
    uint32_t node = 1;
    while (node < leaves_) {
      const uint32_t left = 2 * node;
      const bool go_left = tree_[left] == tree_[node];
      best = std::min(best, go_left ? tree_[left + 1] : tree_[left]);
      node = go_left ? left : left + 1;
    }
    return best;
  }

 private:
  void update(uint32_t tp, uint64_t k) {
    uint32_t n = leaves_ + tp;
    tree_[n] = k;
    for (n /= 2; n >= 1; n /= 2) tree_[n] = std::min(tree_[2 * n], tree_[2 * n + 1]);
  }

  uint32_t leaves_ = 1;
  std::vector<uint64_t> tree_;  // [1] is the root; leaves at [leaves_, 2 * leaves_)
};

}  // namespace strata::tm
