// What the XU crossbar counts: how much each unit class was used and in which mode, the
// fused operations, and the reconfigurations. Operations are counted by class so that the
// energy model can multiply them by a per-operation energy.
#pragma once

#include "model/tm/xu_class.h"

#include <array>
#include <cstdint>

namespace strata::tm {

struct XuUse {
  uint64_t ops = 0;
  // Unit-cycles the operations held an issue slot: 1 per op on a pipelined unit, the
  // latency on a non-pipelined one. Utilisation = busy / (units * cycles).
  uint64_t busy_unit_cycles = 0;

  XuUse& operator+=(const XuUse& o) {
    ops += o.ops;
    busy_unit_cycles += o.busy_unit_cycles;
    return *this;
  }
};

struct XuStats {
  // [mode][class]: use of each unit class, by the mode in force in the cycle the op started.
  // strata.tridiv counts as an fp_div op, a fused multiply-add as one fp_mul and one fp_add.
  std::array<std::array<XuUse, kXuClassCount>, kModeCount> by_mode{};
  uint64_t box_tests = 0;
  uint64_t triangle_tests = 0;
  uint64_t triangle_divides = 0;
  uint64_t fused_multiply_adds = 0;
  uint64_t box_busy_cycles = 0;       // lane-cycles of the box pipeline's initiation slots
  uint64_t triangle_busy_cycles = 0;  // lane-cycles of the triangle pipeline's slots
  uint64_t reconfigurations = 0;      // mode changes (a request for the current mode is not one)
  uint64_t reconfiguring_cycles = 0;  // switching time after the drain
  std::array<uint64_t, kModeCount> mode_cycles{};  // cycles each mode was usable
  // Requests for a cycle the calendars had already forgotten; they were served as if made
  // at the oldest remembered cycle. Nonzero means xu_history_cycles is too small.
  uint64_t late_requests = 0;

  XuUse total(XuClass c) const {
    XuUse sum;
    for (const auto& mode : by_mode) sum += mode[static_cast<unsigned>(c)];
    return sum;
  }
  const XuUse& in(PipelineMode m, XuClass c) const {
    return by_mode[static_cast<unsigned>(m)][static_cast<unsigned>(c)];
  }
};

}  // namespace strata::tm
