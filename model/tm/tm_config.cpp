#include "model/tm/tm_config.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace strata::tm {

namespace {

void require(bool ok, const char* field, const char* why) {
  if (!ok) throw std::invalid_argument(std::string("TmConfig: ") + field + " " + why);
}

// Longer latencies would run for ever in simulated time (a documented range, as the memory's).
constexpr uint32_t kMaxLatencyCycles = 65536;

void check_latency(uint32_t latency, const char* field) {
  require(latency > 0, field, "must be at least 1");
  require(latency <= kMaxLatencyCycles, field, "must be at most 65536 cycles");
}

void check_unit(const XuUnitConfig& u, const char* count_field, const char* latency_field) {
  require(u.count > 0, count_field, "must be at least 1");
  check_latency(u.latency, latency_field);
}

void check_pipeline(const FusedPipelineConfig& p, const XuConfig& xu, const char* const fields[5]) {
  // At least one multiplier and one adder must stay general, or general FP work (shading,
  // address math) could never run while the pipeline is configured.
  require(p.multipliers < xu.fp_mul.count, fields[0], "must leave at least one of xu.fp_mul.count for general use");
  require(p.adders < xu.fp_add.count, fields[1], "must leave at least one of xu.fp_add.count for general use");
  require(p.initiation_interval > 0, fields[2], "must be at least 1");
  check_latency(p.latency, fields[3]);
  require(p.issue_width > 0, fields[4], "must be at least 1");
}

}  // namespace

void TmConfig::validate() const {
  require(tps > 0, "tps", "must be at least 1");

  check_latency(tp.int_alu_latency, "tp.int_alu_latency");
  check_latency(tp.branch_latency, "tp.branch_latency");
  check_latency(tp.system_latency, "tp.system_latency");
  check_latency(tp.fp_move_latency, "tp.fp_move_latency");
  check_latency(tp.id_latency, "tp.id_latency");
  check_latency(tp.pipe_input_latency, "tp.pipe_input_latency");
  check_latency(tp.control_latency, "tp.control_latency");

  check_unit(xu.fp_mul, "xu.fp_mul.count", "xu.fp_mul.latency");
  check_unit(xu.fp_add, "xu.fp_add.count", "xu.fp_add.latency");
  check_unit(xu.fp_cmp, "xu.fp_cmp.count", "xu.fp_cmp.latency");
  check_unit(xu.fp_div, "xu.fp_div.count", "xu.fp_div.latency");
  check_unit(xu.fp_inv_sqrt, "xu.fp_inv_sqrt.count", "xu.fp_inv_sqrt.latency");
  check_unit(xu.int_mul, "xu.int_mul.count", "xu.int_mul.latency");
  check_unit(xu.int_div, "xu.int_div.count", "xu.int_div.latency");

  static const char* const kBox[5] = {"pipelines.box.multipliers", "pipelines.box.adders",
                                      "pipelines.box.initiation_interval", "pipelines.box.latency",
                                      "pipelines.box.issue_width"};
  static const char* const kTriangle[5] = {"pipelines.triangle.multipliers", "pipelines.triangle.adders",
                                           "pipelines.triangle.initiation_interval",
                                           "pipelines.triangle.latency", "pipelines.triangle.issue_width"};
  check_pipeline(pipelines.box, xu, kBox);
  check_pipeline(pipelines.triangle, xu, kTriangle);
  check_latency(pipelines.triangle_divide_latency, "pipelines.triangle_divide_latency");
  require(pipelines.reconfigure_cycles <= kMaxLatencyCycles, "pipelines.reconfigure_cycles", "must be at most 65536 cycles");

  require(xu_horizon_cycles >= 64 && xu_horizon_cycles <= (1u << 20), "xu_horizon_cycles",
          "must be between 64 and 1048576");
  require(xu_history_cycles > 0, "xu_history_cycles", "must be at least 1");
  require(xu_history_cycles <= xu_horizon_cycles / 4, "xu_history_cycles",
          "must be at most a quarter of xu_horizon_cycles (the rest is room for bookings ahead)");
  // The longest single occupancy must fit in the room ahead many times over.
  const uint32_t longest[] = {xu.fp_div.latency, xu.fp_inv_sqrt.latency, xu.int_div.latency,
                              xu.fp_mul.latency, xu.fp_add.latency, xu.fp_cmp.latency, xu.int_mul.latency,
                              pipelines.box.initiation_interval, pipelines.triangle.initiation_interval};
  for (uint32_t l : longest)
    require(l <= xu_horizon_cycles / 16, "xu_horizon_cycles", "must be at least 16 times the longest unit occupancy");
  // A pipeline books its result port `latency` cycles ahead, so that too must fit the window.
  const std::pair<uint32_t, const char*> reach[] = {{pipelines.box.latency, "pipelines.box.latency"},
                                                    {pipelines.triangle.latency, "pipelines.triangle.latency"},
                                                    {pipelines.triangle_divide_latency, "pipelines.triangle_divide_latency"}};
  for (const auto& [l, field] : reach)
    require(l <= xu_horizon_cycles / 16, field, "must be at most a sixteenth of xu_horizon_cycles (its bookings reach that far ahead)");
}

}  // namespace strata::tm
