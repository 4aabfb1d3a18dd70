#include "model/iss/program.h"

#include <algorithm>

#include "model/iss/hex_text.h"

namespace strata::iss {
namespace {

constexpr uint64_t kDataAlignment = 1u << 20;

// [segments][stack][data], the stack top 16-byte aligned, the data 1 MiB aligned.
FlatMemory build_memory(const ElfImage& elf, uint32_t stack_bytes, uint32_t data_bytes,
                        uint32_t* stack_top, uint32_t* data_base) {
  uint64_t low = UINT64_MAX, high = 0;
  for (const ElfSegment& s : elf.segments) {
    low = std::min<uint64_t>(low, s.vaddr);
    high = std::max<uint64_t>(high, uint64_t{s.vaddr} + s.memsz);
  }
  low &= ~uint64_t{0xFFF};
  high = ((high + 15) & ~uint64_t{15}) + ((uint64_t{stack_bytes} + 15) & ~uint64_t{15});
  const uint64_t top = high - 16;
  if (data_bytes > 0) high = (high + kDataAlignment - 1) / kDataAlignment * kDataAlignment;
  const uint64_t data = high;
  high += data_bytes;
  if (high > (uint64_t{1} << 32))
    throw ElfError(elf.path + ": segments plus a " + std::to_string(stack_bytes) + "-byte stack and " +
                   std::to_string(data_bytes) + " data bytes exceed 4 GiB");
  *stack_top = static_cast<uint32_t>(top) & ~15u;
  *data_base = static_cast<uint32_t>(data);
  FlatMemory memory(static_cast<uint32_t>(low), static_cast<uint32_t>(high - low));
  for (const ElfSegment& s : elf.segments)
    if (!s.bytes.empty()) memory.write(s.vaddr, s.bytes.data(), s.bytes.size());
  return memory;
}

CodeImage build_code(const ElfImage& elf, const FlatMemory& memory) {
  uint64_t low = UINT64_MAX, high = 0;
  for (const ElfSegment& s : elf.segments) {
    if (!s.executable) continue;
    low = std::min<uint64_t>(low, s.vaddr & ~3u);
    high = std::max<uint64_t>(high, (uint64_t{s.vaddr} + s.memsz + 3) & ~uint64_t{3});
  }
  if (high == 0) throw ElfError(elf.path + ": no executable segment");
  // Every code word is predecoded up front, so a code span of gigabytes (a fuzz-found hang: an
  // executable p_memsz of 1.75 GiB) would take minutes; real firmware is a few KiB.
  if (high - low > kMaxCodeBytes)
    throw ElfError(elf.path + ": executable segments span " + std::to_string(high - low) + " bytes, more than " +
                   std::to_string(kMaxCodeBytes) + " (64 MiB)");
  std::vector<uint32_t> words(static_cast<size_t>((high - low) / 4));
  memory.read(static_cast<uint32_t>(low), words.data(), words.size() * 4);
  return CodeImage(static_cast<uint32_t>(low), std::move(words));
}

}  // namespace

Program make_program(ElfImage elf, uint32_t stack_bytes, uint32_t data_bytes) {
  uint32_t stack_top = 0, data_base = 0;
  FlatMemory memory = build_memory(elf, stack_bytes, data_bytes, &stack_top, &data_base);
  CodeImage code = build_code(elf, memory);
  if (!code.contains(elf.entry) || (elf.entry & 3u))
    throw ElfError(elf.path + ": entry point " + hex_text(elf.entry) + " is not an aligned address in an executable segment");
  const uint32_t entry = elf.entry;
  std::optional<uint32_t> tohost = elf.symbol("tohost");
  if (tohost && !memory.contains(*tohost, 4))
    throw ElfError(elf.path + ": symbol tohost " + hex_text(*tohost) + " lies outside the loaded segments");
  return Program{std::move(elf), std::move(memory), std::move(code), entry, stack_top, data_base, tohost};
}

Program load_program(const std::string& path, uint32_t stack_bytes, uint32_t data_bytes) {
  return make_program(load_elf(path), stack_bytes, data_bytes);
}

void prepare_hart(Hart<FlatMemory>& hart, const Program& program) {
  hart.reset(program.entry);
  hart.set_x(2, program.stack_top);
  if (program.tohost)
    hart.set_tohost(*program.tohost);
  else
    hart.clear_tohost();
}

}  // namespace strata::iss
