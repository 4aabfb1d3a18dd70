// The verilated triangle pipeline (rtl/pipelines/triangle_pipeline.sv, SystemC mode, two
// lanes) against triangle_hit_test of firmware/common/intersect.h, bit for bit (hit bit, and
// the TrianglePartial on a hit), and its initiation interval, latency and issue width,
// measured from its own handshake, against the TM config. Each test in its own process.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <systemc>
#include <vector>

#include "Vtriangle_pipeline.h"
#include "firmware/common/intersect.h"
#include "firmware/common/float_bits.h"
#include "test/rtl/pipeline_config.h"
#include "test/rtl/triangle_cases.h"

namespace strata {
namespace {

using rtl_test::triangle_cases;
using rtl_test::TriOp;


struct TriResult {
  bool hit, exact;
  uint32_t e0, e1, e2, t_num, t_den;
};

constexpr int kLanes = 2;
constexpr int kOperands = 15;

// Two lanes, each with its own queue of operations, driven and sampled at the rising edge
// (reads see the values before the edge, writes land after it). out_ready of each lane is low
// with probability stall_probability per cycle.
SC_MODULE(TriBench) {
  sc_core::sc_clock clk{"clk", 1, sc_core::SC_NS};
  sc_core::sc_signal<bool> rst{"rst", true};
  sc_core::sc_signal<uint32_t> in_valid{"in_valid"}, in_ready{"in_ready"}, out_valid{"out_valid"},
      out_ready{"out_ready"}, out_hit{"out_hit"}, out_exact{"out_exact"};
  sc_core::sc_signal<uint64_t> operand[kOperands];
  sc_core::sc_signal<uint64_t> out_e0{"out_e0"}, out_e1{"out_e1"}, out_e2{"out_e2"}, out_t_num{"out_t_num"},
      out_t_den{"out_t_den"};
  Vtriangle_pipeline dut{"dut"};

  std::vector<TriOp> ops[kLanes];
  size_t next[kLanes] = {0, 0};
  std::vector<uint64_t> accepted_at[kLanes], finished_at[kLanes];
  std::vector<TriResult> results[kLanes];
  uint64_t cycle = 0;
  double stall_probability = 0.0;
  std::mt19937_64 rng{11};

  SC_CTOR(TriBench) {
    dut.clk(clk);
    dut.rst(rst);
    dut.in_valid(in_valid);
    dut.in_ready(in_ready);
    sc_core::sc_in<uint64_t>* ports[kOperands] = {&dut.v0_x, &dut.v0_y, &dut.v0_z, &dut.v1_x, &dut.v1_y,
                                                  &dut.v1_z, &dut.v2_x, &dut.v2_y, &dut.v2_z, &dut.origin_x,
                                                  &dut.origin_y, &dut.origin_z, &dut.dir_x, &dut.dir_y, &dut.dir_z};
    for (int i = 0; i < kOperands; ++i) (*ports[i])(operand[i]);
    dut.out_valid(out_valid);
    dut.out_ready(out_ready);
    dut.out_hit(out_hit);
    dut.out_exact(out_exact);
    dut.out_e0(out_e0);
    dut.out_e1(out_e1);
    dut.out_e2(out_e2);
    dut.out_t_num(out_t_num);
    dut.out_t_den(out_t_den);
    SC_METHOD(on_edge);
    sensitive << clk.posedge_event();
    dont_initialize();
  }

  static uint32_t lane_word(uint64_t v, int lane) { return static_cast<uint32_t>(v >> (32 * lane)); }

  void on_edge() {
    ++cycle;
    if (!rst.read()) {
      for (int l = 0; l < kLanes; ++l) {
        if ((in_valid.read() >> l & 1u) && (in_ready.read() >> l & 1u)) {
          accepted_at[l].push_back(cycle);
          ++next[l];
        }
        if ((out_valid.read() >> l & 1u) && (out_ready.read() >> l & 1u)) {
          finished_at[l].push_back(cycle);
          results[l].push_back({(out_hit.read() >> l & 1u) != 0, (out_exact.read() >> l & 1u) != 0,
                                lane_word(out_e0.read(), l), lane_word(out_e1.read(), l), lane_word(out_e2.read(), l),
                                lane_word(out_t_num.read(), l), lane_word(out_t_den.read(), l)});
        }
      }
    }
    rst.write(cycle < 3);
    uint32_t valid = 0, ready = 0;
    uint64_t words[kOperands] = {};
    for (int l = 0; l < kLanes; ++l) {
      if (cycle >= 3 && next[l] < ops[l].size()) {
        valid |= 1u << l;
        const TriOp& op = ops[l][next[l]];
        const float v[kOperands] = {op.v0.x, op.v0.y, op.v0.z, op.v1.x, op.v1.y, op.v1.z, op.v2.x, op.v2.y,
                                    op.v2.z, op.origin.x, op.origin.y, op.origin.z, op.dir.x, op.dir.y, op.dir.z};
        for (int i = 0; i < kOperands; ++i) words[i] |= static_cast<uint64_t>(float_bits(v[i])) << (32 * l);
      }
      if (std::uniform_real_distribution<double>(0, 1)(rng) >= stall_probability) ready |= 1u << l;
    }
    in_valid.write(valid);
    for (int i = 0; i < kOperands; ++i) operand[i].write(words[i]);
    out_ready.write(ready);
    if (results[0].size() == ops[0].size() && results[1].size() == ops[1].size()) sc_core::sc_stop();
  }
};

void run(uint64_t max_cycles) { sc_core::sc_start(sc_core::sc_time(static_cast<double>(max_cycles), sc_core::SC_NS)); }


struct Comparison {
  uint64_t ops = 0, mismatches = 0, hits = 0, exact = 0;
  // Hits on the exact path whose three terms are all non-zero: the term whose difference was
  // zero took a non-zero value from product_error, so the fallback arithmetic itself was used.
  uint64_t exact_nonzero_hits = 0;
};

Comparison compare_all(const TriBench& bench) {
  Comparison c;
  for (int l = 0; l < kLanes; ++l) {
    for (size_t i = 0; i < bench.ops[l].size(); ++i) {
      const TriOp& op = bench.ops[l][i];
      TrianglePartial p{};
      const bool hit = triangle_hit_test(op.v0, op.v1, op.v2, op.origin, op.dir, &p);
      const TriResult& r = bench.results[l][i];
      ++c.ops;
      c.hits += hit;
      c.exact += r.exact;
      c.exact_nonzero_hits += hit && r.exact && p.e0 != 0.0f && p.e1 != 0.0f && p.e2 != 0.0f;
      bool same = r.hit == hit;
      if (same && hit)
        same = r.e0 == float_bits(p.e0) && r.e1 == float_bits(p.e1) && r.e2 == float_bits(p.e2) && r.t_num == float_bits(p.t_num) &&
               r.t_den == float_bits(p.t_den);
      if (!same && ++c.mismatches <= 10)
        ADD_FAILURE() << "lane " << l << " op " << i << ": rtl hit " << r.hit << " e 0x" << std::hex << r.e0 << " 0x"
                      << r.e1 << " 0x" << r.e2 << " t 0x" << r.t_num << "/0x" << r.t_den << "; C++ hit " << hit
                      << " e 0x" << float_bits(p.e0) << " 0x" << float_bits(p.e1) << " 0x" << float_bits(p.e2) << " t 0x"
                      << float_bits(p.t_num) << "/0x" << float_bits(p.t_den);
    }
  }
  return c;
}

TEST(RtlTrianglePipeline, MatchesTriangleHitTestBitForBit) {
  TriBench bench("bench");
  bench.ops[0] = triangle_cases(15000, 15);
  bench.ops[1] = triangle_cases(15000, 16);
  bench.stall_probability = 0.05;
  run(40 * 15000 + 1000);
  ASSERT_EQ(bench.results[0].size(), bench.ops[0].size());
  ASSERT_EQ(bench.results[1].size(), bench.ops[1].size());
  const Comparison c = compare_all(bench);
  std::printf("triangle pipeline: %llu operations, %llu hits, %llu on the exact path (%llu hits with a non-zero "
              "fallback term), %llu mismatches\n",
              static_cast<unsigned long long>(c.ops), static_cast<unsigned long long>(c.hits),
              static_cast<unsigned long long>(c.exact), static_cast<unsigned long long>(c.exact_nonzero_hits),
              static_cast<unsigned long long>(c.mismatches));
  EXPECT_EQ(c.mismatches, 0u);
  EXPECT_GT(c.hits, c.ops / 10);        // both outcomes are exercised
  EXPECT_LT(c.hits, c.ops - c.ops / 10);
  EXPECT_GT(c.exact, c.ops / 100);      // and the exact fallback,
  EXPECT_GT(c.exact_nonzero_hits, 0u);  // including non-zero product_error results
}

// Back-to-back issue on both lanes with the outputs always ready.
TEST(RtlTrianglePipeline, TimingFromHandshakeEqualsTmConfig) {
  const tm::FusedPipelineConfig config = rtl_test::configured_pipeline("triangle");
  TriBench bench("bench");
  // Generic random triangles (no integer grids, no rays through vertices or edges): the fast path.
  std::mt19937_64 rng(5);
  auto unit = [&] { return std::uniform_real_distribution<float>(-1.0f, 1.0f)(rng); };
  for (int l = 0; l < kLanes; ++l)
    for (int i = 0; i < 40; ++i)
      bench.ops[l].push_back({{unit(), unit(), unit() + 3}, {unit(), unit(), unit() + 3}, {unit(), unit(), unit() + 3},
                              {unit() * 0.1f, unit() * 0.1f, unit() * 0.1f}, {unit() * 0.2f, unit() * 0.2f, 1.0f}});
  run(100 * 40 + 1000);
  ASSERT_EQ(bench.results[0].size(), bench.ops[0].size());
  ASSERT_EQ(bench.results[1].size(), bench.ops[1].size());
  EXPECT_EQ(compare_all(bench).mismatches, 0u);
  uint64_t ii_min = ~0ull, ii_max = 0, lat_min = ~0ull, lat_max = 0;
  for (int l = 0; l < kLanes; ++l) {
    for (size_t i = 0; i < bench.ops[l].size(); ++i) {
      ASSERT_FALSE(bench.results[l][i].exact);
      if (i > 0) {
        ii_min = std::min(ii_min, bench.accepted_at[l][i] - bench.accepted_at[l][i - 1]);
        ii_max = std::max(ii_max, bench.accepted_at[l][i] - bench.accepted_at[l][i - 1]);
      }
      lat_min = std::min(lat_min, bench.finished_at[l][i] - bench.accepted_at[l][i]);
      lat_max = std::max(lat_max, bench.finished_at[l][i] - bench.accepted_at[l][i]);
    }
  }
  // Issue width: how many operations were accepted in the same cycle.
  uint64_t same_cycle = 0;
  for (size_t i = 0; i < bench.ops[0].size(); ++i)
    same_cycle += std::count(bench.accepted_at[1].begin(), bench.accepted_at[1].end(), bench.accepted_at[0][i]);
  const uint64_t width = same_cycle == bench.ops[0].size() ? 2 : 1;
  std::printf("triangle pipeline: measured II %llu..%llu, latency %llu..%llu, issue width %llu; "
              "config II %u latency %u issue width %u\n",
              static_cast<unsigned long long>(ii_min), static_cast<unsigned long long>(ii_max),
              static_cast<unsigned long long>(lat_min), static_cast<unsigned long long>(lat_max),
              static_cast<unsigned long long>(width), config.initiation_interval, config.latency, config.issue_width);
  EXPECT_EQ(ii_min, config.initiation_interval);
  EXPECT_EQ(ii_max, config.initiation_interval);
  EXPECT_EQ(lat_min, config.latency);
  EXPECT_EQ(lat_max, config.latency);
  EXPECT_EQ(width, config.issue_width);
}

// The exact-fallback (slow) path: its results come 2 cycles later than the config's latency,
// in order, bit-exact, and the II is unchanged. Integer-grid triangles hit through an edge.
TEST(RtlTrianglePipeline, ExactFallbackTakesTheDocumentedSlowPath) {
  const tm::FusedPipelineConfig config = rtl_test::configured_pipeline("triangle");
  constexpr uint64_t kExtraCycles = 2;  // EXACT_TAP - FAST_TAP, rtl/pipelines/triangle_pipeline.sv
  TriBench bench("bench");
  for (int l = 0; l < kLanes; ++l) {
    for (int i = 0; i < 60; ++i) {
      const float k = static_cast<float>(i % 5 + 1);
      // The ray through the midpoint of edge v1-v2 (axis-parallel for even i): e0 is exactly 0.
      bench.ops[l].push_back({{0, 0, 3}, {k, 0, 3}, {0, k, 3}, {k / 2, k / 2, 0},
                              {(i % 2) ? 0.25f : 0.0f, 0.0f, 1.0f}});
    }
  }
  run(100 * 60 + 1000);
  ASSERT_EQ(bench.results[0].size(), bench.ops[0].size());
  ASSERT_EQ(bench.results[1].size(), bench.ops[1].size());
  EXPECT_EQ(compare_all(bench).mismatches, 0u);
  uint64_t exact = 0;
  for (int l = 0; l < kLanes; ++l) {
    for (size_t i = 0; i < bench.ops[l].size(); ++i) {
      const uint64_t latency = bench.finished_at[l][i] - bench.accepted_at[l][i];
      exact += bench.results[l][i].exact;
      EXPECT_EQ(latency, config.latency + (bench.results[l][i].exact ? kExtraCycles : 0)) << "lane " << l << " op " << i;
      if (i > 0) {
        EXPECT_EQ(bench.accepted_at[l][i] - bench.accepted_at[l][i - 1], config.initiation_interval);
      }
    }
  }
  EXPECT_GE(exact, bench.ops[0].size());  // the axis-parallel half at least takes the exact path
}

// Back pressure on both lanes: nothing lost, duplicated or reordered.
TEST(RtlTrianglePipeline, StallsUnderBackPressureWithoutLosingResults) {
  TriBench bench("bench");
  bench.ops[0] = triangle_cases(1500, 21);
  bench.ops[1] = triangle_cases(1500, 22);
  bench.stall_probability = 0.6;
  run(200 * 1500 + 1000);
  ASSERT_EQ(bench.results[0].size(), bench.ops[0].size());
  ASSERT_EQ(bench.results[1].size(), bench.ops[1].size());
  EXPECT_EQ(compare_all(bench).mismatches, 0u);
}

}  // namespace
}  // namespace strata
