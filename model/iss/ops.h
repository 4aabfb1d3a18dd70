// Every operation the ISS knows, in one table: its mnemonic, counter class, disassembly
// format and which register fields it reads or writes. Decoder, executor, disassembler,
// tracer and counters all derive from this table, so they cannot disagree.
#pragma once

#include <cstdint>

namespace strata::iss {

// Instruction classes for the retired-instruction counters (the energy model's categories).
enum class InstrClass : uint8_t {
  kIntAlu,
  kBranch,  // branches and jumps
  kLoad,    // integer and FP loads
  kStore,
  kMulDiv,
  kFpAdd,
  kFpMul,
  kFpDivSqrt,
  kFpFused,
  kFpMisc,  // FP compare, min/max, convert, sign-inject, move, classify
  kSystem,  // CSR, fence, ecall, ebreak, mret, wfi
  kStrataId,
  kStrataGlobal,
  kStrataStream,
  kStrataPipeConfig,
  kStrataPipeLoad,
  kStrataBoxTest,
  kStrataTriangleTest,
  kStrataTriangleDivide,
  kStrataControl,
  kIllegal,  // never retires; present so every op has a class
  kCount
};

enum class Format : uint8_t {
  kR, kI, kShift, kLoad, kStore, kBranch, kUpper, kJal, kJalr,
  kCsr, kCsrImm, kNone, kFence,
  kFpLoad, kFpStore,
  kOperands,  // print the role-carrying fields in order (FP ops and the STRaTA extension)
  kIllegal
};

// Roles, one character per field rd, rs1, rs2, rs3:
//   '-' unused, 'x' integer source, 'X' integer destination, 'f' FP source, 'F' FP destination.
// The last column says whether the funct3 field is a rounding mode.
#define STRATA_ISS_OPS(X)                                                        \
  X(kIllegal, "illegal", kIllegal, kIllegal, "----", 0)                         \
  X(kLui, "lui", kIntAlu, kUpper, "X---", 0)                                    \
  X(kAuipc, "auipc", kIntAlu, kUpper, "X---", 0)                                \
  X(kJal, "jal", kBranch, kJal, "X---", 0)                                      \
  X(kJalr, "jalr", kBranch, kJalr, "Xx--", 0)                                   \
  X(kBeq, "beq", kBranch, kBranch, "-xx-", 0)                                   \
  X(kBne, "bne", kBranch, kBranch, "-xx-", 0)                                   \
  X(kBlt, "blt", kBranch, kBranch, "-xx-", 0)                                   \
  X(kBge, "bge", kBranch, kBranch, "-xx-", 0)                                   \
  X(kBltu, "bltu", kBranch, kBranch, "-xx-", 0)                                 \
  X(kBgeu, "bgeu", kBranch, kBranch, "-xx-", 0)                                 \
  X(kLb, "lb", kLoad, kLoad, "Xx--", 0)                                         \
  X(kLh, "lh", kLoad, kLoad, "Xx--", 0)                                         \
  X(kLw, "lw", kLoad, kLoad, "Xx--", 0)                                         \
  X(kLbu, "lbu", kLoad, kLoad, "Xx--", 0)                                       \
  X(kLhu, "lhu", kLoad, kLoad, "Xx--", 0)                                       \
  X(kSb, "sb", kStore, kStore, "-xx-", 0)                                       \
  X(kSh, "sh", kStore, kStore, "-xx-", 0)                                       \
  X(kSw, "sw", kStore, kStore, "-xx-", 0)                                       \
  X(kAddi, "addi", kIntAlu, kI, "Xx--", 0)                                      \
  X(kSlti, "slti", kIntAlu, kI, "Xx--", 0)                                      \
  X(kSltiu, "sltiu", kIntAlu, kI, "Xx--", 0)                                    \
  X(kXori, "xori", kIntAlu, kI, "Xx--", 0)                                      \
  X(kOri, "ori", kIntAlu, kI, "Xx--", 0)                                        \
  X(kAndi, "andi", kIntAlu, kI, "Xx--", 0)                                      \
  X(kSlli, "slli", kIntAlu, kShift, "Xx--", 0)                                  \
  X(kSrli, "srli", kIntAlu, kShift, "Xx--", 0)                                  \
  X(kSrai, "srai", kIntAlu, kShift, "Xx--", 0)                                  \
  X(kAdd, "add", kIntAlu, kR, "Xxx-", 0)                                        \
  X(kSub, "sub", kIntAlu, kR, "Xxx-", 0)                                        \
  X(kSll, "sll", kIntAlu, kR, "Xxx-", 0)                                        \
  X(kSlt, "slt", kIntAlu, kR, "Xxx-", 0)                                        \
  X(kSltu, "sltu", kIntAlu, kR, "Xxx-", 0)                                      \
  X(kXor, "xor", kIntAlu, kR, "Xxx-", 0)                                        \
  X(kSrl, "srl", kIntAlu, kR, "Xxx-", 0)                                        \
  X(kSra, "sra", kIntAlu, kR, "Xxx-", 0)                                        \
  X(kOr, "or", kIntAlu, kR, "Xxx-", 0)                                          \
  X(kAnd, "and", kIntAlu, kR, "Xxx-", 0)                                        \
  X(kFence, "fence", kSystem, kFence, "----", 0)                                \
  X(kFenceI, "fence.i", kSystem, kNone, "----", 0)                              \
  X(kEcall, "ecall", kSystem, kNone, "----", 0)                                 \
  X(kEbreak, "ebreak", kSystem, kNone, "----", 0)                               \
  X(kMret, "mret", kSystem, kNone, "----", 0)                                   \
  X(kWfi, "wfi", kSystem, kNone, "----", 0)                                     \
  X(kCsrrw, "csrrw", kSystem, kCsr, "Xx--", 0)                                  \
  X(kCsrrs, "csrrs", kSystem, kCsr, "Xx--", 0)                                  \
  X(kCsrrc, "csrrc", kSystem, kCsr, "Xx--", 0)                                  \
  X(kCsrrwi, "csrrwi", kSystem, kCsrImm, "X---", 0)                             \
  X(kCsrrsi, "csrrsi", kSystem, kCsrImm, "X---", 0)                             \
  X(kCsrrci, "csrrci", kSystem, kCsrImm, "X---", 0)                             \
  X(kMul, "mul", kMulDiv, kR, "Xxx-", 0)                                        \
  X(kMulh, "mulh", kMulDiv, kR, "Xxx-", 0)                                      \
  X(kMulhsu, "mulhsu", kMulDiv, kR, "Xxx-", 0)                                  \
  X(kMulhu, "mulhu", kMulDiv, kR, "Xxx-", 0)                                    \
  X(kDiv, "div", kMulDiv, kR, "Xxx-", 0)                                        \
  X(kDivu, "divu", kMulDiv, kR, "Xxx-", 0)                                      \
  X(kRem, "rem", kMulDiv, kR, "Xxx-", 0)                                        \
  X(kRemu, "remu", kMulDiv, kR, "Xxx-", 0)                                      \
  X(kFlw, "flw", kLoad, kFpLoad, "Fx--", 0)                                     \
  X(kFsw, "fsw", kStore, kFpStore, "-xf-", 0)                                   \
  X(kFmadd, "fmadd.s", kFpFused, kOperands, "Ffff", 1)                          \
  X(kFmsub, "fmsub.s", kFpFused, kOperands, "Ffff", 1)                          \
  X(kFnmsub, "fnmsub.s", kFpFused, kOperands, "Ffff", 1)                        \
  X(kFnmadd, "fnmadd.s", kFpFused, kOperands, "Ffff", 1)                        \
  X(kFadd, "fadd.s", kFpAdd, kOperands, "Fff-", 1)                              \
  X(kFsub, "fsub.s", kFpAdd, kOperands, "Fff-", 1)                              \
  X(kFmul, "fmul.s", kFpMul, kOperands, "Fff-", 1)                              \
  X(kFdiv, "fdiv.s", kFpDivSqrt, kOperands, "Fff-", 1)                          \
  X(kFsqrt, "fsqrt.s", kFpDivSqrt, kOperands, "Ff--", 1)                        \
  X(kFsgnj, "fsgnj.s", kFpMisc, kOperands, "Fff-", 0)                           \
  X(kFsgnjn, "fsgnjn.s", kFpMisc, kOperands, "Fff-", 0)                         \
  X(kFsgnjx, "fsgnjx.s", kFpMisc, kOperands, "Fff-", 0)                         \
  X(kFmin, "fmin.s", kFpMisc, kOperands, "Fff-", 0)                             \
  X(kFmax, "fmax.s", kFpMisc, kOperands, "Fff-", 0)                             \
  X(kFcvtWS, "fcvt.w.s", kFpMisc, kOperands, "Xf--", 1)                         \
  X(kFcvtWuS, "fcvt.wu.s", kFpMisc, kOperands, "Xf--", 1)                       \
  X(kFmvXW, "fmv.x.w", kFpMisc, kOperands, "Xf--", 0)                           \
  X(kFeq, "feq.s", kFpMisc, kOperands, "Xff-", 0)                               \
  X(kFlt, "flt.s", kFpMisc, kOperands, "Xff-", 0)                               \
  X(kFle, "fle.s", kFpMisc, kOperands, "Xff-", 0)                               \
  X(kFclass, "fclass.s", kFpMisc, kOperands, "Xf--", 0)                         \
  X(kFcvtSW, "fcvt.s.w", kFpMisc, kOperands, "Fx--", 1)                         \
  X(kFcvtSWu, "fcvt.s.wu", kFpMisc, kOperands, "Fx--", 1)                       \
  X(kFmvWX, "fmv.w.x", kFpMisc, kOperands, "Fx--", 0)                           \
  X(kStThreadId, "strata.threadid", kStrataId, kOperands, "X---", 0)            \
  X(kStTpId, "strata.tpid", kStrataId, kOperands, "X---", 0)                    \
  X(kStTmId, "strata.tmid", kStrataId, kOperands, "X---", 0)                    \
  X(kStThreadCount, "strata.threadcount", kStrataId, kOperands, "X---", 0)      \
  X(kStTpsPerTm, "strata.tpspertm", kStrataId, kOperands, "X---", 0)            \
  X(kStTmCount, "strata.tmcount", kStrataId, kOperands, "X---", 0)              \
  X(kStAtomicInc, "strata.atominc", kStrataGlobal, kOperands, "Xx--", 0)        \
  X(kStAtomicAdd, "strata.atomadd", kStrataGlobal, kOperands, "Xxx-", 0)        \
  X(kStGlobalRead, "strata.gread", kStrataGlobal, kOperands, "Xx--", 0)         \
  X(kStGlobalWrite, "strata.gwrite", kStrataGlobal, kOperands, "-xx-", 0)       \
  X(kStStreamCapacity, "strata.streamcap", kStrataStream, kOperands, "X---", 0) \
  X(kStStreamPush, "strata.streampush", kStrataStream, kOperands, "Xxx-", 0)    \
  X(kStStreamPop, "strata.streampop", kStrataStream, kOperands, "Xx--", 0)      \
  X(kStStreamAssign, "strata.streamassign", kStrataStream, kOperands, "X---", 0) \
  X(kStStreamPush64, "strata.streampush64", kStrataStream, kOperands, "Xxx-", 0) \
  X(kStStreamPop64, "strata.streampop64", kStrataStream, kOperands, "Xx--", 0)   \
  X(kStHalt, "strata.halt", kStrataControl, kNone, "----", 0)                   \
  X(kStPipeGeneral, "strata.pipe.general", kStrataPipeConfig, kNone, "----", 0) \
  X(kStPipeBox, "strata.pipe.box", kStrataPipeConfig, kNone, "----", 0)         \
  X(kStPipeTriangle, "strata.pipe.tri", kStrataPipeConfig, kNone, "----", 0)    \
  X(kStLoadRay, "strata.ldray", kStrataPipeLoad, kOperands, "-x--", 0)          \
  X(kStLoadBox, "strata.ldbox", kStrataPipeLoad, kOperands, "-x--", 0)          \
  X(kStLoadTriangle, "strata.ldtri", kStrataPipeLoad, kOperands, "-x--", 0)     \
  X(kStSetTmax, "strata.settmax", kStrataPipeLoad, kOperands, "-f--", 0)        \
  X(kStBoxTest, "strata.boxtest", kStrataBoxTest, kOperands, "X-F-", 0)         \
  X(kStTriangleTest, "strata.tritest", kStrataTriangleTest, kOperands, "X---", 0) \
  X(kStTriangleDivide, "strata.tridiv", kStrataTriangleDivide, kOperands, "FFF-", 0)

enum class Op : uint8_t {
#define STRATA_ISS_OP_ENUM(name, mnem, cls, fmt, roles, rm) name,
  STRATA_ISS_OPS(STRATA_ISS_OP_ENUM)
#undef STRATA_ISS_OP_ENUM
      kCount
};

constexpr unsigned kOpCount = static_cast<unsigned>(Op::kCount);

enum class Role : uint8_t { kNone, kIntSrc, kIntDst, kFpSrc, kFpDst };

struct OpInfo {
  const char* mnemonic;
  InstrClass cls;
  Format format;
  Role role[4];  // rd, rs1, rs2, rs3
  bool has_rm;
};

constexpr Role role_from_char(char c) {
  return c == 'x'   ? Role::kIntSrc
         : c == 'X' ? Role::kIntDst
         : c == 'f' ? Role::kFpSrc
         : c == 'F' ? Role::kFpDst
                    : Role::kNone;
}

inline constexpr OpInfo kOpInfo[kOpCount] = {
#define STRATA_ISS_OP_INFO(name, mnem, cls, fmt, roles, rm)                                   \
  {mnem, InstrClass::cls, Format::fmt,                                                        \
   {role_from_char(roles[0]), role_from_char(roles[1]), role_from_char(roles[2]),             \
    role_from_char(roles[3])},                                                                \
   rm != 0},
    STRATA_ISS_OPS(STRATA_ISS_OP_INFO)
#undef STRATA_ISS_OP_INFO
};

constexpr const OpInfo& op_info(Op op) { return kOpInfo[static_cast<unsigned>(op)]; }

constexpr bool is_strata(Op op) {
  return static_cast<unsigned>(op) >= static_cast<unsigned>(Op::kStThreadId);
}

// F-extension instructions need mstatus.FS != Off; so do STRaTA ops that touch f registers.
constexpr bool touches_fp_state(Op op) {
  if (static_cast<unsigned>(op) >= static_cast<unsigned>(Op::kFlw) &&
      static_cast<unsigned>(op) <= static_cast<unsigned>(Op::kFmvWX))
    return true;
  for (Role r : op_info(op).role)
    if (r == Role::kFpSrc || r == Role::kFpDst) return true;
  return false;
}

}  // namespace strata::iss
