// The memory policy of a thread processor's hart (see model/iss/flat_memory.h for the
// contract). Data moves functionally through the chip's one sparse backing store; the policy
// also records what the current instruction touched, so the TM can then time that access
// (through its L1 socket, or the TP's local memory for the stack). Inline, no virtual calls.
#pragma once

#include <cstdint>

#include "model/memory/sparse_memory.h"

namespace strata::chip {

struct AccessRecord {
  uint32_t first = 0, last = 0;  // byte range touched by the current instruction [first, last)
  bool any = false, store = false;
  void clear() { any = false; store = false; }
  void note(uint32_t addr, uint32_t bytes, bool is_store) {
    if (!any) {
      first = addr;
      last = addr + bytes;
      any = true;
    } else {
      if (addr < first) first = addr;
      if (addr + bytes > last) last = addr + bytes;
    }
    store = store || is_store;
  }
};

class TpMemory {
 public:
  // Guest addresses [low, high) are valid; below `low` (the null page) and above `high` fault.
  TpMemory(memory::SparseMemory& backing, uint32_t low, uint64_t high)
      : backing_(&backing), low_(low), high_(high) {}

  template <unsigned N>
  bool load(uint32_t addr, uint32_t& value) {
    if (addr < low_ || uint64_t{addr} + N > high_) return false;
    value = 0;
    backing_->read(addr, &value, N);
    record_.note(addr, N, false);
    return true;
  }
  template <unsigned N>
  bool store(uint32_t addr, uint32_t value) {
    if (addr < low_ || uint64_t{addr} + N > high_) return false;
    backing_->write(addr, &value, N);
    record_.note(addr, N, true);
    return true;
  }

  AccessRecord& record() { return record_; }

 private:
  memory::SparseMemory* backing_;
  uint32_t low_;
  uint64_t high_;
  AccessRecord record_;
};

}  // namespace strata::chip
