#include "model/iss/decoder.h"

#include "firmware/abi/strata_isa.h"

namespace strata::iss {
namespace {

constexpr uint32_t bits(uint32_t w, unsigned hi, unsigned lo) {
  return (w >> lo) & ((1u << (hi - lo + 1)) - 1u);
}

constexpr int32_t imm_i(uint32_t w) { return static_cast<int32_t>(w) >> 20; }

constexpr int32_t imm_s(uint32_t w) {
  return (static_cast<int32_t>(w & 0xFE000000u) >> 20) | static_cast<int32_t>(bits(w, 11, 7));
}

constexpr int32_t imm_b(uint32_t w) {
  const uint32_t u = (bits(w, 31, 31) << 12) | (bits(w, 7, 7) << 11) | (bits(w, 30, 25) << 5) |
                     (bits(w, 11, 8) << 1);
  return static_cast<int32_t>(u << 19) >> 19;
}

constexpr int32_t imm_j(uint32_t w) {
  const uint32_t u = (bits(w, 31, 31) << 20) | (bits(w, 19, 12) << 12) | (bits(w, 20, 20) << 11) |
                     (bits(w, 30, 21) << 1);
  return static_cast<int32_t>(u << 11) >> 11;
}

Op decode_op(uint32_t w);

Op decode_custom0(uint32_t f3, uint32_t f7) {
  switch (f3) {
    case STRATA_F3_ID:
      switch (f7) {
        case STRATA_ID_THREAD: return Op::kStThreadId;
        case STRATA_ID_TP: return Op::kStTpId;
        case STRATA_ID_TM: return Op::kStTmId;
        case STRATA_ID_THREAD_COUNT: return Op::kStThreadCount;
        case STRATA_ID_TPS_PER_TM: return Op::kStTpsPerTm;
        case STRATA_ID_TM_COUNT: return Op::kStTmCount;
      }
      break;
    case STRATA_F3_GLOBAL:
      switch (f7) {
        case STRATA_GLOBAL_ATOMIC_INC: return Op::kStAtomicInc;
        case STRATA_GLOBAL_ATOMIC_ADD: return Op::kStAtomicAdd;
        case STRATA_GLOBAL_READ: return Op::kStGlobalRead;
        case STRATA_GLOBAL_WRITE: return Op::kStGlobalWrite;
      }
      break;
    case STRATA_F3_STREAM:
      switch (f7) {
        case STRATA_STREAM_CAPACITY: return Op::kStStreamCapacity;
        case STRATA_STREAM_PUSH: return Op::kStStreamPush;
        case STRATA_STREAM_POP: return Op::kStStreamPop;
        case STRATA_STREAM_ASSIGN: return Op::kStStreamAssign;
        case STRATA_STREAM_PUSH64: return Op::kStStreamPush64;
        case STRATA_STREAM_POP64: return Op::kStStreamPop64;
      }
      break;
    case STRATA_F3_CONTROL:
      if (f7 == STRATA_CONTROL_HALT) return Op::kStHalt;
      break;
  }
  return Op::kIllegal;
}

Op decode_custom1(uint32_t f3, uint32_t f7) {
  switch (f3) {
    case STRATA_F3_PIPE_CONFIG:
      switch (f7) {
        case STRATA_PIPE_GENERAL: return Op::kStPipeGeneral;
        case STRATA_PIPE_BOX: return Op::kStPipeBox;
        case STRATA_PIPE_TRIANGLE: return Op::kStPipeTriangle;
      }
      break;
    case STRATA_F3_PIPE_LOAD:
      switch (f7) {
        case STRATA_LOAD_RAY: return Op::kStLoadRay;
        case STRATA_LOAD_BOX: return Op::kStLoadBox;
        case STRATA_LOAD_TRIANGLE: return Op::kStLoadTriangle;
        case STRATA_SET_TMAX: return Op::kStSetTmax;
      }
      break;
    case STRATA_F3_PIPE_TEST:
      switch (f7) {
        case STRATA_BOX_TEST: return Op::kStBoxTest;
        case STRATA_TRIANGLE_TEST: return Op::kStTriangleTest;
        case STRATA_TRIANGLE_DIVIDE: return Op::kStTriangleDivide;
      }
      break;
  }
  return Op::kIllegal;
}

Op decode_op_fp(uint32_t w) {
  const uint32_t f3 = bits(w, 14, 12), rs2 = bits(w, 24, 20);
  switch (bits(w, 31, 25)) {
    case 0x00: return Op::kFadd;
    case 0x04: return Op::kFsub;
    case 0x08: return Op::kFmul;
    case 0x0C: return Op::kFdiv;
    case 0x2C: return rs2 == 0 ? Op::kFsqrt : Op::kIllegal;
    case 0x10: return f3 == 0 ? Op::kFsgnj : f3 == 1 ? Op::kFsgnjn : f3 == 2 ? Op::kFsgnjx : Op::kIllegal;
    case 0x14: return f3 == 0 ? Op::kFmin : f3 == 1 ? Op::kFmax : Op::kIllegal;
    case 0x60: return rs2 == 0 ? Op::kFcvtWS : rs2 == 1 ? Op::kFcvtWuS : Op::kIllegal;
    case 0x70:
      if (rs2 != 0) return Op::kIllegal;
      return f3 == 0 ? Op::kFmvXW : f3 == 1 ? Op::kFclass : Op::kIllegal;
    case 0x50: return f3 == 2 ? Op::kFeq : f3 == 1 ? Op::kFlt : f3 == 0 ? Op::kFle : Op::kIllegal;
    case 0x68: return rs2 == 0 ? Op::kFcvtSW : rs2 == 1 ? Op::kFcvtSWu : Op::kIllegal;
    case 0x78: return rs2 == 0 && f3 == 0 ? Op::kFmvWX : Op::kIllegal;
  }
  return Op::kIllegal;
}

Op decode_op(uint32_t w) {
  const uint32_t f3 = bits(w, 14, 12), f7 = bits(w, 31, 25);
  switch (bits(w, 6, 0)) {
    case 0x37: return Op::kLui;
    case 0x17: return Op::kAuipc;
    case 0x6F: return Op::kJal;
    case 0x67: return f3 == 0 ? Op::kJalr : Op::kIllegal;
    case 0x63: {
      constexpr Op kBranches[8] = {Op::kBeq, Op::kBne, Op::kIllegal, Op::kIllegal,
                                   Op::kBlt, Op::kBge, Op::kBltu, Op::kBgeu};
      return kBranches[f3];
    }
    case 0x03: {
      constexpr Op kLoads[8] = {Op::kLb, Op::kLh, Op::kLw, Op::kIllegal,
                                Op::kLbu, Op::kLhu, Op::kIllegal, Op::kIllegal};
      return kLoads[f3];
    }
    case 0x23: return f3 == 0 ? Op::kSb : f3 == 1 ? Op::kSh : f3 == 2 ? Op::kSw : Op::kIllegal;
    case 0x13:
      switch (f3) {
        case 0: return Op::kAddi;
        case 2: return Op::kSlti;
        case 3: return Op::kSltiu;
        case 4: return Op::kXori;
        case 6: return Op::kOri;
        case 7: return Op::kAndi;
        case 1: return f7 == 0 ? Op::kSlli : Op::kIllegal;
        case 5: return f7 == 0 ? Op::kSrli : f7 == 0x20 ? Op::kSrai : Op::kIllegal;
      }
      return Op::kIllegal;
    case 0x33:
      if (f7 == 0x00) {
        constexpr Op kOps[8] = {Op::kAdd, Op::kSll, Op::kSlt, Op::kSltu,
                                Op::kXor, Op::kSrl, Op::kOr, Op::kAnd};
        return kOps[f3];
      }
      if (f7 == 0x20) return f3 == 0 ? Op::kSub : f3 == 5 ? Op::kSra : Op::kIllegal;
      if (f7 == 0x01) {
        constexpr Op kOps[8] = {Op::kMul, Op::kMulh, Op::kMulhsu, Op::kMulhu,
                                Op::kDiv, Op::kDivu, Op::kRem, Op::kRemu};
        return kOps[f3];
      }
      return Op::kIllegal;
    case 0x0F: return f3 == 0 ? Op::kFence : f3 == 1 ? Op::kFenceI : Op::kIllegal;
    case 0x73:
      switch (f3) {
        case 0:
          switch (w) {
            case 0x00000073: return Op::kEcall;
            case 0x00100073: return Op::kEbreak;
            case 0x30200073: return Op::kMret;
            case 0x10500073: return Op::kWfi;
          }
          return Op::kIllegal;
        case 1: return Op::kCsrrw;
        case 2: return Op::kCsrrs;
        case 3: return Op::kCsrrc;
        case 5: return Op::kCsrrwi;
        case 6: return Op::kCsrrsi;
        case 7: return Op::kCsrrci;
      }
      return Op::kIllegal;
    case 0x07: return f3 == 2 ? Op::kFlw : Op::kIllegal;
    case 0x27: return f3 == 2 ? Op::kFsw : Op::kIllegal;
    // The fused multiply-adds: fmt (bits 26:25) must be S.
    case 0x43: return bits(w, 26, 25) == 0 ? Op::kFmadd : Op::kIllegal;
    case 0x47: return bits(w, 26, 25) == 0 ? Op::kFmsub : Op::kIllegal;
    case 0x4B: return bits(w, 26, 25) == 0 ? Op::kFnmsub : Op::kIllegal;
    case 0x4F: return bits(w, 26, 25) == 0 ? Op::kFnmadd : Op::kIllegal;
    case 0x53: return decode_op_fp(w);
    case STRATA_OPCODE_THREAD: return decode_custom0(f3, f7);
    case STRATA_OPCODE_PIPE: return decode_custom1(f3, f7);
  }
  return Op::kIllegal;
}

int32_t decode_imm(Op op, uint32_t w) {
  switch (op_info(op).format) {
    case Format::kI:
    case Format::kLoad:
    case Format::kJalr:
    case Format::kFpLoad: return imm_i(w);
    case Format::kStore:
    case Format::kFpStore: return imm_s(w);
    case Format::kBranch: return imm_b(w);
    case Format::kJal: return imm_j(w);
    case Format::kUpper: return static_cast<int32_t>(w & 0xFFFFF000u);
    case Format::kShift: return static_cast<int32_t>(bits(w, 24, 20));
    case Format::kCsr:
    case Format::kCsrImm: return static_cast<int32_t>(bits(w, 31, 20));
    case Format::kFence: return static_cast<int32_t>(bits(w, 27, 20));  // pred/succ, for disassembly
    default: return 0;
  }
}

unsigned rf_slot(const Decoded& d) {
  const uint8_t fields[4] = {d.rd, d.rs1, d.rs2, d.rs3};
  unsigned ir = 0, iw = 0, fr = 0, fw = 0;
  const OpInfo& info = op_info(d.op);
  for (unsigned i = 0; i < 4; ++i) {
    switch (info.role[i]) {
      case Role::kIntSrc: ir += fields[i] != 0; break;
      case Role::kIntDst: iw += fields[i] != 0; break;
      case Role::kFpSrc: ++fr; break;
      case Role::kFpDst: ++fw; break;
      case Role::kNone: break;
    }
  }
  return ir + 3 * (iw + 2 * (fr + 4 * fw));
}

}  // namespace

Decoded decode(uint32_t w) {
  Decoded d;
  d.op = decode_op(w);
  if (d.op == Op::kIllegal) return d;
  const OpInfo& info = op_info(d.op);
  d.rd = static_cast<uint8_t>(bits(w, 11, 7));
  d.rs1 = static_cast<uint8_t>(bits(w, 19, 15));
  d.rs2 = static_cast<uint8_t>(bits(w, 24, 20));
  d.rs3 = static_cast<uint8_t>(bits(w, 31, 27));
  d.rm = static_cast<uint8_t>(bits(w, 14, 12));
  d.imm = decode_imm(d.op, w);
  // Rounding modes 5 and 6 are reserved; a static one is illegal at decode time.
  if (info.has_rm && (d.rm == 5 || d.rm == 6)) return Decoded{};
  // The extension keeps unused register fields zero, so later revisions can give them meaning.
  if (is_strata(d.op)) {
    const uint8_t fields[3] = {d.rd, d.rs1, d.rs2};
    for (unsigned i = 0; i < 3; ++i)
      if (info.role[i] == Role::kNone && fields[i] != 0) return Decoded{};
  }
  d.rf = static_cast<uint8_t>(rf_slot(d));
  return d;
}

}  // namespace strata::iss
