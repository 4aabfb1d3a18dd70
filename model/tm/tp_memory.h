// The memory policy of a thread processor's hart (see model/iss/flat_memory.h for the
// contract). Data moves functionally through the chip's one sparse backing store; the policy
// also records what the current instruction touched, so the TM can then time that access
// (through its L1 socket, or the TP's local memory for the stack). Inline, no virtual calls.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "model/memory/sparse_memory.h"

namespace strata::tm {

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
// to, in order, so the TM can then replay them as tag updates. Entries are line << 1 | store.
// What would change nothing is left out as it happens, so the log stays short:
//   - a run of accesses to one line (a node's fields, a ray's words) is one entry;
//   - addresses no cache holds (the TPs' stacks, on-chip path state) are skipped;
//   - a load of a line the TM's direct-mapped L1 is known to hold: `known` mirrors, by set,
//     the lines this log's replays put there. Only the TM uses its L1, so the mirror is exact
//     until a timed access changes the L1, when the TM calls forget().
// The vectors keep their capacity: after the first batches, nothing is allocated.
struct WarmLog {
  std::vector<uint64_t> entries;
  std::vector<uint64_t> known;  // per L1 set: line + 1, 0 unknown (size: a power of two)
  uint32_t line_shift = 6;
  uint64_t skip_lo[2] = {0, 0}, skip_hi[2] = {0, 0};  // [lo, hi) byte ranges no cache holds
  uint64_t last = ~uint64_t{0};
  void clear() {
    entries.clear();
    last = ~uint64_t{0};
  }
  void forget() { std::fill(known.begin(), known.end(), 0); }
  // The same entries as one note(a, 4, store) per aligned word of [addr, addr + bytes): with
  // no skipped range overlapping the block, those are the block's lines in order.
  void note_words(uint32_t addr, uint32_t bytes, bool store) {
    const uint64_t end = uint64_t{addr} + bytes;
    for (int r = 0; r < 2; ++r)
      if (skip_lo[r] < end && addr < skip_hi[r]) {
        for (uint64_t a = addr; a < end; a += 4) note(static_cast<uint32_t>(a), 4, store);
        return;
      }
    note(addr, bytes, store);
  }
  void note(uint32_t addr, uint32_t bytes, bool store) {
    for (int r = 0; r < 2; ++r)
      if (addr >= skip_lo[r] && addr < skip_hi[r]) return;
    const uint64_t first = addr >> line_shift, end = (uint64_t{addr} + bytes - 1) >> line_shift;
    for (uint64_t line = first; line <= end; ++line) {
      const uint64_t e = line << 1 | (store ? 1u : 0u);
      if (e == last) continue;
      last = e;
      if (!store) {  // the L1 is write-around: only loads allocate in it
        uint64_t& k = known[line & (known.size() - 1)];
        if (k == line + 1) continue;
        k = line + 1;
      }
      entries.push_back(e);
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
  // n aligned words (flat_memory.h): all of them, or none and false.
  bool load_words(uint32_t addr, uint32_t* out, unsigned n) {
    const uint32_t bytes = 4 * n;
    if (n == 0 || addr < low_ || uint64_t{addr} + bytes > high_) return false;
    backing_->read(addr, out, bytes);
    record_.note(addr, bytes, false);
    if (warm_ != nullptr) warm_->note_words(addr, bytes, false);
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

}  // namespace strata::tm
