// The verilated box pipeline (rtl/pipelines/box_pipeline.sv, SystemC mode) against
// intersect_box / intersect_box_valid_ray of firmware/common/intersect.h, bit for bit, and its
// initiation interval and latency, measured from its own valid/ready handshake, against the
// TM config. Each test elaborates its own SystemC design, so each runs in its own process
// (gtest_discover_tests).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <systemc>
#include <vector>

#include "Vbox_pipeline.h"
#include "firmware/common/intersect.h"
#include "firmware/common/float_bits.h"
#include "test/rtl/box_cases.h"
#include "test/rtl/pipeline_config.h"

namespace strata {
namespace {

using rtl_test::box_cases;
using rtl_test::BoxOp;


struct BoxResult {
  bool hit, overlap;
  uint32_t t_entry;
};

// Drives a list of operations through the pipeline at its handshake. Everything is sampled
// and driven at the rising edge (SystemC signal semantics: reads see the values before the
// edge, writes land after it), the cycle counter counts rising edges. out_ready is low with
// probability stall_probability in each cycle.
SC_MODULE(BoxBench) {
  sc_core::sc_clock clk{"clk", 1, sc_core::SC_NS};
  sc_core::sc_signal<bool> rst{"rst", true}, in_valid{"in_valid"}, in_ready{"in_ready"};
  sc_core::sc_signal<bool> out_valid{"out_valid"}, out_ready{"out_ready"}, out_hit{"out_hit"}, out_overlap{"out_overlap"};
  sc_core::sc_signal<uint32_t> operand[14];
  sc_core::sc_signal<uint32_t> out_t_entry{"out_t_entry"};
  Vbox_pipeline dut{"dut"};

  std::vector<BoxOp> ops;
  size_t next = 0;
  std::vector<uint64_t> accepted_at, finished_at;
  std::vector<BoxResult> results;
  uint64_t cycle = 0;
  double stall_probability = 0.0;
  std::mt19937_64 rng{7};

  SC_CTOR(BoxBench) {
    dut.clk(clk);
    dut.rst(rst);
    dut.in_valid(in_valid);
    dut.in_ready(in_ready);
    sc_core::sc_in<uint32_t>* ports[14] = {&dut.bmin_x, &dut.bmin_y, &dut.bmin_z, &dut.bmax_x, &dut.bmax_y,
                                           &dut.bmax_z, &dut.origin_x, &dut.origin_y, &dut.origin_z, &dut.inv_dir_x,
                                           &dut.inv_dir_y, &dut.inv_dir_z, &dut.tmin, &dut.tmax};
    for (int i = 0; i < 14; ++i) (*ports[i])(operand[i]);
    dut.out_valid(out_valid);
    dut.out_ready(out_ready);
    dut.out_hit(out_hit);
    dut.out_overlap(out_overlap);
    dut.out_t_entry(out_t_entry);
    SC_METHOD(on_edge);
    sensitive << clk.posedge_event();
    dont_initialize();
  }

  void on_edge() {
    ++cycle;
    if (!rst.read()) {
      if (in_valid.read() && in_ready.read()) {
        accepted_at.push_back(cycle);
        ++next;
      }
      if (out_valid.read() && out_ready.read()) {
        finished_at.push_back(cycle);
        results.push_back({out_hit.read(), out_overlap.read(), out_t_entry.read()});
      }
    }
    rst.write(cycle < 3);
    const bool have = cycle >= 3 && next < ops.size();
    in_valid.write(have);
    if (have) {
      const BoxOp& op = ops[next];
      const float v[14] = {op.bmin[0], op.bmin[1], op.bmin[2], op.bmax[0], op.bmax[1],
                           op.bmax[2], op.ray.origin.x, op.ray.origin.y, op.ray.origin.z, op.ray.inv_dir.x,
                           op.ray.inv_dir.y, op.ray.inv_dir.z, op.ray.tmin, op.ray.tmax};
      for (int i = 0; i < 14; ++i) operand[i].write(float_bits(v[i]));
    }
    out_ready.write(std::uniform_real_distribution<double>(0, 1)(rng) >= stall_probability);
    if (results.size() == ops.size()) sc_core::sc_stop();
  }
};

// Runs the bench's operations, with a bound on the cycles so that a hung pipeline fails
// instead of hanging (the bench stops the simulation when every result is in).
void run(uint64_t max_cycles) {
  sc_core::sc_start(sc_core::sc_time(static_cast<double>(max_cycles), sc_core::SC_NS));
}


TEST(RtlBoxPipeline, MatchesIntersectBoxBitForBit) {
  BoxBench bench("bench");
  bench.ops = box_cases(100000, 15);
  bench.stall_probability = 0.1;  // results must survive back pressure
  run(10 * bench.ops.size() + 100);
  ASSERT_EQ(bench.results.size(), bench.ops.size());
  uint64_t mismatches = 0, hits = 0, nan_entries = 0;
  for (size_t i = 0; i < bench.ops.size(); ++i) {
    const BoxOp& op = bench.ops[i];
    float t_valid = 0.0f, t_full = 0.0f;
    const bool overlap = intersect_box_valid_ray(op.bmin, op.bmax, op.ray, &t_valid);
    const bool hit = intersect_box(op.bmin, op.bmax, op.ray, &t_full);
    const BoxResult& r = bench.results[i];
    hits += hit;
    nan_entries += t_valid != t_valid;
    if (r.hit != hit || r.overlap != overlap || r.t_entry != float_bits(t_valid)) {
      if (++mismatches <= 10)
        ADD_FAILURE() << "op " << i << ": rtl hit " << r.hit << " overlap " << r.overlap << " t_entry 0x" << std::hex
                      << r.t_entry << ", C++ hit " << hit << " overlap " << overlap << " t_entry 0x" << float_bits(t_valid);
    }
  }
  EXPECT_EQ(mismatches, 0u);
  // The cases exercise both outcomes and the NaN paths.
  EXPECT_GT(hits, bench.ops.size() / 20);
  EXPECT_LT(hits, bench.ops.size() - bench.ops.size() / 20);
  EXPECT_GT(nan_entries, 100u);
  RecordProperty("vectors", static_cast<int>(bench.ops.size()));
  RecordProperty("mismatches", static_cast<int>(mismatches));
  std::printf("box pipeline: %zu operations, %llu mismatches\n", bench.ops.size(),
              static_cast<unsigned long long>(mismatches));
}

// Back-to-back issue with the output always ready: the initiation interval is the distance
// between consecutive accepted operations, the latency the distance from acceptance to result.
TEST(RtlBoxPipeline, TimingFromHandshakeEqualsTmConfig) {
  const tm::FusedPipelineConfig config = rtl_test::configured_pipeline("box");
  BoxBench bench("bench");
  bench.ops = box_cases(200, 3);
  run(10 * bench.ops.size() + 100);
  ASSERT_EQ(bench.results.size(), bench.ops.size());
  ASSERT_EQ(bench.accepted_at.size(), bench.ops.size());
  uint64_t ii_min = ~0ull, ii_max = 0, lat_min = ~0ull, lat_max = 0;
  for (size_t i = 0; i < bench.ops.size(); ++i) {
    if (i > 0) {
      ii_min = std::min(ii_min, bench.accepted_at[i] - bench.accepted_at[i - 1]);
      ii_max = std::max(ii_max, bench.accepted_at[i] - bench.accepted_at[i - 1]);
    }
    lat_min = std::min(lat_min, bench.finished_at[i] - bench.accepted_at[i]);
    lat_max = std::max(lat_max, bench.finished_at[i] - bench.accepted_at[i]);
  }
  std::printf("box pipeline: measured II %llu..%llu, latency %llu..%llu; config II %u latency %u issue width %u\n",
              static_cast<unsigned long long>(ii_min), static_cast<unsigned long long>(ii_max),
              static_cast<unsigned long long>(lat_min), static_cast<unsigned long long>(lat_max),
              config.initiation_interval, config.latency, config.issue_width);
  EXPECT_EQ(ii_min, config.initiation_interval);
  EXPECT_EQ(ii_max, config.initiation_interval);
  EXPECT_EQ(lat_min, config.latency);
  EXPECT_EQ(lat_max, config.latency);
  EXPECT_EQ(config.issue_width, 1u);  // one operation per II: the RTL has a single lane
}

// Back pressure: a result held at the output stops the pipeline (in_ready low) and nothing is
// lost or duplicated; reset empties it.
TEST(RtlBoxPipeline, StallsUnderBackPressureWithoutLosingResults) {
  BoxBench bench("bench");
  bench.ops = box_cases(5000, 9);
  bench.stall_probability = 0.7;
  run(20 * bench.ops.size() + 100);
  ASSERT_EQ(bench.results.size(), bench.ops.size());
  for (size_t i = 0; i < bench.ops.size(); ++i) {
    float t = 0.0f;
    const bool hit = intersect_box(bench.ops[i].bmin, bench.ops[i].bmax, bench.ops[i].ray, &t);
    intersect_box_valid_ray(bench.ops[i].bmin, bench.ops[i].bmax, bench.ops[i].ray, &t);
    ASSERT_EQ(bench.results[i].hit, hit) << "op " << i;
    ASSERT_EQ(bench.results[i].t_entry, float_bits(t)) << "op " << i;
  }
  // With the output stalled most of the time, acceptance cannot run at one per cycle.
  EXPECT_GT(bench.accepted_at.back() - bench.accepted_at.front(), 2 * bench.ops.size());
}

}  // namespace
}  // namespace strata
