// The ray stream memory's storage: one LIFO singly linked list of rays per treelet, held in
// a byte-addressed model of the SRAM itself. Everything the lists need is carved out of the
// same S bytes, so the capacity is what is left:
//
//   [free-list head 4 B][next-unused 4 B][stored 4 B][credits 4 B]
//   [head pointer 4 B x treelets][ray count 4 B x treelets]
//   [holds-a-ray bit x threads, rounded up to 4 B]
//   [entry 0: ray 48 or 64 B + link 4 B][entry 1] ... [entry capacity-1]
//   [path record 0] ... [path record capacity-1]   (only with path state on chip)
//
// Entries never used yet are taken from a bump pointer, recycled ones from the free list, so
// reset costs nothing per entry. The lists ARE the data: push copies the ray's bytes in, pop
// copies them out.
//
// Never losing a ray, never deadlocking: a thread that pops a ray holds a credit for one slot
// (its "holds-a-ray" bit). Its next push uses that slot and always succeeds, so one-for-one
// replacement cannot fail however full the memory is. Any other push (filling the memory,
// or a second ray from one pop) succeeds only while stored + credits < capacity, i.e. only
// into slots nobody holds; otherwise it returns kFull and stores nothing, and the thread keeps
// the ray and retries later (backpressure). A thread's next pop releases a credit it did not
// use (its ray ended without a successor). Invariant: stored + credits <= capacity.
#pragma once

#include "model/memory/config.h"
#include "tlm/memory_extension.h"

#include <cstdint>
#include <vector>

namespace strata::memory {

struct StreamLayout {
  uint32_t ray_bytes = 48;  // StreamMemoryConfig::ray_bytes
  uint32_t entry_bytes() const { return ray_bytes + 4; }  // ray + link word
  uint64_t size_bytes = 0;
  uint32_t treelets = 0;
  uint32_t threads = 0;
  uint64_t heads_offset = 0, counts_offset = 0, credits_offset = 0, entries_offset = 0;
  uint32_t capacity = 0;  // rays
  // On-chip path state: one record per ray slot after the entries (its data lives in the
  // chip's backing store; the region only takes its bytes here).
  uint32_t path_record_bytes = 0;
  uint64_t path_records_offset = 0;
  // Bytes not holding ray payload (registers, heads, counts, credit bits, links, slack) / S.
  double overhead_fraction() const {
    return 1.0 - static_cast<double>(uint64_t{capacity} * ray_bytes) / static_cast<double>(size_bytes);
  }
};

// Throws std::invalid_argument if the SRAM cannot hold its bookkeeping plus one ray.
StreamLayout make_stream_layout(const StreamMemoryConfig& config);

class StreamSram {
 public:
  using Status = transport::StreamStatus;
  static constexpr uint32_t kNil = 0xFFFFFFFFu;

  explicit StreamSram(const StreamLayout& layout);

  // thread: global thread id (< layout.threads); treelet < layout.treelets (else kBadRequest).
  // `entry` (may be null) gets the entry the ray was stored in or taken from (kNil if none).
  Status push(uint32_t thread, uint32_t treelet, const uint8_t* ray, uint32_t* entry = nullptr);
  Status pop(uint32_t thread, uint32_t treelet, uint8_t* ray, uint32_t* entry = nullptr);
  uint32_t size(uint32_t treelet) const { return read32(layout_.counts_offset + 4ull * treelet); }
  uint32_t capacity() const { return layout_.capacity; }
  uint32_t stored() const { return read32(kStoredOffset); }
  uint32_t credits() const { return read32(kCreditsOffset); }
  bool holds_credit(uint32_t thread) const;
  const StreamLayout& layout() const { return layout_; }

 private:
  static constexpr uint64_t kFreeHeadOffset = 0, kNextUnusedOffset = 4, kStoredOffset = 8, kCreditsOffset = 12;
  uint32_t read32(uint64_t offset) const;
  void write32(uint64_t offset, uint32_t value);
  uint64_t entry_offset(uint32_t entry) const { return layout_.entries_offset + uint64_t{entry} * layout_.entry_bytes(); }
  void set_credit(uint32_t thread, bool on);

  StreamLayout layout_;
  std::vector<uint8_t> sram_;
};

}  // namespace strata::memory
