// Template definitions of Hart<Memory>. Include this only where you instantiate a hart with
// a memory policy other than FlatMemory.
#pragma once

#include <type_traits>
#include <utility>

#include "model/iss/csr.h"
#include "model/iss/fp_ops.h"
#include "model/iss/hart.h"
#include "model/iss/trace.h"

namespace strata::iss {

template <class Memory>
Hart<Memory>::Hart(CodeImage& code, Memory& memory, StrataHook* hook, uint32_t hart_id)
    : code_(&code), mem_(&memory), hook_(hook), hart_id_(hart_id) {
  reset(code.base());
}

template <class Memory>
void Hart<Memory>::reset(uint32_t pc) {
  x_.fill(0);
  f_.fill(0);
  pc_ = pc;
  fflags_ = frm_ = 0;
  mstatus_ = mtvec_ = mepc_ = mcause_ = mtval_ = mscratch_ = mie_ = 0;
  instret_offset_ = cycle_offset_ = stall_cycles_ = 0;
  trap_detail_ = nullptr;
  op_counts_.fill(0);
  rf_counts_.fill(0);
}

template <class Memory>
uint64_t Hart<Memory>::instructions_retired() const {
  uint64_t n = 0;
  for (uint64_t c : op_counts_) n += c;
  return n;
}

template <class Memory>
bool Hart<Memory>::read_csr(uint16_t number, uint32_t& value) const {
  const uint64_t instret = instructions_retired() + instret_offset_;
  const uint64_t cycle = cycles_now() + cycle_offset_;
  switch (number) {
    case csr::kFflags: value = fflags_; return true;
    case csr::kFrm: value = frm_; return true;
    case csr::kFcsr: value = (frm_ << 5) | fflags_; return true;
    case csr::kMstatus:
      value = mstatus_ | mstatus::kMpp | ((mstatus_ & mstatus::kFs) == mstatus::kFsDirty ? mstatus::kSd : 0u);
      return true;
    case csr::kMisa: value = kMisa; return true;
    case csr::kMie: value = mie_; return true;
    case csr::kMtvec: value = mtvec_; return true;
    case csr::kMscratch: value = mscratch_; return true;
    case csr::kMepc: value = mepc_; return true;
    case csr::kMcause: value = mcause_; return true;
    case csr::kMtval: value = mtval_; return true;
    case csr::kMip: value = 0; return true;  // no interrupt sources
    case csr::kMcycle:
    case csr::kCycle:
    case csr::kTime: value = static_cast<uint32_t>(cycle); return true;
    case csr::kMcycleh:
    case csr::kCycleh:
    case csr::kTimeh: value = static_cast<uint32_t>(cycle >> 32); return true;
    case csr::kMinstret:
    case csr::kInstret: value = static_cast<uint32_t>(instret); return true;
    case csr::kMinstreth:
    case csr::kInstreth: value = static_cast<uint32_t>(instret >> 32); return true;
    case csr::kMvendorid:
    case csr::kMarchid:
    case csr::kMimpid: value = 0; return true;
    case csr::kMhartid: value = hart_id_; return true;
  }
  return false;
}

template <class Memory>
bool Hart<Memory>::write_csr(uint16_t number, uint32_t value) {
  if ((number >> 10) == 3) return false;  // read-only range
  // A counter write sets the count as of before the writing instruction, which then
  // retires and counts as usual.
  const uint64_t retired = instructions_retired();
  const uint64_t instret = retired + instret_offset_;
  const uint64_t cycle = cycles_now() + cycle_offset_;
  switch (number) {
    case csr::kFflags: fflags_ = value & 0x1Fu; break;
    case csr::kFrm: frm_ = value & 0x7u; break;
    case csr::kFcsr:
      fflags_ = value & 0x1Fu;
      frm_ = (value >> 5) & 0x7u;
      break;
    case csr::kMstatus: mstatus_ = value & mstatus::kWritable; break;
    case csr::kMisa: break;  // WARL, fixed
    case csr::kMie: mie_ = value & 0x888u; break;
    case csr::kMtvec: mtvec_ = value & ~2u; break;  // modes: direct or vectored (no interrupts)
    case csr::kMscratch: mscratch_ = value; break;
    case csr::kMepc: mepc_ = value & ~3u; break;  // IALIGN = 32
    case csr::kMcause: mcause_ = value; break;
    case csr::kMtval: mtval_ = value; break;
    case csr::kMip: break;
    case csr::kMcycle: cycle_offset_ += ((cycle & ~uint64_t{0xFFFFFFFF}) | value) - cycle; break;
    case csr::kMcycleh: cycle_offset_ += ((cycle & 0xFFFFFFFFu) | (uint64_t{value} << 32)) - cycle; break;
    case csr::kMinstret: instret_offset_ += ((instret & ~uint64_t{0xFFFFFFFF}) | value) - instret; break;
    case csr::kMinstreth:
      instret_offset_ += ((instret & 0xFFFFFFFFu) | (uint64_t{value} << 32)) - instret;
      break;
    default: return false;
  }
  return true;
}

template <class Memory>
bool Hart<Memory>::take_trap(uint32_t cause, uint32_t tval, uint32_t epc) {
  const uint32_t target = mtvec_ & ~3u;
  if (mtvec_ == 0 || !code_->contains(target)) return false;
  mepc_ = epc;
  mcause_ = cause;
  mtval_ = tval;
  const uint32_t mpie = (mstatus_ & mstatus::kMie) ? mstatus::kMpie : 0u;
  mstatus_ = (mstatus_ & ~(mstatus::kMie | mstatus::kMpie)) | mpie;
  return true;
}

// Guest CSR instruction semantics: which accesses happen depends on rd/rs1 being x0.
template <class Memory>
bool Hart<Memory>::csr_access(const Decoded& d, uint32_t& cause) {
  const uint16_t number = static_cast<uint16_t>(d.imm);
  const bool is_imm = d.op == Op::kCsrrwi || d.op == Op::kCsrrsi || d.op == Op::kCsrrci;
  const uint32_t operand = is_imm ? d.rs1 : x_[d.rs1];
  const bool is_write_op = d.op == Op::kCsrrw || d.op == Op::kCsrrwi;
  const bool reads = !is_write_op || d.rd != 0;
  const bool writes = is_write_op || d.rs1 != 0;
  cause = cause::kIllegalInstruction;
  if (number <= csr::kFcsr && !fs_enabled()) return false;
  uint32_t old = 0;
  if (!csr_name(number) || (reads && !read_csr(number, old))) return false;
  if (writes) {
    uint32_t value = operand;
    if (d.op == Op::kCsrrs || d.op == Op::kCsrrsi) value = old | operand;
    if (d.op == Op::kCsrrc || d.op == Op::kCsrrci) value = old & ~operand;
    if (!write_csr(number, value)) return false;
    if (number <= csr::kFcsr) mstatus_ |= mstatus::kFsDirty;
    // The privileged spec: a counter write takes effect after the writing instruction, whose
    // own increment is lost, so the next instruction reads the written value (not value + 1).
    if (number == csr::kMinstret || number == csr::kMinstreth) --instret_offset_;
    if (number == csr::kMcycle || number == csr::kMcycleh) --cycle_offset_;
  }
  x_[d.rd] = old;
  return true;
}

template <class Memory>
typename Hart<Memory>::Outcome Hart<Memory>::after_store(uint32_t addr, RunResult& stop) {
  if (code_->contains(addr)) {
    uint32_t word = 0;
    mem_->template load<4>(addr & ~3u, word);
    code_->update(addr & ~3u, word);
  }
  if ((addr & ~3u) == tohost_) {
    uint32_t value = 0;
    mem_->template load<4>(tohost_, value);
    if (value & 1u) {  // HTIF exit; other values (syscalls) are not supported and ignored
      stop.reason = StopReason::kToHost;
      stop.exit_code = value >> 1;
      return Outcome::kStop;
    }
  }
  return Outcome::kOk;
}

// A policy with load_words (flat_memory.h) reads a STRaTA op's operand block in one go: one
// bounds check, one copy and one access record instead of one per word (a box is 6 words, a
// triangle or a pushed ray more), which was a fifth of the fast-forward's host time.
template <class Memory, class = void>
struct HasLoadWords : std::false_type {};
template <class Memory>
struct HasLoadWords<Memory, std::void_t<decltype(std::declval<Memory&>().load_words(uint32_t{}, nullptr, 0u))>>
    : std::true_type {};

template <class Memory>
bool Hart<Memory>::load_words(uint32_t addr, uint32_t* out, unsigned n) {
  if constexpr (HasLoadWords<Memory>::value) {
    return mem_->load_words(addr, out, n);
  } else {
    (void)addr, (void)out, (void)n;
    return false;
  }
}

template <class Memory>
typename Hart<Memory>::Outcome Hart<Memory>::exec_strata(const Decoded& d, uint32_t pc, uint32_t& cause,
                                                         uint32_t& tval, RunResult& stop) {
  const OpInfo& info = op_info(d.op);
  if (touches_fp_state(d.op)) {
    if (!fs_enabled()) {
      cause = cause::kIllegalInstruction;
      tval = code_->word_at(pc);
      return Outcome::kException;
    }
    mstatus_ |= mstatus::kFsDirty;
  }
  if (!hook_) {
    stop.reason = StopReason::kHookError;
    stop.detail = "no STRaTA hook installed";
    return Outcome::kStop;
  }
  auto source = [&](Role r, uint8_t field) -> uint32_t {
    return r == Role::kIntSrc ? x_[field] : r == Role::kFpSrc ? f_[field] : 0u;
  };
  uint32_t in[kMaxStrataMemWords];
  uint32_t out[kMaxStrataMemWords];
  HookCall call{d.op, hart_id_, source(info.role[1], d.rs1), source(info.role[2], d.rs2), in, out, run_retired_};
  const uint32_t addr = x_[d.rs1];
  if (const unsigned n = strata_mem_in_words(d.op)) {
    cause = cause::kLoadMisaligned;
    tval = addr;
    if (addr & 3u) return Outcome::kException;
    cause = cause::kLoadAccessFault;
    if (!load_words(addr, in, n)) {
      for (unsigned i = 0; i < n; ++i) {
        tval = addr + 4 * i;
        if (!mem_->template load<4>(tval, in[i])) return Outcome::kException;
      }
    }
  }
  const HookResult r = hook_->execute(call);
  switch (r.status) {
    case HookStatus::kIllegal:
      cause = cause::kIllegalInstruction;
      tval = code_->word_at(pc);
      trap_detail_ = r.message;
      return Outcome::kException;
    case HookStatus::kFatal:
      stop.reason = StopReason::kHookError;
      stop.detail = r.message;
      return Outcome::kStop;
    case HookStatus::kDefer:  // nothing happened: the run stops with pc on this op (goto stop)
      stop.reason = StopReason::kDeferred;
      return Outcome::kStop;
    case HookStatus::kStore: {
      const unsigned n = strata_mem_out_words(d.op);
      cause = cause::kStoreMisaligned;
      tval = addr;
      if (addr & 3u) return Outcome::kException;
      cause = cause::kStoreAccessFault;
      for (unsigned i = 0; i < n; ++i) {
        tval = addr + 4 * i;
        if (!mem_->template store<4>(tval, out[i])) return Outcome::kException;
        if (after_store(tval, stop) == Outcome::kStop) return Outcome::kStop;
      }
      break;
    }
    case HookStatus::kOk: break;
  }
  const uint8_t fields[3] = {d.rd, d.rs1, d.rs2};
  for (unsigned i = 0; i < 3; ++i) {
    if (info.role[i] == Role::kIntDst) x_[fields[i]] = r.dest[i];
    if (info.role[i] == Role::kFpDst) f_[fields[i]] = r.dest[i];
  }
  if (r.yield) {
    stop.reason = StopReason::kYield;
    return Outcome::kStop;
  }
  return Outcome::kOk;
}

template <class Memory>
RunResult Hart<Memory>::run(uint64_t max_instructions) {
  return trace_ ? run_loop<true>(max_instructions) : run_loop<false>(max_instructions);
}

template <class Memory>
template <bool kTrace>
RunResult Hart<Memory>::run_loop(uint64_t max_instructions) {
  CodeImage& code = *code_;
  const Decoded* const decoded = code.entries();
  const uint32_t code_base = code.base();
  const uint32_t code_bytes = code.size_bytes();
  uint32_t* const x = x_.data();
  uint32_t* const f = f_.data();
  uint32_t pc = pc_;
  uint64_t n = 0, retired = 0;
  RunResult result;

// Raise an exception for the current instruction.
#define STRATA_RAISE(c, t) \
  do {                     \
    cause = (c);           \
    tval = (t);            \
    goto exception;        \
  } while (0)
#define STRATA_ILLEGAL() STRATA_RAISE(cause::kIllegalInstruction, code.word_at(pc))
#define STRATA_REQUIRE_FP()                          \
  do {                                               \
    if (!(mstatus_ & mstatus::kFs)) STRATA_ILLEGAL(); \
    mstatus_ |= mstatus::kFsDirty;                   \
  } while (0)
#define STRATA_ROUNDING(var)              \
  unsigned var = d.rm;                    \
  if (var == fp::kDyn) {                  \
    var = frm_;                           \
    if (var > fp::kRmm) STRATA_ILLEGAL(); \
  }
#define STRATA_LOAD(bytes, convert)                                                          \
  {                                                                                          \
    const uint32_t a = x[d.rs1] + static_cast<uint32_t>(d.imm);                              \
    if (a & (bytes - 1u)) STRATA_RAISE(cause::kLoadMisaligned, a);                           \
    uint32_t v;                                                                              \
    if (!mem_->template load<bytes>(a, v)) STRATA_RAISE(cause::kLoadAccessFault, a);         \
    x[d.rd] = convert;                                                                       \
    break;                                                                                   \
  }
#define STRATA_STORE(bytes, value)                                                           \
  {                                                                                          \
    const uint32_t a = x[d.rs1] + static_cast<uint32_t>(d.imm);                              \
    if (a & (bytes - 1u)) STRATA_RAISE(cause::kStoreMisaligned, a);                          \
    if (!mem_->template store<bytes>(a, value)) STRATA_RAISE(cause::kStoreAccessFault, a);   \
    if ((a - code_base < code_bytes || (a & ~3u) == tohost_) &&                              \
        after_store(a, result) == Outcome::kStop)                                            \
      goto stop_retired;                                                                     \
    break;                                                                                   \
  }
#define STRATA_BRANCH(condition)                                     \
  if (condition) {                                                   \
    next = pc + static_cast<uint32_t>(d.imm);                        \
    if (next & 3u) STRATA_RAISE(cause::kInstructionMisaligned, next); \
  }                                                                  \
  break;
#define STRATA_FP(expr)     \
  {                         \
    STRATA_REQUIRE_FP();    \
    expr;                   \
    break;                  \
  }
#define STRATA_FP_RM(expr)  \
  {                         \
    STRATA_REQUIRE_FP();    \
    STRATA_ROUNDING(rm);    \
    expr;                   \
    break;                  \
  }

  while (n < max_instructions) {
    ++n;
    uint32_t cause = 0, tval = 0;
    if (pc - code_base >= code_bytes) {
      cause = cause::kInstructionAccessFault;
      tval = pc;
      goto exception;
    }
    {
      const Decoded& d = decoded[(pc - code_base) >> 2];
      const Op op = d.op;
      const uint8_t rf = d.rf;
      uint32_t next = pc + 4;
      switch (op) {
        case Op::kIllegal: STRATA_ILLEGAL();
        case Op::kLui: x[d.rd] = static_cast<uint32_t>(d.imm); break;
        case Op::kAuipc: x[d.rd] = pc + static_cast<uint32_t>(d.imm); break;
        case Op::kJal:
          next = pc + static_cast<uint32_t>(d.imm);
          if (next & 3u) STRATA_RAISE(cause::kInstructionMisaligned, next);
          x[d.rd] = pc + 4;
          break;
        case Op::kJalr:
          next = (x[d.rs1] + static_cast<uint32_t>(d.imm)) & ~1u;
          if (next & 3u) STRATA_RAISE(cause::kInstructionMisaligned, next);
          x[d.rd] = pc + 4;
          break;
        case Op::kBeq: STRATA_BRANCH(x[d.rs1] == x[d.rs2])
        case Op::kBne: STRATA_BRANCH(x[d.rs1] != x[d.rs2])
        case Op::kBlt: STRATA_BRANCH(static_cast<int32_t>(x[d.rs1]) < static_cast<int32_t>(x[d.rs2]))
        case Op::kBge: STRATA_BRANCH(static_cast<int32_t>(x[d.rs1]) >= static_cast<int32_t>(x[d.rs2]))
        case Op::kBltu: STRATA_BRANCH(x[d.rs1] < x[d.rs2])
        case Op::kBgeu: STRATA_BRANCH(x[d.rs1] >= x[d.rs2])
        case Op::kLb: STRATA_LOAD(1, static_cast<uint32_t>(static_cast<int32_t>(static_cast<int8_t>(v))))
        case Op::kLh: STRATA_LOAD(2, static_cast<uint32_t>(static_cast<int32_t>(static_cast<int16_t>(v))))
        case Op::kLw: STRATA_LOAD(4, v)
        case Op::kLbu: STRATA_LOAD(1, v)
        case Op::kLhu: STRATA_LOAD(2, v)
        case Op::kSb: STRATA_STORE(1, x[d.rs2])
        case Op::kSh: STRATA_STORE(2, x[d.rs2])
        case Op::kSw: STRATA_STORE(4, x[d.rs2])
        case Op::kAddi: x[d.rd] = x[d.rs1] + static_cast<uint32_t>(d.imm); break;
        case Op::kSlti: x[d.rd] = static_cast<int32_t>(x[d.rs1]) < d.imm; break;
        case Op::kSltiu: x[d.rd] = x[d.rs1] < static_cast<uint32_t>(d.imm); break;
        case Op::kXori: x[d.rd] = x[d.rs1] ^ static_cast<uint32_t>(d.imm); break;
        case Op::kOri: x[d.rd] = x[d.rs1] | static_cast<uint32_t>(d.imm); break;
        case Op::kAndi: x[d.rd] = x[d.rs1] & static_cast<uint32_t>(d.imm); break;
        case Op::kSlli: x[d.rd] = x[d.rs1] << d.imm; break;
        case Op::kSrli: x[d.rd] = x[d.rs1] >> d.imm; break;
        case Op::kSrai: x[d.rd] = static_cast<uint32_t>(static_cast<int32_t>(x[d.rs1]) >> d.imm); break;
        case Op::kAdd: x[d.rd] = x[d.rs1] + x[d.rs2]; break;
        case Op::kSub: x[d.rd] = x[d.rs1] - x[d.rs2]; break;
        case Op::kSll: x[d.rd] = x[d.rs1] << (x[d.rs2] & 31u); break;
        case Op::kSlt: x[d.rd] = static_cast<int32_t>(x[d.rs1]) < static_cast<int32_t>(x[d.rs2]); break;
        case Op::kSltu: x[d.rd] = x[d.rs1] < x[d.rs2]; break;
        case Op::kXor: x[d.rd] = x[d.rs1] ^ x[d.rs2]; break;
        case Op::kSrl: x[d.rd] = x[d.rs1] >> (x[d.rs2] & 31u); break;
        case Op::kSra:
          x[d.rd] = static_cast<uint32_t>(static_cast<int32_t>(x[d.rs1]) >> (x[d.rs2] & 31u));
          break;
        case Op::kOr: x[d.rd] = x[d.rs1] | x[d.rs2]; break;
        case Op::kAnd: x[d.rd] = x[d.rs1] & x[d.rs2]; break;
        case Op::kFence:
        case Op::kWfi: break;  // one hart, no interrupts: both complete at once
        case Op::kFenceI: break;  // stores re-decode the code image immediately
        case Op::kEcall: STRATA_RAISE(cause::kEcallM, 0);
        case Op::kEbreak: STRATA_RAISE(cause::kBreakpoint, pc);
        case Op::kMret:
          next = mepc_;
          mstatus_ = (mstatus_ & ~mstatus::kMie) | ((mstatus_ & mstatus::kMpie) ? mstatus::kMie : 0u) |
                     mstatus::kMpie;
          break;
        case Op::kCsrrw:
        case Op::kCsrrs:
        case Op::kCsrrc:
        case Op::kCsrrwi:
        case Op::kCsrrsi:
        case Op::kCsrrci:
          if (!csr_access(d, cause)) STRATA_ILLEGAL();
          break;
        case Op::kMul: x[d.rd] = x[d.rs1] * x[d.rs2]; break;
        case Op::kMulh:
          x[d.rd] = static_cast<uint32_t>(
              static_cast<uint64_t>(int64_t{static_cast<int32_t>(x[d.rs1])} * static_cast<int32_t>(x[d.rs2])) >> 32);
          break;
        case Op::kMulhsu:
          x[d.rd] = static_cast<uint32_t>(
              static_cast<uint64_t>(int64_t{static_cast<int32_t>(x[d.rs1])} * int64_t{x[d.rs2]}) >> 32);
          break;
        case Op::kMulhu: x[d.rd] = static_cast<uint32_t>((uint64_t{x[d.rs1]} * x[d.rs2]) >> 32); break;
        case Op::kDiv: {
          const int32_t a = static_cast<int32_t>(x[d.rs1]), b = static_cast<int32_t>(x[d.rs2]);
          x[d.rd] = b == 0 ? ~0u : (a == INT32_MIN && b == -1) ? x[d.rs1] : static_cast<uint32_t>(a / b);
          break;
        }
        case Op::kDivu: x[d.rd] = x[d.rs2] == 0 ? ~0u : x[d.rs1] / x[d.rs2]; break;
        case Op::kRem: {
          const int32_t a = static_cast<int32_t>(x[d.rs1]), b = static_cast<int32_t>(x[d.rs2]);
          x[d.rd] = b == 0 ? x[d.rs1] : (a == INT32_MIN && b == -1) ? 0u : static_cast<uint32_t>(a % b);
          break;
        }
        case Op::kRemu: x[d.rd] = x[d.rs2] == 0 ? x[d.rs1] : x[d.rs1] % x[d.rs2]; break;
        case Op::kFlw: {
          STRATA_REQUIRE_FP();
          const uint32_t a = x[d.rs1] + static_cast<uint32_t>(d.imm);
          if (a & 3u) STRATA_RAISE(cause::kLoadMisaligned, a);
          if (!mem_->template load<4>(a, f[d.rd])) STRATA_RAISE(cause::kLoadAccessFault, a);
          break;
        }
        case Op::kFsw: {
          STRATA_REQUIRE_FP();
          STRATA_STORE(4, f[d.rs2])
        }
        case Op::kFmadd: STRATA_FP_RM(f[d.rd] = fp::fma(f[d.rs1], f[d.rs2], f[d.rs3], rm, fflags_))
        case Op::kFmsub: STRATA_FP_RM(f[d.rd] = fp::fma(f[d.rs1], f[d.rs2], f[d.rs3] ^ fp::kSign, rm, fflags_))
        case Op::kFnmsub: STRATA_FP_RM(f[d.rd] = fp::fma(f[d.rs1] ^ fp::kSign, f[d.rs2], f[d.rs3], rm, fflags_))
        case Op::kFnmadd:
          STRATA_FP_RM(f[d.rd] = fp::fma(f[d.rs1] ^ fp::kSign, f[d.rs2], f[d.rs3] ^ fp::kSign, rm, fflags_))
        case Op::kFadd: STRATA_FP_RM(f[d.rd] = fp::add(f[d.rs1], f[d.rs2], rm, fflags_))
        case Op::kFsub: STRATA_FP_RM(f[d.rd] = fp::sub(f[d.rs1], f[d.rs2], rm, fflags_))
        case Op::kFmul: STRATA_FP_RM(f[d.rd] = fp::mul(f[d.rs1], f[d.rs2], rm, fflags_))
        case Op::kFdiv: STRATA_FP_RM(f[d.rd] = fp::div(f[d.rs1], f[d.rs2], rm, fflags_))
        case Op::kFsqrt: STRATA_FP_RM(f[d.rd] = fp::sqrt(f[d.rs1], rm, fflags_))
        case Op::kFsgnj: STRATA_FP(f[d.rd] = fp::sgnj(f[d.rs1], f[d.rs2]))
        case Op::kFsgnjn: STRATA_FP(f[d.rd] = fp::sgnjn(f[d.rs1], f[d.rs2]))
        case Op::kFsgnjx: STRATA_FP(f[d.rd] = fp::sgnjx(f[d.rs1], f[d.rs2]))
        case Op::kFmin: STRATA_FP(f[d.rd] = fp::min(f[d.rs1], f[d.rs2], fflags_))
        case Op::kFmax: STRATA_FP(f[d.rd] = fp::max(f[d.rs1], f[d.rs2], fflags_))
        case Op::kFcvtWS: STRATA_FP_RM(x[d.rd] = fp::to_int32(f[d.rs1], rm, fflags_))
        case Op::kFcvtWuS: STRATA_FP_RM(x[d.rd] = fp::to_uint32(f[d.rs1], rm, fflags_))
        case Op::kFmvXW: STRATA_FP(x[d.rd] = f[d.rs1])
        case Op::kFeq: STRATA_FP(x[d.rd] = fp::eq(f[d.rs1], f[d.rs2], fflags_))
        case Op::kFlt: STRATA_FP(x[d.rd] = fp::lt(f[d.rs1], f[d.rs2], fflags_))
        case Op::kFle: STRATA_FP(x[d.rd] = fp::le(f[d.rs1], f[d.rs2], fflags_))
        case Op::kFclass: STRATA_FP(x[d.rd] = fp::classify(f[d.rs1]))
        case Op::kFcvtSW: STRATA_FP_RM(f[d.rd] = fp::from_int32(x[d.rs1], rm, fflags_))
        case Op::kFcvtSWu: STRATA_FP_RM(f[d.rd] = fp::from_uint32(x[d.rs1], rm, fflags_))
        case Op::kFmvWX: STRATA_FP(f[d.rd] = x[d.rs1])
        case Op::kStHalt: result.reason = StopReason::kHalt; goto stop_retired;
        case Op::kCount: STRATA_ILLEGAL();
        default:  // the rest of the STRaTA extension
          run_retired_ = retired;
          switch (exec_strata(d, pc, cause, tval, result)) {
            case Outcome::kOk: break;
            case Outcome::kException: goto exception;
            case Outcome::kStop:
              if (result.reason == StopReason::kToHost || result.reason == StopReason::kYield) goto stop_retired;
              goto stop;
          }
          break;
      }
      // Retire.
      ++retired;
      ++op_counts_[static_cast<unsigned>(op)];
      ++rf_counts_[rf];
      x[0] = 0;
      if constexpr (kTrace) trace_retired(trace_, hart_id_, pc, code.word_at(pc), d, x, f);
      pc = next;
      continue;

    stop_retired:
      ++retired;
      ++op_counts_[static_cast<unsigned>(op)];
      ++rf_counts_[rf];
      x[0] = 0;
      if constexpr (kTrace) trace_retired(trace_, hart_id_, pc, code.word_at(pc), d, x, f);
      if (result.reason == StopReason::kYield) pc = next;  // resume after it
      goto stop;
    }

  exception:
    if (take_trap(cause, tval, pc)) {
      if constexpr (kTrace) trace_trap(trace_, hart_id_, pc, cause, tval, true);
      trap_detail_ = nullptr;
      pc = mtvec_ & ~3u;
      continue;
    }
    if constexpr (kTrace) trace_trap(trace_, hart_id_, pc, cause, tval, false);
    result.reason = StopReason::kTrap;
    result.cause = cause;
    result.tval = tval;
    result.detail = trap_detail_;
    trap_detail_ = nullptr;

  stop:
    result.pc = pc;
    result.insn = code.contains(pc) ? code.word_at(pc) : 0;
    result.executed = retired;
    pc_ = pc;
    return result;
  }

#undef STRATA_RAISE
#undef STRATA_ILLEGAL
#undef STRATA_REQUIRE_FP
#undef STRATA_ROUNDING
#undef STRATA_LOAD
#undef STRATA_STORE
#undef STRATA_BRANCH
#undef STRATA_FP
#undef STRATA_FP_RM

  result.reason = StopReason::kInstructionLimit;
  result.pc = pc;
  result.insn = code.contains(pc) ? code.word_at(pc) : 0;
  result.executed = retired;
  pc_ = pc;
  return result;
}

}  // namespace strata::iss
