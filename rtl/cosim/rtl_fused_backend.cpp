// The RTL chip run's fused-pipeline backend: see rtl_fused_backend.h.
#include "rtl/cosim/rtl_fused_backend.h"

#include <limits>
#include <utility>

namespace strata::rtl {

RtlFusedBackend::RtlFusedBackend(sc_core::sc_module_name name, RtlBackendConfig config)
    : sc_core::sc_module(name), config_(std::move(config)), transactor_("transactor") {
  socket.bind(transactor_.socket);
  payload_.set_command(tlm::TLM_IGNORE_COMMAND);
  if (!config_.vcd_path.empty()) transactor_.pipelines().open_vcd(config_.vcd_path);
}

void RtlFusedBackend::transport(FusedOpExtension& op) {
  if (!config_.vcd_path.empty()) {
    const uint64_t c = config_.cycle ? config_.cycle() : 0;
    if (c >= config_.vcd_start && c <= config_.vcd_end)
      transactor_.pipelines().trace_from(c * config_.ps_per_cycle);
    else
      transactor_.pipelines().trace_off();
  }
  payload_.set_extension(&op);
  payload_.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
  // Zero time: the transactor neither waits nor moves the delay (the XU crossbar times the op).
  sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
  socket->b_transport(payload_, delay);
  payload_.clear_extension(&op);
  if (payload_.get_response_status() != tlm::TLM_OK_RESPONSE)
    SC_REPORT_FATAL("strata/rtl/backend", "the RTL pipeline transactor refused a fused operation");
}

iss::FusedBackendCounts RtlFusedBackend::counts() const {
  iss::FusedBackendCounts c = counts_;
  c.box_cycles = transactor_.box_cycle() - ZeroTimeTransactor::kResetCycles;
  c.triangle_cycles = transactor_.triangle_cycle() - ZeroTimeTransactor::kResetCycles;
  return c;
}

iss::BoxTestResult RtlFusedBackend::box_test(const strata_pipe_ray& ray, const strata_pipe_box& box) {
  FusedOpExtension op;
  op.kind = FusedOpKind::kBox;
  for (int i = 0; i < 3; ++i) {
    op.box.bmin[i] = box.min[i];
    op.box.bmax[i] = box.max[i];
  }
  op.box.ray = {load_vec3(ray.origin), load_vec3(ray.inv_direction), ray.tmin, ray.tmax};
  transport(op);
  ++counts_.box_tests;
  if (op.latency_cycles != config_.box_latency) ++counts_.box_latency_mismatches;
  const BoxResult& r = op.box_result;
  return {r.hit, r.hit ? r.t_entry : std::numeric_limits<float>::infinity()};
}

iss::TriangleTestResult RtlFusedBackend::triangle_test(const strata_pipe_ray& ray, const strata_pipe_triangle& tri,
                                                       const TrianglePartial& previous) {
  FusedOpExtension op;
  op.kind = FusedOpKind::kTriangle;
  op.triangle = {load_vec3(tri.v0), load_vec3(tri.v1), load_vec3(tri.v2), load_vec3(ray.origin),
                 load_vec3(ray.direction)};
  transport(op);
  const TriangleResult& r = op.triangle_result;
  ++counts_.triangle_tests;
  uint32_t expected = config_.triangle_latency;
  if (r.exact) {
    ++counts_.triangle_slow_path_tests;
    expected += kTriangleSlowPathExtraCycles;
  }
  if (op.latency_cycles != expected) ++counts_.triangle_latency_mismatches;
  return {r.hit, r.hit ? r.partial : previous};
}

}  // namespace strata::rtl
