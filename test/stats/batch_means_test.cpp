// Sampled timing's confidence intervals (model/stats/batch_means.h, student_t.h) on a small
// statistics tree whose windows the test writes by hand, so every interval can be computed
// here independently.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "model/stats/batch_means.h"
#include "model/stats/student_t.h"

namespace strata::stats {
namespace {

TEST(StudentT, QuantilesMatchTheTables) {
  EXPECT_NEAR(normal_quantile(0.975), 1.959964, 1e-6);
  EXPECT_NEAR(normal_quantile(0.5), 0.0, 1e-9);
  // Two-sided 95%: t(0.975, dof), from the standard tables.
  const std::pair<unsigned, double> table[] = {{1, 12.7062}, {2, 4.3027}, {3, 3.1824}, {4, 2.7764},
                                               {9, 2.2622}, {30, 2.0423}, {120, 1.9799}};
  for (const auto& [dof, t] : table) EXPECT_NEAR(student_t_quantile(0.975, dof), t, 1e-4) << dof;
  EXPECT_NEAR(student_t_quantile(0.995, 10), 3.1693, 1e-4);
  EXPECT_NEAR(student_t_quantile(0.025, 5), -2.5706, 1e-4);
  EXPECT_THROW(student_t_quantile(0.975, 0), std::domain_error);
  EXPECT_THROW(normal_quantile(1.0), std::domain_error);
}

// A frame in miniature: `retired` and `rays` are exact totals; `misses` is extrapolated by
// the measured-instructions basis; `hit_rate` is a ratio and `per_ray` a formula.
struct Tree {
  uint64_t retired = 0, rays = 0, measured = 0, misses = 0, hits = 0;
  Group root{"chip", "test"};
  Group sampling{"sampling", "measured denominators", Basis::kExact};
  Group memory{"memory", "extrapolated", Basis::kMeasuredInstructions};
  Tree() {
    root.count("retired", &retired, Unit::kCount, "exact", Basis::kExact);
    root.count("rays", &rays, Unit::kCount, "exact", Basis::kExact);
    sampling.count("measured_instructions", &measured, Unit::kCount, "measured");
    memory.count("misses", &misses, Unit::kCount, "m");
    memory.count("hits", &hits, Unit::kCount, "h");
    memory.ratio("hit_rate", "hits", {"hits", "misses"}, "r");
    memory.derived("misses_per_ray", Unit::kRatio, "f",
                   [](const Scope& s) { return s.self().number("misses") / s.root().number("rays"); });
    root.child(&sampling);
    root.child(&memory);
  }
};

bool measured(const std::string& path, const Values::Stat& s) {
  return s.basis != Basis::kExact || path.compare(0, 9, "sampling.") == 0;
}

// What the report does with a tree: extrapolate `misses` and `hits` by retired / measured.
void finish(Values& v) {
  Factors f;
  f[Basis::kMeasuredInstructions] = v.number("retired") / v.number("sampling.measured_instructions");
  v.scale(f);
  v.derive();
}

TEST(BatchMeans, JackknifeOverWindowsMatchesAHandComputation) {
  Tree t;
  BatchMeans b(&measured, 32);
  const uint64_t m[] = {100, 120, 80, 100, 110};
  const uint64_t x[] = {10, 15, 6, 9, 12};
  for (int i = 0; i < 5; ++i) {
    t.retired += 1000;
    t.rays += 7;
    t.measured += m[i];
    t.misses += x[i];
    t.hits += 3 * x[i];
    b.add_window(Values::snapshot(t.root));
  }
  const Values total = Values::snapshot(t.root);
  EXPECT_EQ(b.windows(), 5u);
  EXPECT_EQ(b.batches(total), 5u);  // nothing after the last window: no tail
  const auto hw = b.half_widths(total,
                                [](Values r) {
                                  finish(r);
                                  return std::vector<double>{r.number("memory.misses"), r.number("rays"),
                                                             r.number("memory.misses_per_ray")};
                                },
                                0.95);
  ASSERT_EQ(hw.size(), 3u);
  // By hand: each replicate drops one window's misses and measured instructions.
  double reps[5], mean = 0;
  for (int i = 0; i < 5; ++i) {
    const double xs = 52 - double(x[i]), ms = 510 - double(m[i]);
    reps[i] = double(std::llround(xs * 5000.0 / ms));  // integer counts are rounded when scaled
    mean += reps[i] / 5;
  }
  double ss = 0;
  for (double r : reps) ss += (r - mean) * (r - mean);
  const double expected = student_t_quantile(0.975, 4) * std::sqrt(ss * 4 / 5);
  EXPECT_NEAR(hw[0], expected, 1e-9);
  EXPECT_GT(hw[0], 0.0);
  EXPECT_EQ(hw[1], 0.0);  // an exact total has no interval
  EXPECT_NEAR(hw[2], expected / 35.0, 1e-9);  // a formula over it: the same, per ray
}

TEST(BatchMeans, ATailAfterTheLastWindowIsOneMoreBatch) {
  Tree t;
  BatchMeans b(&measured);
  for (int i = 0; i < 3; ++i) {
    t.measured += 100;
    t.misses += 10 + i;
    b.add_window(Values::snapshot(t.root));
  }
  t.measured += 40;
  t.misses += 1;
  t.retired = 10000;
  const Values total = Values::snapshot(t.root);
  EXPECT_EQ(b.batches(total), 4u);
  // Weight 1: the weighted total is the raw total.
  const Values w = b.weighted_total(total);
  EXPECT_EQ(w.count("memory.misses"), total.count("memory.misses"));
  EXPECT_EQ(w.count("sampling.measured_instructions"), 340u);
}

// The frame's head and drain as strata (docs/sampled-timing.md, "Head and drain strata"): in no
// batch, never deleted from a replicate, and the middle's exact totals are the frame's less
// theirs, so each part can be scaled by its own ratio.
TEST(BatchMeans, TheHeadAndTheDrainAreStrataOutsideTheBatches) {
  Tree t;
  BatchMeans b(&measured);
  t.retired = 1000;  // the head: everything measured
  t.measured = 1000;
  t.misses = 50;
  b.add_head_stratum(Values::snapshot(t.root));
  EXPECT_THROW(b.add_head_stratum(Values::snapshot(t.root)), std::logic_error);
  for (int i = 0; i < 4; ++i) {  // the middle: a tenth measured
    t.retired += 1000;
    t.measured += 100;
    t.misses += 20 + i;
    b.add_window(Values::snapshot(t.root));
  }
  t.retired += 500;  // the drain, after the last window
  t.measured += 450;
  t.misses += 90;
  const Values total = Values::snapshot(t.root);
  EXPECT_EQ(b.batches(total), 5u) << "without the drain stratum the tail is a batch";
  b.set_tail_stratum(true);
  EXPECT_EQ(b.batches(total), 4u);
  const std::vector<Values> strata = b.strata(total);
  ASSERT_EQ(strata.size(), 2u);
  EXPECT_EQ(strata[0].count("retired"), 1000u);
  EXPECT_EQ(strata[0].count("memory.misses"), 50u);
  EXPECT_EQ(strata[1].count("retired"), 500u);
  EXPECT_EQ(strata[1].count("sampling.measured_instructions"), 450u);
  EXPECT_EQ(strata[1].count("memory.misses"), 90u);
  // The middle: 4,000 instructions retired, 400 measured, 86 misses.
  const Values middle = b.weighted_total(total);
  EXPECT_EQ(middle.count("retired"), 4000u);
  EXPECT_EQ(middle.count("sampling.measured_instructions"), 400u);
  EXPECT_EQ(middle.count("memory.misses"), 86u);
  // Replicates delete middle batches only: the strata's counts are in none of them.
  std::vector<std::vector<double>> replicates;
  const auto hw = b.half_widths(total,
                                [](Values r) {
                                  finish(r);
                                  return std::vector<double>{r.number("memory.misses")};
                                },
                                0.95, &replicates);
  ASSERT_EQ(hw.size(), 1u);
  ASSERT_EQ(replicates[0].size(), 4u);
  const double x[] = {20, 21, 22, 23};
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(replicates[0][i], (86 - x[i]) * 4000.0 / 300.0, 0.5) << i;  // integer counts round
}

TEST(BatchMeans, FullBatchesMergeSoMemoryStaysBounded) {
  Tree t;
  BatchMeans b(&measured, 4);
  for (int i = 0; i < 37; ++i) {
    t.measured += 100;
    t.misses += 10 + (i % 3);
    b.add_window(Values::snapshot(t.root));
  }
  const Values total = Values::snapshot(t.root);
  EXPECT_EQ(b.windows(), 37u);
  // 4 full batches at most, plus the one filling: 37 windows in batches of 8 -> 4 full + 5.
  EXPECT_LE(b.batches(total), 5u);
  EXPECT_GE(b.batches(total), 3u);
  const Values w = b.weighted_total(total);
  EXPECT_EQ(w.count("memory.misses"), total.count("memory.misses"));  // nothing lost in merging
  EXPECT_EQ(w.count("sampling.measured_instructions"), total.count("sampling.measured_instructions"));
}

TEST(BatchMeans, WeightsCountAWindowOfASparserStretchForMore) {
  // Two stretches: the first sampled every 4 units (weight 4), the second every unit (weight
  // 1), with miss densities 0.2 and 0.1 per measured instruction. Each stretch's share of the
  // frame is its weight times its measured instructions; the weighted ratio recovers the
  // frame's density, the plain one is pulled towards the densely sampled stretch.
  Tree t;
  BatchMeans b(&measured);
  for (int i = 0; i < 4; ++i) {
    t.measured += 100;
    t.misses += 20;
    b.add_window(Values::snapshot(t.root), 4.0);
  }
  b.set_tail_weight(1.0);
  for (int i = 0; i < 16; ++i) {
    t.measured += 100;
    t.misses += 10;
    b.add_window(Values::snapshot(t.root), 1.0);
  }
  t.retired = 3200;  // 1600 instructions in each stretch
  const Values total = Values::snapshot(t.root);
  Values w = b.weighted_total(total);
  finish(w);
  EXPECT_NEAR(w.number("memory.misses"), 0.2 * 1600 + 0.1 * 1600, 1.0);
  Values plain = total;
  finish(plain);
  EXPECT_NEAR(plain.number("memory.misses"), 3200.0 * 240 / 2000, 1.0);  // 384, not 480
}

TEST(BatchMeans, FewerThanTwoBatchesGiveNoInterval) {
  Tree t;
  BatchMeans b(&measured);
  t.measured = 100;
  t.misses = 5;
  b.add_window(Values::snapshot(t.root));
  EXPECT_TRUE(b.half_widths(Values::snapshot(t.root), [](Values) { return std::vector<double>{1.0}; }, 0.95).empty());
}


// Successive differences (interval_method.h) by hand: half the squared differences of
// neighbouring replicates in place of the squares about their mean, and t with 2(n - 1)/3
// degrees of freedom.
TEST(SuccessiveDifferences, MatchAHandComputation) {
  const std::vector<double> r = {10, 12, 11, 15, 14, 13, 16};
  double ss = 0;
  for (size_t i = 1; i < r.size(); ++i) ss += (r[i] - r[i - 1]) * (r[i] - r[i - 1]);
  const double expected = student_t_quantile(0.975, 4) * std::sqrt(0.5 * ss * 6 / 7);  // 2 x 6 / 3 = 4
  EXPECT_NEAR(successive_difference_half_width(r, 0.95), expected, 1e-12);
  EXPECT_EQ(successive_difference_half_width({3.0}, 0.95), 0.0);
  // Two replicates: one difference, one degree of freedom (never 0).
  EXPECT_NEAR(successive_difference_half_width({1.0, 3.0}, 0.95), student_t_quantile(0.975, 1) * std::sqrt(2.0 * 0.5),
              1e-12);
}

// The reason for the method: replicates that trend (a frame whose DRAM bytes per instruction
// rise from its camera rays to its bounces) give the jackknife a wide interval, the successive
// differences a narrow one; replicates that only scatter give both about the same.
TEST(SuccessiveDifferences, FollowATrendThatTheJackknifeCountsAsVariance) {
  std::vector<double> trend, scatter;
  uint32_t state = 12345;  // a fixed sequence, so the test is deterministic
  const auto uniform = [&state] {
    state = state * 1664525u + 1013904223u;
    return double(state >> 8) / double(1u << 24) - 0.5;
  };
  for (int i = 0; i < 32; ++i) {
    trend.push_back(100.0 + 2.0 * i + 0.1 * uniform());
    scatter.push_back(100.0 + 10.0 * uniform());
  }
  EXPECT_LT(successive_difference_half_width(trend, 0.95), 0.1 * jackknife_half_width(trend, 0.95));
  const double ratio = successive_difference_half_width(scatter, 0.95) / jackknife_half_width(scatter, 0.95);
  EXPECT_GT(ratio, 0.7);
  EXPECT_LT(ratio, 1.4);
}

// BatchMeans takes the method: the same windows, the replicates in the batches' order.
TEST(BatchMeans, SuccessiveDifferencesOverTheBatchesInTheirOrder) {
  Tree t;
  BatchMeans jack(&measured, 32, IntervalMethod::kJackknife);
  BatchMeans succ(&measured, 32, IntervalMethod::kSuccessiveDifferences);
  EXPECT_EQ(succ.method(), IntervalMethod::kSuccessiveDifferences);
  // Misses per instruction rising window by window.
  for (int i = 0; i < 8; ++i) {
    t.retired += 1000;
    t.measured += 100;
    t.misses += 10 + 5 * i;
    jack.add_window(Values::snapshot(t.root));
    succ.add_window(Values::snapshot(t.root));
  }
  const Values total = Values::snapshot(t.root);
  const auto misses = [](Values r) {
    finish(r);
    return std::vector<double>{r.number("memory.misses")};
  };
  const double j = jack.half_widths(total, misses, 0.95).at(0);
  const double s = succ.half_widths(total, misses, 0.95).at(0);
  // The replicates by hand, in window order.
  std::vector<double> reps;
  for (int i = 0; i < 8; ++i) reps.push_back(double(std::llround((double(t.misses) - (10.0 + 5 * i)) * 8000.0 / 700.0)));
  EXPECT_NEAR(j, jackknife_half_width(reps, 0.95), 1e-9);
  EXPECT_NEAR(s, successive_difference_half_width(reps, 0.95), 1e-9);
  EXPECT_LT(s, 0.5 * j);
}

// The replicates behind an interval are handed back, in batch order.
TEST(BatchMeans, TheReplicatesBehindAnIntervalAreHandedBackInBatchOrder) {
  Tree t;
  BatchMeans b(&measured, 32, IntervalMethod::kSuccessiveDifferences);
  const uint64_t m[] = {100, 120, 80, 100, 110, 90};
  const uint64_t x[] = {10, 15, 6, 9, 12, 8};
  for (int i = 0; i < 6; ++i) {
    t.retired += 1000;
    t.measured += m[i];
    t.misses += x[i];
    b.add_window(Values::snapshot(t.root));
  }
  const Values total = Values::snapshot(t.root);
  const auto misses = [](Values r) {
    finish(r);
    return std::vector<double>{r.number("memory.misses")};
  };
  std::vector<std::vector<double>> reps;
  const double whole = b.half_widths(total, misses, 0.95, &reps).at(0);
  EXPECT_GT(whole, 0.0);
  ASSERT_EQ(reps.size(), 1u);
  ASSERT_EQ(reps[0].size(), 6u);
  EXPECT_NEAR(successive_difference_half_width(reps[0], 0.95), whole, 1e-9);
  // The third replicate drops the third window: its misses and its measured instructions.
  EXPECT_NEAR(reps[0][2], static_cast<double>(std::llround((60.0 - 6) * 6000.0 / (600.0 - 80))), 1e-9);
}

}  // namespace
}  // namespace strata::stats
