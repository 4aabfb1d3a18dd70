#include "model/memory/stream_sram.h"

#include <cstring>
#include <stdexcept>
#include <string>

namespace strata::memory {

StreamLayout make_stream_layout(const StreamMemoryConfig& config) {
  StreamLayout l;
  l.size_bytes = config.size_bytes;
  l.treelets = config.treelets;
  l.threads = config.threads;
  l.heads_offset = 16;
  l.counts_offset = l.heads_offset + 4ull * config.treelets;
  l.credits_offset = l.counts_offset + 4ull * config.treelets;
  l.entries_offset = l.credits_offset + ((uint64_t{config.threads} + 31) / 32) * 4;
  l.ray_bytes = config.ray_bytes;
  l.path_record_bytes = config.path_record_bytes;
  const uint64_t per_ray = l.entry_bytes() + uint64_t{config.path_record_bytes};
  if (l.entries_offset + per_ray > l.size_bytes)
    throw std::invalid_argument("stream.size_bytes: " + std::to_string(config.size_bytes) +
                                " bytes cannot hold the heads, counts and credit bits of " +
                                std::to_string(config.treelets) + " treelets and " +
                                std::to_string(config.threads) + " threads plus one ray" +
                                (config.path_record_bytes ? " and its path record" : ""));
  const uint64_t entries = (l.size_bytes - l.entries_offset) / per_ray;
  l.capacity = static_cast<uint32_t>(entries < StreamSram::kNil ? entries : StreamSram::kNil - 1);
  l.path_records_offset = l.entries_offset + uint64_t{l.capacity} * l.entry_bytes();
  return l;
}

StreamSram::StreamSram(const StreamLayout& layout) : layout_(layout), sram_(layout.size_bytes, 0) {
  write32(kFreeHeadOffset, kNil);
  for (uint32_t t = 0; t < layout_.treelets; ++t) write32(layout_.heads_offset + 4ull * t, kNil);
}

uint32_t StreamSram::read32(uint64_t offset) const {
  uint32_t v;
  std::memcpy(&v, &sram_[offset], 4);
  return v;
}

void StreamSram::write32(uint64_t offset, uint32_t value) { std::memcpy(&sram_[offset], &value, 4); }

bool StreamSram::holds_credit(uint32_t thread) const {
  return (read32(layout_.credits_offset + 4ull * (thread / 32)) >> (thread % 32)) & 1u;
}

void StreamSram::set_credit(uint32_t thread, bool on) {
  const uint64_t word = layout_.credits_offset + 4ull * (thread / 32);
  const uint32_t bit = 1u << (thread % 32);
  const uint32_t v = read32(word);
  const bool was = (v & bit) != 0;
  if (was == on) return;
  write32(word, on ? (v | bit) : (v & ~bit));
  write32(kCreditsOffset, on ? credits() + 1 : credits() - 1);
}

StreamSram::Status StreamSram::push(uint32_t thread, uint32_t treelet, const uint8_t* ray, uint32_t* taken) {
  if (taken) *taken = kNil;
  if (treelet >= layout_.treelets || thread >= layout_.threads) return Status::kBadRequest;
  if (holds_credit(thread)) {
    set_credit(thread, false);  // one-for-one replacement: its slot is reserved
  } else if (uint64_t{stored()} + credits() >= layout_.capacity) {
    return Status::kFull;  // every free slot is promised to a thread holding a popped ray
  }
  uint32_t entry = read32(kFreeHeadOffset);
  if (entry != kNil) {
    write32(kFreeHeadOffset, read32(entry_offset(entry) + layout_.ray_bytes));
  } else {
    entry = read32(kNextUnusedOffset);
    write32(kNextUnusedOffset, entry + 1);
  }
  const uint64_t at = entry_offset(entry);
  std::memcpy(&sram_[at], ray, layout_.ray_bytes);
  const uint64_t head = layout_.heads_offset + 4ull * treelet;
  write32(at + layout_.ray_bytes, read32(head));
  write32(head, entry);
  write32(layout_.counts_offset + 4ull * treelet, size(treelet) + 1);
  write32(kStoredOffset, stored() + 1);
  if (taken) *taken = entry;
  return Status::kOk;
}

StreamSram::Status StreamSram::pop(uint32_t thread, uint32_t treelet, uint8_t* ray, uint32_t* taken) {
  if (taken) *taken = kNil;
  if (treelet >= layout_.treelets || thread >= layout_.threads) return Status::kBadRequest;
  const uint64_t head = layout_.heads_offset + 4ull * treelet;
  const uint32_t entry = read32(head);
  if (entry == kNil) return Status::kEmpty;
  const uint64_t at = entry_offset(entry);
  std::memcpy(ray, &sram_[at], layout_.ray_bytes);
  write32(head, read32(at + layout_.ray_bytes));
  write32(at + layout_.ray_bytes, read32(kFreeHeadOffset));
  write32(kFreeHeadOffset, entry);
  write32(layout_.counts_offset + 4ull * treelet, size(treelet) - 1);
  write32(kStoredOffset, stored() - 1);
  set_credit(thread, true);  // replaces an unused credit from an earlier pop, if any
  if (taken) *taken = entry;
  return Status::kOk;
}

}  // namespace strata::memory
