// A TM's treelet sessions on a known sequence of assigns, pops and L1 answers: when a session
// begins and ends, which kind it is, where its lines came from, and the histogram's buckets.
#include <gtest/gtest.h>

#include "model/tm/treelet_sessions.h"
#include "model/stats/stat_values.h"

namespace strata::tm {
namespace {

using transport::kNoTreelet;
using transport::ServedBy;

TEST(TreeletSessionStats, BucketsArePowersOfTwoAfterZero) {
  EXPECT_EQ(TreeletSessions::bucket_of(0), 0u);
  EXPECT_EQ(TreeletSessions::bucket_of(1), 1u);
  EXPECT_EQ(TreeletSessions::bucket_of(2), 2u);
  EXPECT_EQ(TreeletSessions::bucket_of(3), 2u);
  EXPECT_EQ(TreeletSessions::bucket_of(4), 3u);
  EXPECT_EQ(TreeletSessions::bucket_of(1023), 10u);
  EXPECT_EQ(TreeletSessions::bucket_of(1024), 11u);
  const uint64_t last_from = uint64_t{1} << (TreeletSessions::kBuckets - 2);
  EXPECT_EQ(TreeletSessions::bucket_of(last_from - 1), TreeletSessions::kBuckets - 2);
  EXPECT_EQ(TreeletSessions::bucket_of(last_from), TreeletSessions::kBuckets - 1);
  EXPECT_EQ(TreeletSessions::bucket_of(~uint64_t{0}), TreeletSessions::kBuckets - 1);
}

TEST(TreeletSessionStats, ASessionRunsFromOneTreeletToTheNext) {
  TreeletSessions s(5);  // treelets 0-4 hold nodes, 5 and up triangles
  s.assigned(kNoTreelet);       // nothing to do yet: no session
  s.answered(ServedBy::kDram);  // a line filled before the first buffer
  s.assigned(3);                // node session 1
  for (int i = 0; i < 3; ++i) s.popped();
  s.answered(ServedBy::kL2);
  s.answered(ServedBy::kL1);        // a hit fills nothing
  s.answered(ServedBy::kL1Merged);  // a miss merged into a fill on its way fills nothing
  s.assigned(3);                    // the same buffer: the same session
  s.popped();
  s.assigned(7);  // triangle session 1
  s.popped();
  s.answered(ServedBy::kDram);
  s.answered(ServedBy::kL2Merged);
  s.assigned(kNoTreelet);  // every buffer empty: the TM idles on its treelet
  s.answered(ServedBy::kL2);
  s.assigned(7);  // ... and the same treelet again continues the session
  s.popped();
  s.assigned(3);  // node session 2 (open, no ray yet)

  stats::Values v = stats::Values::snapshot(s.stats());
  v.derive();
  EXPECT_EQ(v.count("sessions"), 3u);
  EXPECT_EQ(v.count("node.sessions"), 2u);
  EXPECT_EQ(v.count("triangle.sessions"), 1u);
  EXPECT_EQ(v.count("rays"), 6u);
  EXPECT_EQ(v.count("rays_popped"), 6u);
  EXPECT_EQ(v.count("node.rays"), 4u);
  EXPECT_EQ(v.count("triangle.rays"), 2u);
  EXPECT_DOUBLE_EQ(v.number("rays_per_session"), 2.0);
  EXPECT_DOUBLE_EQ(v.number("triangle.rays_per_session"), 2.0);
  EXPECT_EQ(v.count("lines_filled"), 4u);
  EXPECT_EQ(v.count("lines_l2_hit"), 2u);
  EXPECT_EQ(v.count("lines_dram"), 1u);
  EXPECT_EQ(v.count("lines_l2_merged"), 1u);
  EXPECT_EQ(v.count("node.lines_l2_hit"), 1u);
  EXPECT_EQ(v.count("triangle.lines_l2_hit"), 1u);
  EXPECT_EQ(v.count("triangle.lines_dram"), 1u);
  EXPECT_EQ(v.count("lines_outside_sessions"), 1u);
  EXPECT_DOUBLE_EQ(v.number("dram_lines_per_session"), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(v.number("triangle.lines_per_session"), 3.0);
  // 4 rays, 2 rays, and the open session with none.
  EXPECT_EQ(v.count("rays_histogram.from_4"), 1u);
  EXPECT_EQ(v.count("rays_histogram.from_2"), 1u);
  EXPECT_EQ(v.count("rays_histogram.zero"), 1u);
  uint64_t in_buckets = 0;
  for (const auto& st : v.group("rays_histogram").stats()) in_buckets += st.u;
  EXPECT_EQ(in_buckets, 3u);

  // The open session moves between buckets as it traces; the snapshot counts it once.
  s.popped();
  s.popped();
  v = stats::Values::snapshot(s.stats());
  EXPECT_EQ(v.count("rays_histogram.zero"), 0u);
  EXPECT_EQ(v.count("rays_histogram.from_2"), 2u);
}

}  // namespace
}  // namespace strata::tm
