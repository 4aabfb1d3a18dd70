// How the hart executes the STRaTA extension: it decodes the instruction, reads the source
// registers and any memory operand itself (through its memory policy, with the usual
// alignment and access-fault traps), and hands the rest to a hook that the embedder
// supplies. The chip model implements the hook with its TMs, pipelines and stream memory;
// FunctionalStrataHook is the standalone version. The hook is called only for these ops.
#pragma once

#include "model/iss/ops.h"

#include <cstdint>

namespace strata::iss {

struct HookCall {
  Op op;             // one of the kSt* operations except kStHalt, which the hart handles
  uint32_t hart_id;  // mhartid of the calling hart
  uint32_t rs1;      // source values (integer, or FP bits for strata.settmax); 0 if unused
  uint32_t rs2;
  const uint32_t* in;  // memory operand read from x[rs1]: strata_mem_in_words(op) words
  uint32_t* out;       // memory result for x[rs1]: strata_mem_out_words(op) words
  // Instructions the current Hart::run() call retired before this one: an embedder that runs
  // many instructions per call (sampled timing's fast-forward) dates the op with it.
  uint64_t retired_in_run = 0;
};

enum class HookStatus : uint8_t {
  kOk,       // write the destinations
  kStore,    // write the destinations, then store `out` to x[rs1]
  kIllegal,  // raise an illegal-instruction exception (message says why)
  kFatal,    // stop the run: the embedder cannot execute this (message says why)
  kDefer     // not now: stop the run before this op, with no effect (StopReason::kDeferred); the
             // next run() executes it again. The hook must not have changed any state.
};

struct HookResult {
  HookStatus status = HookStatus::kOk;
  uint32_t dest[3] = {0, 0, 0};  // values for the fields rd, rs1, rs2 that the op writes
  const char* message = nullptr;  // static string
  // kOk/kStore: end the current Hart::run() once this instruction retires (StopReason::kYield),
  // so an embedder running long batches can stop one at the right time.
  bool yield = false;
};

class StrataHook {
 public:
  virtual ~StrataHook() = default;
  virtual HookResult execute(const HookCall& call) = 0;
};

unsigned strata_mem_in_words(Op op);
unsigned strata_mem_out_words(Op op);
constexpr unsigned kMaxStrataMemWords = 16;
// The bytes one ray moves for a stream push or pop (48, or 64 for push64/pop64); 0 otherwise.
unsigned stream_ray_bytes(Op op);

}  // namespace strata::iss
