#include "model/iss/program.h"

#include <algorithm>

namespace strata::iss {
namespace {

std::string hex(uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08x", v);
  return buf;
}

FlatMemory build_memory(const ElfImage& elf, uint32_t stack_bytes) {
  uint64_t low = UINT64_MAX, high = 0;
  for (const ElfSegment& s : elf.segments) {
    low = std::min<uint64_t>(low, s.vaddr);
    high = std::max<uint64_t>(high, uint64_t{s.vaddr} + s.memsz);
  }
  low &= ~uint64_t{0xFFF};
  high = ((high + 15) & ~uint64_t{15}) + ((uint64_t{stack_bytes} + 15) & ~uint64_t{15});
  if (high > (uint64_t{1} << 32))
    throw ElfError(elf.path + ": segments plus a " + std::to_string(stack_bytes) + "-byte stack exceed 4 GiB");
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
  std::vector<uint32_t> words(static_cast<size_t>((high - low) / 4));
  memory.read(static_cast<uint32_t>(low), words.data(), words.size() * 4);
  return CodeImage(static_cast<uint32_t>(low), std::move(words));
}

}  // namespace

Program make_program(ElfImage elf, uint32_t stack_bytes) {
  FlatMemory memory = build_memory(elf, stack_bytes);
  CodeImage code = build_code(elf, memory);
  if (!code.contains(elf.entry) || (elf.entry & 3u))
    throw ElfError(elf.path + ": entry point " + hex(elf.entry) + " is not an aligned address in an executable segment");
  const uint32_t entry = elf.entry;
  const uint32_t stack_top = static_cast<uint32_t>(memory.end() - 16) & ~15u;
  std::optional<uint32_t> tohost = elf.symbol("tohost");
  if (tohost && !memory.contains(*tohost, 4))
    throw ElfError(elf.path + ": symbol tohost " + hex(*tohost) + " lies outside the loaded segments");
  return Program{std::move(elf), std::move(memory), std::move(code), entry, stack_top, tohost};
}

Program load_program(const std::string& path, uint32_t stack_bytes) {
  return make_program(load_elf(path), stack_bytes);
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
