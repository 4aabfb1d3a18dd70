// A TM's treelet sessions (ARCHITECTURE.md, "Treelets"): what one visit of a TM to a treelet
// buffer traced, and what it loaded. The statistics that let an architect read a design's
// DRAM traffic as sessions x lines per session.
//
// A session begins when an assign returns a treelet other than the one the TM had (its
// first buffer included), and ends when an assign returns yet another treelet. An assign
// that finds every buffer empty ends nothing: the TM idles on its treelet, whose lines its
// L1 still holds, and an assign returning that treelet again continues the session (in a
// frame's drain, idle TMs flip between "none" and the one buffer that still gets rays;
// counting each return as a session made three of four sessions empty ones on Cornell).
// Its rays are the pops that took a ray from the TM's buffer meanwhile (every pop reads
// the TM's assigned buffer, and only the TM's own assigns change that); its lines are the
// L1 data lines the TM's loads filled meanwhile, whichever TP's ray they were for, by where
// the line came from:
//   l2_hit     the L2 held the line;
//   dram       the L2 missed and read the line from DRAM;
//   l2_merged  the L2 missed, but had the line on its way from DRAM for an earlier miss (no
//              second DRAM read).
// The L1 fills a line exactly when a load misses; a load merged into a fill already on its
// way fills nothing (the L1 answers it kL1Merged, and it is not counted here). Lines filled
// before the TM's first buffer are counted apart. A frame's last session of each TM is still
// open when the frame ends; the statistics count it with the rays it has.
//
// Kinds: treelets [0, node_treelets) hold BVH nodes, the rest triangles (the scene header's
// node_treelet_count; firmware/kernels/stream_ray.h, TreeletBounds).
//
// Sampled timing: every stream operation passes here, fast-forwarded or not, so sessions and
// rays count the whole sampled execution; lines are counted in the measured parts only, as
// the L1's fills are, and are extrapolated by data operations. The rays are the frame's in
// every mode, and the sessions are the sampled execution's. Its fast-forward runs each TP in
// batches, but its stream operations wait for their dates (timing.fast_forward_time_order), so
// its ray schedule is LT's within a few percent (docs/sampled-timing.md, "Treelet sessions");
// in arrival order it had 3-5x fewer, longer sessions than LT.
#pragma once

#include "model/stats/stat_group.h"
#include "tlm/memory_extension.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace strata::tm {

class TreeletSessions {
 public:
  // Rays per session: 0, then [2^k, 2^(k+1)) for k = 0 .. kBuckets - 3, then 2^(kBuckets-2)
  // or more.
  static constexpr unsigned kBuckets = 25;

  explicit TreeletSessions(uint32_t node_treelets);
  TreeletSessions(const TreeletSessions&) = delete;  // the statistics point into it
  TreeletSessions& operator=(const TreeletSessions&) = delete;

  // The treelet an assign returned (transport::kNoTreelet: every buffer was empty).
  void assigned(uint32_t treelet) {
    if (treelet == current_ || treelet == transport::kNoTreelet) return;
    close();
    current_ = treelet;
    kind_ = &kinds_[treelet < node_treelets_ ? kNode : kTriangle];
    ++kind_->sessions;
  }
  // A pop took a ray from the TM's buffer.
  void popped() {
    ++rays_popped_;
    if (kind_ == nullptr) return;  // cannot happen: before the first buffer, pops find none
    ++kind_->rays;
    ++open_rays_;
  }
  // The answer to a counted L1 data load or store: a line filled, and from where, or not.
  void answered(transport::ServedBy by) {
    using transport::ServedBy;
    if (by != ServedBy::kL2 && by != ServedBy::kDram && by != ServedBy::kL2Merged) return;
    Lines& l = kind_ != nullptr ? kind_->lines : outside_;
    ++(by == ServedBy::kL2 ? l.l2_hit : by == ServedBy::kDram ? l.dram : l.l2_merged);
  }

  const stats::Group& stats() const { return stats_; }

  static unsigned bucket_of(uint64_t rays) {
    unsigned b = 0;
    while (rays != 0 && b < kBuckets - 1) {
      rays >>= 1;
      ++b;
    }
    return b;
  }

 private:
  enum : unsigned { kNode, kTriangle };
  struct Lines {
    uint64_t l2_hit = 0, dram = 0, l2_merged = 0;
  };
  struct Kind {
    uint64_t sessions = 0, rays = 0;
    Lines lines;
  };
  void close() {
    if (current_ == transport::kNoTreelet) return;
    ++closed_[bucket_of(open_rays_)];
    open_rays_ = 0;
  }
  void register_stats();
  void register_kind(stats::Group& g, const Kind& k);

  uint32_t node_treelets_;
  uint32_t current_ = transport::kNoTreelet;  // the session's treelet (none before the first)
  Kind* kind_ = nullptr;  // the current session's kind (null before the first)
  uint64_t open_rays_ = 0;
  std::array<Kind, 2> kinds_{};
  Lines outside_{};
  uint64_t rays_popped_ = 0;
  std::array<uint64_t, kBuckets> closed_{};    // sessions ended, by rays
  std::array<uint64_t, kBuckets> reported_{};  // ... and the open one, as of the last snapshot

  stats::Group stats_;
  std::vector<std::unique_ptr<stats::Group>> groups_;  // the sub-groups
};

}  // namespace strata::tm
