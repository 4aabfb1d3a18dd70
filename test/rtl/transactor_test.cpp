// The TLM-2.0 transactor (rtl/cosim/pipeline_transactor.h) in front of the verilated
// pipelines: fused operations from several initiator threads through one target socket,
// results bit for bit against firmware/common/intersect.h, the latency the transactor observes
// against the TM config (test/rtl/pipeline_config.h), and the initiation interval and issue
// width visible when several operations are in flight. Each test elaborates its own design,
// so each runs in its own process (gtest_discover_tests).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <vector>

#include "firmware/common/intersect.h"
#include "firmware/common/float_bits.h"
#include "rtl/cosim/pipeline_transactor.h"
#include "test/rtl/box_cases.h"
#include "test/rtl/pipeline_config.h"
#include "test/rtl/triangle_cases.h"

namespace strata {
namespace {

using rtl::FusedOpExtension;
using rtl::FusedOpKind;


const sc_core::sc_time kPeriod(1, sc_core::SC_NS);

// Initiator threads sharing one initiator socket bound to the transactor's target socket.
SC_MODULE(Initiators) {
  tlm_utils::simple_initiator_socket<Initiators> socket{"socket"};
  rtl::PipelineTransactor transactor{"transactor", kPeriod};

  SC_CTOR(Initiators) { socket.bind(transactor.socket); }

  // One fused operation through b_transport; returns the extension as the target left it.
  FusedOpExtension issue(const FusedOpExtension& request, sc_core::sc_time delay = sc_core::SC_ZERO_TIME) {
    FusedOpExtension op = request;
    tlm::tlm_generic_payload payload;
    payload.set_command(tlm::TLM_IGNORE_COMMAND);
    payload.set_extension(&op);
    socket->b_transport(payload, delay);
    payload.clear_extension(&op);
    EXPECT_EQ(payload.get_response_status(), tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(delay, sc_core::SC_ZERO_TIME);
    return op;
  }

  void spawn(const std::string& name, std::function<void()> body) {
    sc_core::sc_spawn(std::move(body), sc_core::sc_gen_unique_name(name.c_str()));
  }
};

FusedOpExtension box_request(const rtl_test::BoxOp& op) {
  FusedOpExtension e;
  e.kind = FusedOpKind::kBox;
  for (int i = 0; i < 3; ++i) {
    e.box.bmin[i] = op.bmin[i];
    e.box.bmax[i] = op.bmax[i];
  }
  e.box.ray = op.ray;
  return e;
}

FusedOpExtension triangle_request(const rtl_test::TriOp& op) {
  FusedOpExtension e;
  e.kind = FusedOpKind::kTriangle;
  e.triangle = {op.v0, op.v1, op.v2, op.origin, op.dir};
  return e;
}

bool box_matches(const rtl_test::BoxOp& op, const FusedOpExtension& r) {
  float t_valid = 0.0f, t_full = 0.0f;
  const bool overlap = intersect_box_valid_ray(op.bmin, op.bmax, op.ray, &t_valid);
  const bool hit = intersect_box(op.bmin, op.bmax, op.ray, &t_full);
  return r.box_result.hit == hit && r.box_result.overlap == overlap && float_bits(r.box_result.t_entry) == float_bits(t_valid);
}

bool triangle_matches(const rtl_test::TriOp& op, const FusedOpExtension& r, bool* hit_out) {
  TrianglePartial p{};
  const bool hit = triangle_hit_test(op.v0, op.v1, op.v2, op.origin, op.dir, &p);
  *hit_out = hit;
  if (r.triangle_result.hit != hit) return false;
  if (!hit) return true;  // intersect.h leaves the partial unspecified on a miss
  const TrianglePartial& q = r.triangle_result.partial;
  return float_bits(q.e0) == float_bits(p.e0) && float_bits(q.e1) == float_bits(p.e1) && float_bits(q.e2) == float_bits(p.e2) &&
         float_bits(q.t_num) == float_bits(p.t_num) && float_bits(q.t_den) == float_bits(p.t_den);
}

void run(uint64_t max_cycles) { sc_core::sc_start(kPeriod * static_cast<double>(max_cycles)); }

// Random and hard-case box operations from 8 initiator threads, each issuing its share back to
// back: every result bit for bit, every observed latency the config's.
TEST(RtlTransactor, BoxOperationsFromSeveralInitiatorsMatchIntersectBox) {
  const tm::FusedPipelineConfig config = rtl_test::configured_pipeline("box");
  constexpr int kThreads = 8;
  Initiators top("top");
  const std::vector<rtl_test::BoxOp> ops = rtl_test::box_cases(20000, 31);
  std::vector<FusedOpExtension> results(ops.size());
  for (int t = 0; t < kThreads; ++t)
    top.spawn("box_initiator", [&, t] {
      for (size_t i = static_cast<size_t>(t); i < ops.size(); i += kThreads) results[i] = top.issue(box_request(ops[i]));
    });
  run(4 * ops.size() + 100);
  ASSERT_EQ(top.transactor.box_operations(), ops.size());
  uint64_t mismatches = 0, wrong_latency = 0, hits = 0, queued = 0;
  for (size_t i = 0; i < ops.size(); ++i) {
    hits += results[i].box_result.hit;
    queued += results[i].queued_cycles > 0;
    if (!box_matches(ops[i], results[i]) && ++mismatches <= 10) ADD_FAILURE() << "box op " << i << " differs";
    wrong_latency += results[i].latency_cycles != config.latency;
  }
  uint64_t cycles = 0;  // the edge of the last result
  for (const FusedOpExtension& r : results) cycles = std::max(cycles, r.done_cycle);
  std::printf("transactor box: %zu operations from %d initiators in %llu cycles, %llu hits, %llu mismatches, "
              "%llu with a latency other than %u, %llu waited for a slot\n",
              ops.size(), kThreads, static_cast<unsigned long long>(cycles), static_cast<unsigned long long>(hits),
              static_cast<unsigned long long>(mismatches), static_cast<unsigned long long>(wrong_latency),
              config.latency, static_cast<unsigned long long>(queued));
  EXPECT_EQ(mismatches, 0u);
  EXPECT_EQ(wrong_latency, 0u);
  EXPECT_GT(hits, ops.size() / 20);
  EXPECT_LT(hits, ops.size() - ops.size() / 20);
  // 8 operations in flight: far more than one per latency.
  EXPECT_LT(cycles, ops.size() * config.latency / 4);
}

// Random and hard-case triangle operations from 4 initiator threads: every result bit for bit,
// every observed latency the config's (the exact edge fallback: 2 cycles more, as documented in
// docs/rtl-cosim.md and checked by RtlTrianglePipeline.ExactFallbackTakesTheDocumentedSlowPath).
TEST(RtlTransactor, TriangleOperationsFromSeveralInitiatorsMatchTriangleHitTest) {
  const tm::FusedPipelineConfig config = rtl_test::configured_pipeline("triangle");
  constexpr uint32_t kExactExtraCycles = 2;
  constexpr int kThreads = 4;
  Initiators top("top");
  const std::vector<rtl_test::TriOp> ops = rtl_test::triangle_cases(6000, 41);
  std::vector<FusedOpExtension> results(ops.size());
  for (int t = 0; t < kThreads; ++t)
    top.spawn("triangle_initiator", [&, t] {
      for (size_t i = static_cast<size_t>(t); i < ops.size(); i += kThreads)
        results[i] = top.issue(triangle_request(ops[i]));
    });
  run(40 * ops.size() + 1000);
  ASSERT_EQ(top.transactor.triangle_operations(), ops.size());
  uint64_t mismatches = 0, wrong_latency = 0, hits = 0, exact = 0, lane1 = 0;
  for (size_t i = 0; i < ops.size(); ++i) {
    bool hit = false;
    if (!triangle_matches(ops[i], results[i], &hit) && ++mismatches <= 10)
      ADD_FAILURE() << "triangle op " << i << " differs";
    hits += hit;
    exact += results[i].triangle_result.exact;
    lane1 += results[i].lane == 1;
    const uint32_t expected = config.latency + (results[i].triangle_result.exact ? kExactExtraCycles : 0);
    wrong_latency += results[i].latency_cycles != expected;
  }
  uint64_t cycles = 0;  // the edge of the last result
  for (const FusedOpExtension& r : results) cycles = std::max(cycles, r.done_cycle);
  std::printf("transactor triangle: %zu operations from %d initiators in %llu cycles, %llu hits, %llu exact, "
              "%llu on lane 1, %llu mismatches, %llu with an unexpected latency\n",
              ops.size(), kThreads, static_cast<unsigned long long>(cycles), static_cast<unsigned long long>(hits),
              static_cast<unsigned long long>(exact), static_cast<unsigned long long>(lane1),
              static_cast<unsigned long long>(mismatches), static_cast<unsigned long long>(wrong_latency));
  EXPECT_EQ(mismatches, 0u);
  EXPECT_EQ(wrong_latency, 0u);
  EXPECT_GT(hits, ops.size() / 10);
  EXPECT_GT(exact, ops.size() / 100);
  // Both lanes busy: the throughput is issue_width operations per initiation interval.
  EXPECT_GT(lane1, ops.size() / 3);
  EXPECT_LT(cycles, ops.size() * config.initiation_interval / config.issue_width + ops.size() + 1000);
}

// Two box operations issued in the same cycle by two initiators: the pipeline accepts them one
// initiation interval apart and both take the config's latency, so they finish II cycles
// apart; the time b_transport takes is the queueing plus the latency the extension reports.
TEST(RtlTransactor, BoxOperationsInTheSameCycleFinishOneIntervalApart) {
  const tm::FusedPipelineConfig config = rtl_test::configured_pipeline("box");
  Initiators top("top");
  const std::vector<rtl_test::BoxOp> ops = rtl_test::box_cases(2, 5);
  FusedOpExtension r[2];
  sc_core::sc_time returned[2];
  const sc_core::sc_time start = kPeriod * 10.5;  // between two rising edges
  for (int t = 0; t < 2; ++t)
    top.spawn("box_initiator", [&, t] {
      r[t] = top.issue(box_request(ops[t]), start);  // the annotated delay: issued at 10.5 cycles
      returned[t] = sc_core::sc_time_stamp();
    });
  run(100);
  ASSERT_EQ(top.transactor.box_operations(), 2u);
  const int first = r[0].accept_cycle < r[1].accept_cycle ? 0 : 1, second = 1 - first;
  std::printf("transactor box: accepted at cycles %llu and %llu, finished at %llu and %llu, latency %u and %u\n",
              static_cast<unsigned long long>(r[first].accept_cycle),
              static_cast<unsigned long long>(r[second].accept_cycle),
              static_cast<unsigned long long>(r[first].done_cycle),
              static_cast<unsigned long long>(r[second].done_cycle), r[first].latency_cycles,
              r[second].latency_cycles);
  EXPECT_EQ(r[second].accept_cycle - r[first].accept_cycle, config.initiation_interval);
  EXPECT_EQ(r[second].done_cycle - r[first].done_cycle, config.initiation_interval);
  for (int t = 0; t < 2; ++t) {
    EXPECT_EQ(r[t].latency_cycles, config.latency);
    EXPECT_TRUE(box_matches(ops[t], r[t]));
    // Half a cycle to the first edge, one cycle on the pins, then queueing and the latency, in
    // simulated time.
    EXPECT_EQ(returned[t] - start, kPeriod * (1.5 + r[t].queued_cycles + r[t].latency_cycles));
  }
  EXPECT_EQ(r[first].queued_cycles, 0u);
  EXPECT_EQ(r[second].queued_cycles, config.initiation_interval);
  EXPECT_EQ(returned[second] - returned[first], kPeriod * config.initiation_interval);
}

// Four triangle operations issued in the same cycle: issue_width of them start together (one
// per lane), the others one initiation interval later on the same lanes.
TEST(RtlTransactor, TriangleOperationsInTheSameCycleFillBothLanes) {
  const tm::FusedPipelineConfig config = rtl_test::configured_pipeline("triangle");
  Initiators top("top");
  constexpr int kOps = 4;
  FusedOpExtension r[kOps];
  for (int t = 0; t < kOps; ++t)
    top.spawn("triangle_initiator", [&, t] {
      const float k = static_cast<float>(t + 1) * 0.05f;  // inside the triangle
      FusedOpExtension op;
      op.kind = FusedOpKind::kTriangle;
      op.triangle = {{-1, -1, 3}, {1, -1, 3}, {0, 1, 3}, {k, k, 0}, {0.0f, 0.0f, 1.0f}};
      r[t] = top.issue(op, kPeriod * 7.5);
    });
  run(200);
  ASSERT_EQ(top.transactor.triangle_operations(), static_cast<uint64_t>(kOps));
  uint64_t first_accept = ~0ull;
  for (const FusedOpExtension& e : r) first_accept = std::min(first_accept, e.accept_cycle);
  uint32_t at_first = 0, at_second = 0, lanes_first = 0, lanes_second = 0;
  for (int t = 0; t < kOps; ++t) {
    std::printf("transactor triangle op %d: lane %u accepted at %llu, latency %u, hit %d\n", t, r[t].lane,
                static_cast<unsigned long long>(r[t].accept_cycle), r[t].latency_cycles, r[t].triangle_result.hit);
    EXPECT_EQ(r[t].latency_cycles, config.latency);
    EXPECT_FALSE(r[t].triangle_result.exact);
    bool hit = false;
    EXPECT_TRUE(triangle_matches({r[t].triangle.v0, r[t].triangle.v1, r[t].triangle.v2, r[t].triangle.origin,
                                  r[t].triangle.dir},
                                 r[t], &hit));
    EXPECT_TRUE(hit);
    if (r[t].accept_cycle == first_accept) {
      ++at_first;
      lanes_first |= 1u << r[t].lane;
    } else if (r[t].accept_cycle == first_accept + config.initiation_interval) {
      ++at_second;
      lanes_second |= 1u << r[t].lane;
    }
  }
  EXPECT_EQ(at_first, config.issue_width);
  EXPECT_EQ(at_second, kOps - config.issue_width);
  EXPECT_EQ(lanes_first, 3u);   // both lanes
  EXPECT_EQ(lanes_second, 3u);
}

// A transaction without the extension, or with a memory command, is refused.
TEST(RtlTransactor, RejectsPayloadsWithoutAnOperation) {
  Initiators top("top");
  tlm::tlm_response_status without_extension = tlm::TLM_INCOMPLETE_RESPONSE, with_read = without_extension;
  top.spawn("initiator", [&] {
    tlm::tlm_generic_payload payload;
    sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
    payload.set_command(tlm::TLM_IGNORE_COMMAND);
    top.socket->b_transport(payload, delay);
    without_extension = payload.get_response_status();
    FusedOpExtension op;
    payload.set_extension(&op);
    payload.set_command(tlm::TLM_READ_COMMAND);
    top.socket->b_transport(payload, delay);
    with_read = payload.get_response_status();
    payload.clear_extension(&op);
  });
  run(10);
  EXPECT_EQ(without_extension, tlm::TLM_COMMAND_ERROR_RESPONSE);
  EXPECT_EQ(with_read, tlm::TLM_COMMAND_ERROR_RESPONSE);
  EXPECT_EQ(top.transactor.box_operations() + top.transactor.triangle_operations(), 0u);
}

}  // namespace
}  // namespace strata
