// The state of one thread processor inside a ThreadMultiprocessor: its functional hart and
// memory policy, its issue timing, its pipeline input registers, and its fast-forward clock.
// Private to the TM's own source files (thread_multiprocessor.cpp, tm_fast_forward.cpp).
#pragma once

#include "model/tm/thread_multiprocessor.h"

namespace strata::tm {

struct ThreadMultiprocessor::Tp {
  Tp(iss::CodeImage& code, memory::SparseMemory& backing, const TmEnvironment& env,
     ThreadMultiprocessor* hook, uint32_t thread, uint32_t tp, uint32_t tm, const tm::OpTimingTable& table)
      : memory(backing, env.guest_low, env.guest_high),
        hart(code, memory, hook, thread),
        timing(table),
        pipe(iss::FunctionalStrataHook::Config{tp, tm, env.setup->tps_per_tm, env.setup->tms, 0}),
        thread_id(thread),
        stack_lo(env.stacks_base + thread * env.setup->tp_stack_bytes),
        stack_hi(stack_lo + env.setup->tp_stack_bytes) {}
  TpMemory memory;
  iss::Hart<TpMemory> hart;
  tm::TpTiming timing;
  iss::FunctionalStrataHook pipe;  // this TP's pipeline input registers and last test
  uint32_t thread_id;
  uint32_t stack_lo, stack_hi;
  uint32_t fetch_line = 0xFFFFFFFFu;
  double ff_clock = 0.0;       // fast-forward time, with the fraction of a cycle kept
  bool forwarded = false;      // fast-forwarded since it was last timed in detail
  // The next instruction's fetch was already made (to find when an op that must be sent in
  // time order issues; it may then wait for its operands); its answer is kept for the step.
  bool fetched = false;
  transport::Cycle fetch_ready = 0;
  // The same for the op's issue gate (TpTiming::begin_memory): set just before the step that
  // sends it, which then reuses the answer instead of asking again.
  bool begun = false;
  transport::Cycle begun_at = 0;
};

}  // namespace strata::tm
