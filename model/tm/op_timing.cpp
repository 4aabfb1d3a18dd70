#include "model/tm/op_timing.h"

namespace strata::tm {

namespace {

using iss::InstrClass;
using iss::Op;

OpTiming local(uint32_t latency) { return {Route::kLocal, XuClass::kCount, PipelineMode::kGeneral, 0, 0, latency}; }
OpTiming xu(XuClass cls, const XuUnitConfig& unit) {
  return {Route::kXu, cls, PipelineMode::kGeneral, 0, 0, unit.latency};
}
OpTiming memory(uint8_t writes_pipe = 0) {
  return {Route::kMemory, XuClass::kCount, PipelineMode::kGeneral, 0, writes_pipe, 0};
}
OpTiming configure(PipelineMode mode) { return {Route::kConfigure, XuClass::kCount, mode, 0, 0, 0}; }

OpTiming timing_of(Op op, const TmConfig& c) {
  const TpConfig& tp = c.tp;
  const XuConfig& u = c.xu;
  switch (op) {
    // Integer M extension: multiplies and divides go to different units.
    case Op::kMul: case Op::kMulh: case Op::kMulhsu: case Op::kMulhu:
      return xu(XuClass::kIntMul, u.int_mul);
    case Op::kDiv: case Op::kDivu: case Op::kRem: case Op::kRemu:
      return xu(XuClass::kIntDiv, u.int_div);
    case Op::kFdiv: return xu(XuClass::kFpDiv, u.fp_div);
    case Op::kFsqrt: return xu(XuClass::kFpInvSqrt, u.fp_inv_sqrt);
    case Op::kFmin: case Op::kFmax: case Op::kFeq: case Op::kFlt: case Op::kFle:
      return xu(XuClass::kFpCmp, u.fp_cmp);
    // Conversions need an aligner and normaliser: the adder's datapath.
    case Op::kFcvtWS: case Op::kFcvtWuS: case Op::kFcvtSW: case Op::kFcvtSWu:
      return xu(XuClass::kFpAdd, u.fp_add);
    // Sign injection, moves and classify only move or inspect bits.
    case Op::kFsgnj: case Op::kFsgnjn: case Op::kFsgnjx: case Op::kFmvXW: case Op::kFmvWX: case Op::kFclass:
      return local(tp.fp_move_latency);
    case Op::kStPipeGeneral: return configure(PipelineMode::kGeneral);
    case Op::kStPipeBox: return configure(PipelineMode::kBox);
    case Op::kStPipeTriangle: return configure(PipelineMode::kTriangle);
    case Op::kStLoadRay: return memory(kPipeRay);
    case Op::kStLoadBox: return memory(kPipeBox);
    case Op::kStLoadTriangle: return memory(kPipeTriangle);
    case Op::kStSetTmax: {
      OpTiming t = local(tp.pipe_input_latency);
      t.writes_pipe = kPipeRay;
      return t;
    }
    case Op::kStBoxTest:
      return {Route::kBoxTest, XuClass::kCount, PipelineMode::kBox, kPipeRay | kPipeBox, 0,
              c.pipelines.box.latency};
    case Op::kStTriangleTest:
      return {Route::kTriangleTest, XuClass::kCount, PipelineMode::kTriangle, kPipeRay | kPipeTriangle,
              kPipePartial, c.pipelines.triangle.latency};
    case Op::kStTriangleDivide:
      return {Route::kTriangleDivide, XuClass::kCount, PipelineMode::kTriangle, kPipePartial, 0,
              c.pipelines.triangle_divide_latency};
    default: break;
  }
  switch (iss::op_info(op).cls) {
    case InstrClass::kIntAlu: return local(tp.int_alu_latency);
    case InstrClass::kBranch: return local(tp.branch_latency);
    case InstrClass::kLoad: case InstrClass::kStore: return memory();
    case InstrClass::kFpAdd: return xu(XuClass::kFpAdd, u.fp_add);
    case InstrClass::kFpMul: return xu(XuClass::kFpMul, u.fp_mul);
    case InstrClass::kFpFused:
      return {Route::kFusedMultiplyAdd, XuClass::kCount, PipelineMode::kGeneral, 0, 0,
              u.fp_mul.latency + u.fp_add.latency};
    case InstrClass::kStrataId: return local(tp.id_latency);
    case InstrClass::kStrataGlobal: case InstrClass::kStrataStream: return memory();
    case InstrClass::kStrataControl: return local(tp.control_latency);
    // System ops, and kIllegal: an illegal instruction traps in the ISS and costs a slot.
    default: return local(tp.system_latency);
  }
}

}  // namespace

OpTimingTable::OpTimingTable(const TmConfig& config) {
  config.validate();
  for (unsigned i = 0; i < iss::kOpCount; ++i) {
    OpTiming t = timing_of(static_cast<Op>(i), config);
    const iss::OpInfo& info = iss::op_info(static_cast<Op>(i));
    for (unsigned slot = 0; slot < 4; ++slot) {
      const uint8_t b = static_cast<uint8_t>(1u << slot);
      switch (info.role[slot]) {
        case iss::Role::kIntDst: t.int_results |= b; [[fallthrough]];
        case iss::Role::kIntSrc: t.int_operands |= b; break;
        case iss::Role::kFpDst: t.fp_results |= b; [[fallthrough]];
        case iss::Role::kFpSrc: t.fp_operands |= b; break;
        default: break;
      }
    }
    table_[i] = t;
  }
}

}  // namespace strata::tm
