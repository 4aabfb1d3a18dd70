#include "model/tm/tm_config.h"

#include <stdexcept>
#include <string>

namespace strata::tm {

namespace {

void require(bool ok, const char* field, const char* why) {
  if (!ok) throw std::invalid_argument(std::string("TmConfig: ") + field + " " + why);
}

void check_unit(const XuUnitConfig& u, const char* count_field, const char* latency_field) {
  require(u.count > 0, count_field, "must be at least 1");
  require(u.latency > 0, latency_field, "must be at least 1");
}

void check_pipeline(const FusedPipelineConfig& p, const XuConfig& xu, const char* const fields[5]) {
  // At least one multiplier and one adder must stay general, or general FP work (shading,
  // address math) could never run while the pipeline is configured.
  require(p.multipliers < xu.fp_mul.count, fields[0], "must leave at least one of xu.fp_mul.count for general use");
  require(p.adders < xu.fp_add.count, fields[1], "must leave at least one of xu.fp_add.count for general use");
  require(p.initiation_interval > 0, fields[2], "must be at least 1");
  require(p.latency > 0, fields[3], "must be at least 1");
  require(p.issue_width > 0, fields[4], "must be at least 1");
}

}  // namespace

void TmConfig::validate() const {
  require(tps > 0, "tps", "must be at least 1");

  require(tp.int_alu_latency > 0, "tp.int_alu_latency", "must be at least 1");
  require(tp.branch_latency > 0, "tp.branch_latency", "must be at least 1");
  require(tp.system_latency > 0, "tp.system_latency", "must be at least 1");
  require(tp.fp_move_latency > 0, "tp.fp_move_latency", "must be at least 1");
  require(tp.id_latency > 0, "tp.id_latency", "must be at least 1");
  require(tp.pipe_input_latency > 0, "tp.pipe_input_latency", "must be at least 1");
  require(tp.control_latency > 0, "tp.control_latency", "must be at least 1");

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
  require(pipelines.triangle_divide_latency > 0, "pipelines.triangle_divide_latency", "must be at least 1");

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
}

}  // namespace strata::tm
