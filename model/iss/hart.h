// One RV32IMF + Zicsr hart with the STRaTA extension, machine mode only, functional (no
// timing). It is a template on its memory policy (see flat_memory.h) so that loads and
// stores inline; the TLM thread-processor module instantiates it with its own policy.
// Hart<FlatMemory> is compiled once in the library; other policies include hart_impl.h.
//
// Hot path: no allocation and no virtual call per instruction. Instructions come from a
// shared, predecoded CodeImage; only STRaTA operations call out, through the StrataHook.
//
// Its two dozen data members are one job's: a hart's architectural state (integer and float
// registers, pc, the CSRs and their machine-mode fields) and its counters. They stay flat in one
// object on purpose: the dispatch loop reads them every instruction, and grouping them behind
// further objects would cost the hot path its locality for no gain in structure.
#pragma once

#include "model/iss/code_image.h"
#include "model/iss/counters.h"
#include "model/iss/csr.h"
#include "model/iss/flat_memory.h"
#include "model/iss/run_result.h"
#include "model/iss/strata_hook.h"

#include <array>
#include <cstdint>
#include <cstdio>

namespace strata::iss {

template <class Memory>
class Hart {
 public:
  Hart(CodeImage& code, Memory& memory, StrataHook* hook = nullptr, uint32_t hart_id = 0);

  // Registers, CSRs and counters to their reset values (mstatus.FS = Off, mtvec = 0).
  void reset(uint32_t pc);

  // Runs until a stop condition or until max_instructions have been attempted.
  RunResult run(uint64_t max_instructions);
  RunResult step() { return run(1); }

  uint32_t hart_id() const { return hart_id_; }
  uint32_t pc() const { return pc_; }
  void set_pc(uint32_t pc) { pc_ = pc; }
  uint32_t x(unsigned i) const { return x_[i & 31]; }
  void set_x(unsigned i, uint32_t value) {
    if (i & 31) x_[i & 31] = value;
  }
  uint32_t f(unsigned i) const { return f_[i & 31]; }
  void set_f(unsigned i, uint32_t bits) { f_[i & 31] = bits; }

  // Debugger access with architectural WARL masking; false for an unimplemented CSR (or,
  // for write_csr, a read-only one). Unlike guest access, FP CSRs ignore mstatus.FS.
  bool read_csr(uint16_t number, uint32_t& value) const;
  bool write_csr(uint16_t number, uint32_t value);

  // A store of (code << 1) | 1 to this word ends the run with StopReason::kToHost.
  void set_tohost(uint32_t address) { tohost_ = address & ~3u; }
  void clear_tohost() { tohost_ = kNoToHost; }
  void set_trace(std::FILE* out) { trace_ = out; }  // nullptr: off
  void set_hook(StrataHook* hook) { hook_ = hook; }
  // mcycle = instructions retired + stall cycles that a timing wrapper reports here.
  void add_stall_cycles(uint64_t cycles) { stall_cycles_ += cycles; }
  // Or: mcycle reads a timing wrapper's clock (the cycle the current instruction issues in),
  // which costs the wrapper nothing per instruction. nullptr: back to retired + stalls.
  void use_cycle_clock(const uint64_t* cycles) { cycle_clock_ = cycles; }

  uint64_t instructions_retired() const;
  uint64_t op_count(Op op) const { return op_counts_[static_cast<unsigned>(op)]; }
  Counters counters() const { return fold_counters(op_counts_, rf_counts_); }
  // The instruction at pc, for a timing wrapper to look at before it steps; null outside code.
  const Decoded* next_instruction() const { return code_->contains(pc_) ? &code_->at(pc_) : nullptr; }

 private:
  static constexpr uint32_t kNoToHost = 1;  // not word aligned, so it never matches a store
  enum class Outcome { kOk, kException, kStop };

  template <bool kTrace>
  RunResult run_loop(uint64_t max_instructions);
  bool take_trap(uint32_t cause, uint32_t tval, uint32_t epc);
  bool csr_access(const Decoded& d, uint32_t& cause);
  bool fs_enabled() const { return (mstatus_ & mstatus::kFs) != 0; }
  Outcome after_store(uint32_t addr, RunResult& stop);
  Outcome exec_strata(const Decoded& d, uint32_t pc, uint32_t& cause, uint32_t& tval, RunResult& stop);
  bool load_words(uint32_t addr, uint32_t* out, unsigned n);  // false: load word by word

  CodeImage* code_;
  Memory* mem_;
  StrataHook* hook_;
  uint32_t hart_id_;
  std::FILE* trace_ = nullptr;
  uint32_t tohost_ = kNoToHost;

  std::array<uint32_t, 32> x_{};
  std::array<uint32_t, 32> f_{};
  uint32_t pc_ = 0;
  uint64_t run_retired_ = 0;  // for HookCall::retired_in_run
  uint32_t fflags_ = 0, frm_ = 0;
  uint32_t mstatus_ = 0, mtvec_ = 0, mepc_ = 0, mcause_ = 0, mtval_ = 0, mscratch_ = 0, mie_ = 0;
  uint64_t instret_offset_ = 0, cycle_offset_ = 0, stall_cycles_ = 0;
  const uint64_t* cycle_clock_ = nullptr;
  uint64_t cycles_now() const { return cycle_clock_ ? *cycle_clock_ : instructions_retired() + stall_cycles_; }
  const char* trap_detail_ = nullptr;  // why the last illegal-instruction trap came from the hook

  std::array<uint64_t, kOpCount> op_counts_{};
  std::array<uint64_t, kRfSlotCount> rf_counts_{};
};

extern template class Hart<FlatMemory>;

}  // namespace strata::iss
