// The memory policy of a thread processor's hart (see model/iss/flat_memory.h for the
// contract). Data moves functionally through the chip's one sparse backing store; the policy
// also records what the current instruction touched, so the TM can then time that access
// (through its L1 socket, or the TP's local memory for the stack). Inline, no virtual calls.
#pragma once

#include <cstdint>
#include <vector>

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

// Functional warming (sampled timing): the L1 lines a fast-forward batch loaded from or stored
// to, in order, so the TM can then replay them as tag updates. A run of accesses to one line
// (the common case: a node's fields, a ray's words) is one entry. Entries are line << 1 | store.
// The vector keeps its capacity across batches: after the first few, nothing is allocated.
struct WarmLog {
  std::vector<uint64_t> entries;
  uint32_t line_shift = 6;
  uint64_t last = ~uint64_t{0};
  void clear() {
    entries.clear();
    last = ~uint64_t{0};
  }
  void note(uint32_t addr, uint32_t bytes, bool store) {
    const uint64_t first = addr >> line_shift, end = (uint64_t{addr} + bytes - 1) >> line_shift;
    for (uint64_t line = first; line <= end; ++line) {
      const uint64_t e = line << 1 | (store ? 1u : 0u);
      if (e != last) entries.push_back(e);
      last = e;
    }
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
    if (warm_ != nullptr) warm_->note(addr, N, false);
    return true;
  }
  template <unsigned N>
  bool store(uint32_t addr, uint32_t value) {
    if (addr < low_ || uint64_t{addr} + N > high_) return false;
    backing_->write(addr, &value, N);
    record_.note(addr, N, true);
    if (warm_ != nullptr) warm_->note(addr, N, true);
    return true;
  }

  AccessRecord& record() { return record_; }
  // While set (a fast-forward batch with functional warming), every access is also logged.
  void set_warm_log(WarmLog* log) { warm_ = log; }

 private:
  memory::SparseMemory* backing_;
  uint32_t low_;
  uint64_t high_;
  AccessRecord record_;
  WarmLog* warm_ = nullptr;
};

}  // namespace strata::chip
