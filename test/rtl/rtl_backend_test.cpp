// The RTL inside a chip run, below the chip: the zero-time transactor
// (rtl/cosim/zero_time_transactor.h) against firmware/common/intersect.h and the TM config's
// latencies, and the fused-pipeline backend (rtl/cosim/rtl_fused_backend.h) against the C++
// pipeline model the ISS uses (model/iss/pipeline_reference.h), with its latency counts. Each
// test elaborates its own design, so each runs in its own process (gtest_discover_tests).
#include <gtest/gtest.h>

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
#include "model/iss/pipeline_reference.h"
#include "rtl/cosim/rtl_fused_backend.h"
#include "rtl/cosim/zero_time_transactor.h"
#include "test/rtl/box_cases.h"
#include "test/rtl/pipeline_config.h"
#include "test/rtl/triangle_cases.h"

namespace strata {
namespace {

using rtl::FusedOpExtension;
using rtl::FusedOpKind;


bool same_partial(const TrianglePartial& a, const TrianglePartial& b) {
  return float_bits(a.e0) == float_bits(b.e0) && float_bits(a.e1) == float_bits(b.e1) && float_bits(a.e2) == float_bits(b.e2) &&
         float_bits(a.t_num) == float_bits(b.t_num) && float_bits(a.t_den) == float_bits(b.t_den);
}

// Runs `body` in a thread of its own, as the chip's TMs call the RTL, and fails if it moved
// simulated time.
void run_in_thread(std::function<void()> body) {
  bool ran = false;
  sc_core::sc_spawn([&] {
    body();
    EXPECT_EQ(sc_core::sc_time_stamp(), sc_core::SC_ZERO_TIME) << "the RTL advanced simulated time";
    ran = true;
  });
  sc_core::sc_start();
  ASSERT_TRUE(ran);
}

SC_MODULE(Initiator) {
  tlm_utils::simple_initiator_socket<Initiator> socket{"socket"};
  rtl::ZeroTimeTransactor transactor{"transactor"};
  SC_CTOR(Initiator) { socket.bind(transactor.socket); }

  FusedOpExtension issue(const FusedOpExtension& request) {
    FusedOpExtension op = request;
    tlm::tlm_generic_payload payload;
    payload.set_command(tlm::TLM_IGNORE_COMMAND);
    payload.set_extension(&op);
    const sc_core::sc_time annotated(3, sc_core::SC_NS);
    sc_core::sc_time delay = annotated;
    socket->b_transport(payload, delay);
    payload.clear_extension(&op);
    EXPECT_EQ(payload.get_response_status(), tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(delay, annotated) << "a zero-time transaction leaves the delay alone";
    return op;
  }
};

// Box operations through the transactor: hit, overlap and t_entry bit for bit against
// intersect.h, every latency the config's, one cycle on the pins before each acceptance.
TEST(RtlZeroTimeTransactor, BoxOperationsMatchIntersectBoxWithTheConfiguredLatency) {
  const tm::FusedPipelineConfig config = rtl_test::configured_pipeline("box");
  Initiator top("top");
  const std::vector<rtl_test::BoxOp> ops = rtl_test::box_cases(5000, 77);
  uint64_t mismatches = 0, wrong_latency = 0, hits = 0;
  run_in_thread([&] {
    for (size_t i = 0; i < ops.size(); ++i) {
      FusedOpExtension e;
      e.kind = FusedOpKind::kBox;
      for (int a = 0; a < 3; ++a) {
        e.box.bmin[a] = ops[i].bmin[a];
        e.box.bmax[a] = ops[i].bmax[a];
      }
      e.box.ray = ops[i].ray;
      const uint64_t before = top.transactor.box_cycle();
      const FusedOpExtension r = top.issue(e);
      float t_valid = 0.0f, t_full = 0.0f;
      const bool overlap = intersect_box_valid_ray(ops[i].bmin, ops[i].bmax, ops[i].ray, &t_valid);
      const bool hit = intersect_box(ops[i].bmin, ops[i].bmax, ops[i].ray, &t_full);
      hits += hit;
      if ((r.box_result.hit != hit || r.box_result.overlap != overlap || float_bits(r.box_result.t_entry) != float_bits(t_valid)) &&
          ++mismatches <= 10)
        ADD_FAILURE() << "box op " << i << " differs";
      wrong_latency += r.latency_cycles != config.latency;
      EXPECT_EQ(r.accept_cycle, before + 1);
      EXPECT_EQ(r.done_cycle, top.transactor.box_cycle());
    }
  });
  std::printf("zero-time transactor box: %zu operations, %llu hits, %llu mismatches, %llu with a latency other than "
              "%u, %llu box cycles\n",
              ops.size(), static_cast<unsigned long long>(hits), static_cast<unsigned long long>(mismatches),
              static_cast<unsigned long long>(wrong_latency), config.latency,
              static_cast<unsigned long long>(top.transactor.box_cycle()));
  EXPECT_EQ(mismatches, 0u);
  EXPECT_EQ(wrong_latency, 0u);
  EXPECT_GT(hits, ops.size() / 20);
  // Only the box pipeline was clocked: the triangle's clock stopped after its reset.
  EXPECT_EQ(top.transactor.triangle_cycle(), rtl::ZeroTimeTransactor::kResetCycles);
}

// Triangle operations: hit and (on a hit) the partial bit for bit, the latency the config's or,
// on the exact-fallback path, 2 cycles more; the two lanes take turns.
TEST(RtlZeroTimeTransactor, TriangleOperationsMatchTriangleHitTestWithTheConfiguredLatency) {
  const tm::FusedPipelineConfig config = rtl_test::configured_pipeline("triangle");
  Initiator top("top");
  const std::vector<rtl_test::TriOp> ops = rtl_test::triangle_cases(1500, 78);
  uint64_t mismatches = 0, wrong_latency = 0, hits = 0, exact = 0, lane1 = 0;
  run_in_thread([&] {
    for (size_t i = 0; i < ops.size(); ++i) {
      FusedOpExtension e;
      e.kind = FusedOpKind::kTriangle;
      e.triangle = {ops[i].v0, ops[i].v1, ops[i].v2, ops[i].origin, ops[i].dir};
      const FusedOpExtension r = top.issue(e);
      TrianglePartial p{};
      const bool hit = triangle_hit_test(ops[i].v0, ops[i].v1, ops[i].v2, ops[i].origin, ops[i].dir, &p);
      hits += hit;
      exact += r.triangle_result.exact;
      lane1 += r.lane == 1;
      if ((r.triangle_result.hit != hit || (hit && !same_partial(r.triangle_result.partial, p))) && ++mismatches <= 10)
        ADD_FAILURE() << "triangle op " << i << " differs";
      const uint32_t expected = config.latency + (r.triangle_result.exact ? rtl::kTriangleSlowPathExtraCycles : 0);
      wrong_latency += r.latency_cycles != expected;
      EXPECT_EQ(r.lane, i % 2);
    }
  });
  std::printf("zero-time transactor triangle: %zu operations, %llu hits, %llu exact, %llu on lane 1, %llu "
              "mismatches, %llu with an unexpected latency\n",
              ops.size(), static_cast<unsigned long long>(hits), static_cast<unsigned long long>(exact),
              static_cast<unsigned long long>(lane1), static_cast<unsigned long long>(mismatches),
              static_cast<unsigned long long>(wrong_latency));
  EXPECT_EQ(mismatches, 0u);
  EXPECT_EQ(wrong_latency, 0u);
  EXPECT_GT(hits, ops.size() / 10);
  EXPECT_GT(exact, ops.size() / 100);
  EXPECT_EQ(lane1, ops.size() / 2);
  EXPECT_EQ(top.transactor.box_cycle(), rtl::ZeroTimeTransactor::kResetCycles);
}

TEST(RtlZeroTimeTransactor, RejectsPayloadsWithoutAnOperation) {
  Initiator top("top");
  tlm::tlm_response_status without_extension = tlm::TLM_INCOMPLETE_RESPONSE, with_read = without_extension;
  run_in_thread([&] {
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
  EXPECT_EQ(without_extension, tlm::TLM_COMMAND_ERROR_RESPONSE);
  EXPECT_EQ(with_read, tlm::TLM_COMMAND_ERROR_RESPONSE);
  EXPECT_EQ(top.transactor.box_cycle() + top.transactor.triangle_cycle(), 2 * rtl::ZeroTimeTransactor::kResetCycles);
}

strata_pipe_ray pipe_ray(const Vec3f& origin, const Vec3f& dir, const Vec3f& inv, float tmin, float tmax) {
  strata_pipe_ray r{};
  const float o[3] = {origin.x, origin.y, origin.z}, d[3] = {dir.x, dir.y, dir.z}, v[3] = {inv.x, inv.y, inv.z};
  for (int a = 0; a < 3; ++a) {
    r.origin[a] = o[a];
    r.direction[a] = d[a];
    r.inv_direction[a] = v[a];
  }
  r.tmin = tmin;
  r.tmax = tmax;
  return r;
}

rtl::RtlBackendConfig configured_backend() {
  rtl::RtlBackendConfig c;
  c.box_latency = rtl_test::configured_pipeline("box").latency;
  c.triangle_latency = rtl_test::configured_pipeline("triangle").latency;
  return c;
}

// What the ISS gets from the backend is what the C++ pipeline model gives it: box hit and
// t_entry (+inf on a miss), triangle hit and partial (the previous one kept on a miss), for
// every case; the counts say every op ran with the configured latency, the slow path apart.
TEST(RtlFusedBackend, AnswersAsTheCppPipelineModelAndCountsTheOps) {
  rtl::RtlFusedBackend backend("backend", configured_backend());
  const std::vector<rtl_test::BoxOp> boxes = rtl_test::box_cases(3000, 91);
  const std::vector<rtl_test::TriOp> tris = rtl_test::triangle_cases(800, 92);
  uint64_t box_diff = 0, tri_diff = 0;
  run_in_thread([&] {
    for (const rtl_test::BoxOp& op : boxes) {
      strata_pipe_box box{};
      for (int a = 0; a < 3; ++a) {
        box.min[a] = op.bmin[a];
        box.max[a] = op.bmax[a];
      }
      const strata_pipe_ray ray = pipe_ray(op.ray.origin, {0, 0, 0}, op.ray.inv_dir, op.ray.tmin, op.ray.tmax);
      const iss::BoxTestResult want = iss::box_test(ray, box), got = backend.box_test(ray, box);
      box_diff += got.hit != want.hit || float_bits(got.t_entry) != float_bits(want.t_entry);
    }
    // A previous partial no test produces, so a miss that failed to keep it would show.
    const TrianglePartial previous = {-7.0f, -7.0f, -7.0f, 1234.5f, -0.25f};
    for (const rtl_test::TriOp& op : tris) {
      strata_pipe_triangle tri{};
      const Vec3f v[3] = {op.v0, op.v1, op.v2};
      for (int k = 0; k < 3; ++k) {
        float* dst = k == 0 ? tri.v0 : k == 1 ? tri.v1 : tri.v2;
        dst[0] = v[k].x;
        dst[1] = v[k].y;
        dst[2] = v[k].z;
      }
      const strata_pipe_ray ray = pipe_ray(op.origin, op.dir, {0, 0, 0}, 0.0f, 1.0f);
      const iss::TriangleTestResult want = iss::triangle_test(ray, tri, previous);
      const iss::TriangleTestResult got = backend.triangle_test(ray, tri, previous);
      tri_diff += got.hit != want.hit || !same_partial(got.partial, want.partial);
    }
  });
  const iss::FusedBackendCounts c = backend.counts();
  std::printf("RTL backend: %llu box tests (%llu cycles), %llu triangle tests (%llu cycles), %llu slow-path, "
              "%llu + %llu latency mismatches\n",
              static_cast<unsigned long long>(c.box_tests), static_cast<unsigned long long>(c.box_cycles),
              static_cast<unsigned long long>(c.triangle_tests), static_cast<unsigned long long>(c.triangle_cycles),
              static_cast<unsigned long long>(c.triangle_slow_path_tests),
              static_cast<unsigned long long>(c.box_latency_mismatches),
              static_cast<unsigned long long>(c.triangle_latency_mismatches));
  EXPECT_EQ(box_diff, 0u);
  EXPECT_EQ(tri_diff, 0u);
  EXPECT_EQ(c.box_tests, boxes.size());
  EXPECT_EQ(c.triangle_tests, tris.size());
  EXPECT_EQ(c.box_latency_mismatches, 0u);
  EXPECT_EQ(c.triangle_latency_mismatches, 0u);
  EXPECT_GT(c.triangle_slow_path_tests, tris.size() / 100);
  // Each op: one edge on the pins, then its latency.
  const uint32_t box_latency = configured_backend().box_latency, tri_latency = configured_backend().triangle_latency;
  EXPECT_EQ(c.box_cycles, c.box_tests * (box_latency + 1));
  EXPECT_EQ(c.triangle_cycles, c.triangle_tests * (tri_latency + 1) +
                                   c.triangle_slow_path_tests * rtl::kTriangleSlowPathExtraCycles);
}

// A config whose latencies the RTL does not have: every op is a mismatch (the slow path's too).
TEST(RtlFusedBackend, CountsEveryOpWhoseLatencyDiffersFromTheConfig) {
  rtl::RtlBackendConfig config = configured_backend();
  config.box_latency += 1;
  config.triangle_latency -= 1;
  rtl::RtlFusedBackend backend("backend", config);
  const std::vector<rtl_test::BoxOp> boxes = rtl_test::box_cases(200, 93);
  const std::vector<rtl_test::TriOp> tris = rtl_test::triangle_cases(200, 94);
  run_in_thread([&] {
    for (const rtl_test::BoxOp& op : boxes) {
      strata_pipe_box box{};
      for (int a = 0; a < 3; ++a) {
        box.min[a] = op.bmin[a];
        box.max[a] = op.bmax[a];
      }
      (void)backend.box_test(pipe_ray(op.ray.origin, {0, 0, 0}, op.ray.inv_dir, op.ray.tmin, op.ray.tmax), box);
    }
    for (const rtl_test::TriOp& op : tris) {
      strata_pipe_triangle tri{};
      const float v[9] = {op.v0.x, op.v0.y, op.v0.z, op.v1.x, op.v1.y, op.v1.z, op.v2.x, op.v2.y, op.v2.z};
      std::memcpy(&tri, v, sizeof v);
      (void)backend.triangle_test(pipe_ray(op.origin, op.dir, {0, 0, 0}, 0.0f, 1.0f), tri, TrianglePartial{});
    }
  });
  const iss::FusedBackendCounts c = backend.counts();
  EXPECT_EQ(c.box_latency_mismatches, boxes.size());
  EXPECT_EQ(c.triangle_latency_mismatches, tris.size());
  EXPECT_GT(c.triangle_slow_path_tests, 0u);
}

}  // namespace
}  // namespace strata
