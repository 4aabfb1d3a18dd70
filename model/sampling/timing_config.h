// How a frame is timed: the mode (loosely timed, precise, sampled), the LT quantum and TP slack,
// and sampled timing's windows, warming, fast-forward and error target. Bound to the config's
// `timing.*` fields by the chip (model/chip/chip_config.cpp), which also checks them against
// each other; the TMs and the window sampler read it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/stats/interval_method.h"
#include "tlm/timing_mode.h"

namespace strata::sampling {

struct TimingConfig {
  transport::TimingMode mode = transport::TimingMode::kLooselyTimed;
  uint32_t quantum_cycles = 1000;  // LT: how far a TM may run ahead of global time
  // LT: how far one TP may run ahead of the other TPs of its TM before the TM switches to the
  // earliest one. Larger bursts simulate faster; the XU and memory calendars still see every
  // request at its own cycle.
  uint32_t tp_slack_cycles = 32;
  // LT: a stream-memory or global-register operation waits until global time reaches its
  // cycle, so the ray buffers, the treelet assignments and the global registers change in
  // time order, as in precise mode. Off, they change in arrival order: a TM a quantum ahead
  // drains the fullest buffer before the others ask, so TMs spread over treelets instead of
  // sharing the fullest one, and LT shows fewer L1 misses than precise
  // (docs/memory-system.md, "Where LT differs").
  bool sync_shared_ops = true;
  // Sampled: every sample_period_cycles, sample_detail_cycles run loosely timed; the rest of
  // the period fast-forwards functionally at each TM's measured cycles per instruction. The
  // first sample_warmup_cycles of a detailed window refill the scoreboards and calendars
  // and are not measured. docs/sampled-timing.md.
  uint32_t sample_period_cycles = 100000;
  uint32_t sample_detail_cycles = 20000;
  uint32_t sample_warmup_cycles = 8000;
  // Sampled: the frame's two ends, where its rates change fastest, are strata of their own,
  // timed in full and estimated apart from the sampled middle (window_sampler.h,
  // docs/sampled-timing.md "Head and drain strata"). The head: the first sample_head_periods
  // configured periods (0: none), cold caches and the first camera rays, whose windows skewed
  // STRaTA's DRAM estimate when they were sampled like the middle. The drain: from the first window after every
  // pixel has been handed out and the pixels left to finish have fallen to sample_drain_share
  // of the frame's (0: none), where the rays in flight run out.
  uint32_t sample_head_periods = 4;
  double sample_drain_share = 0.25;
  // Sampled: during fast-forward, replay every load and store as a tag update of the L1 data
  // cache and the L2 (no time, no counts), so a detailed window starts from warm caches.
  bool functional_warming = true;
  // Sampled: how far past the TM's runner-up TP one fast-forward batch of a TP may run, in
  // quanta (it never runs into a detailed window). A TP advances by about this much per batch,
  // so longer batches pay the per-batch costs (switching TPs, reloading the TP's state into
  // the host's caches) less often, but reorder the stream operations over a longer stretch.
  // 16 is as accurate against LT as shorter batches, and faster (docs/sampled-timing.md,
  // "Fast-forward batch length", has the measurement).
  uint32_t fast_forward_batch_quanta = 16;
  // Sampled: a fast-forwarded TP's stream and global-register operations wait, as in LT with
  // sync_shared_ops, until global time reaches the cycle the measured rates date them at, so
  // the ray buffers and treelet assignments change in time order through the whole frame.
  // Off, they change in arrival order (a TM up to the batch length ahead): faster, but the
  // buffers then hold more rays per treelet than LT's, the detailed windows inherit them, and
  // STRaTA's L1 misses, L2 accesses and DRAM bytes come out low (docs/sampled-timing.md,
  // "The fast-forward's ray schedule").
  bool fast_forward_time_order = true;
  // Sampled: charge a fast-forwarded stream or global-register op the mean latency measured for
  // its kind of outcome (assign found/none, pop ray/empty, push stored/full, global), not the
  // mean over all of them (tm_sampler.h, OpClass).
  bool fast_forward_op_classes = true;
  // Sampled: 0, or the relative half-width (e.g. 0.02) the 95% intervals of the statistics
  // sample_target_stats names should reach; the sampler then chooses the period itself
  // (window_sampler.h).
  double sample_target_error = 0.0;
  // Comma-separated statistics the target holds for: counts or formulas over counts. By default
  // the figures a design comparison reads: frame time, DRAM bytes and L2 accesses (DRAM varies
  // far more between windows than cycles do, so a target on cycles alone leaves it wide).
  std::string sample_target_stats = "frame.cycles,memory.dram.bytes,memory.l2.accesses";
  // Sampled: how the batches' replicates become an interval (model/stats/interval_method.h).
  // "successive" (differences of neighbouring batches) follows the frame's trends, as windows
  // spread evenly over it do; "jackknife" treats the batches as exchangeable and counts a trend
  // as variance, so STRaTA's DRAM intervals stay wide whatever the windows
  // (docs/sampled-timing.md, "Trends and the interval").
  stats::IntervalMethod sample_interval = stats::IntervalMethod::kSuccessiveDifferences;
  // Sampled: the least relative error the frame time's interval allows the simulated clock
  // beside the batches' spread (docs/sampled-timing.md, "The clock's error in the interval").
  // The clock's error against LT is not visible inside a run; its disagreement with the
  // samples' own estimate is, and the larger of the two is added. 0.025: the largest clock
  // error measured against LT on 11 frames, 128x128 to 512x512, was 2.34%.
  double sample_clock_bound = 0.025;
};

// timing.sample_target_stats's entries, trimmed; an empty or a repeated entry throws
// std::invalid_argument naming the field (the window sampler checks the names against the tree).
std::vector<std::string> sample_target_list(const std::string& list);

}  // namespace strata::sampling
