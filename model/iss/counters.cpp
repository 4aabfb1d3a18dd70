#include "model/iss/counters.h"

#include <cstdio>

namespace strata::iss {

Counters& Counters::operator+=(const Counters& o) {
  retired += o.retired;
  for (unsigned i = 0; i < kClassCount; ++i) by_class[i] += o.by_class[i];
  int_reads += o.int_reads;
  int_writes += o.int_writes;
  fp_reads += o.fp_reads;
  fp_writes += o.fp_writes;
  return *this;
}

const char* class_name(InstrClass c) {
  switch (c) {
    case InstrClass::kIntAlu: return "int_alu";
    case InstrClass::kBranch: return "branch_jump";
    case InstrClass::kLoad: return "load";
    case InstrClass::kStore: return "store";
    case InstrClass::kMulDiv: return "mul_div";
    case InstrClass::kFpAdd: return "fp_add";
    case InstrClass::kFpMul: return "fp_mul";
    case InstrClass::kFpDivSqrt: return "fp_div_sqrt";
    case InstrClass::kFpFused: return "fp_fused";
    case InstrClass::kFpMisc: return "fp_cmp_cvt_move";
    case InstrClass::kSystem: return "csr_system";
    case InstrClass::kStrataId: return "strata_id";
    case InstrClass::kStrataGlobal: return "strata_global";
    case InstrClass::kStrataStream: return "strata_stream";
    case InstrClass::kStrataPipeConfig: return "strata_pipe_config";
    case InstrClass::kStrataPipeLoad: return "strata_pipe_load";
    case InstrClass::kStrataBoxTest: return "strata_box_test";
    case InstrClass::kStrataTriangleTest: return "strata_triangle_test";
    case InstrClass::kStrataTriangleDivide: return "strata_triangle_divide";
    case InstrClass::kStrataControl: return "strata_control";
    case InstrClass::kIllegal: return "illegal";
    case InstrClass::kCount: break;
  }
  return "?";
}

Counters fold_counters(const std::array<uint64_t, kOpCount>& op_counts,
                       const std::array<uint64_t, kRfSlotCount>& rf_counts) {
  Counters c;
  for (unsigned op = 0; op < kOpCount; ++op) {
    c.retired += op_counts[op];
    c.by_class[static_cast<unsigned>(kOpInfo[op].cls)] += op_counts[op];
  }
  for (unsigned slot = 0; slot < kRfSlotCount; ++slot) {
    const RfAccesses a = rf_slot_accesses(slot);
    c.int_reads += rf_counts[slot] * a.int_reads;
    c.int_writes += rf_counts[slot] * a.int_writes;
    c.fp_reads += rf_counts[slot] * a.fp_reads;
    c.fp_writes += rf_counts[slot] * a.fp_writes;
  }
  return c;
}

std::string format_counters(const Counters& c) {
  std::string out;
  char line[96];
  auto row = [&](const char* name, uint64_t n) {
    const double share = c.retired ? 100.0 * static_cast<double>(n) / static_cast<double>(c.retired) : 0.0;
    std::snprintf(line, sizeof line, "  %-24s %14llu  %5.1f%%\n", name, static_cast<unsigned long long>(n), share);
    out += line;
  };
  std::snprintf(line, sizeof line, "  %-24s %14llu\n", "retired", static_cast<unsigned long long>(c.retired));
  out += line;
  for (unsigned i = 0; i < kClassCount; ++i)
    if (c.by_class[i]) row(class_name(static_cast<InstrClass>(i)), c.by_class[i]);
  std::snprintf(line, sizeof line, "  %-24s %14llu reads %14llu writes\n", "int registers",
                static_cast<unsigned long long>(c.int_reads), static_cast<unsigned long long>(c.int_writes));
  out += line;
  std::snprintf(line, sizeof line, "  %-24s %14llu reads %14llu writes\n", "fp registers",
                static_cast<unsigned long long>(c.fp_reads), static_cast<unsigned long long>(c.fp_writes));
  out += line;
  return out;
}

}  // namespace strata::iss
