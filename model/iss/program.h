// An ELF executable made ready to run: guest memory spanning its segments plus a stack
// above them, and the predecoded image of its executable segments.
#pragma once

#include "model/iss/code_image.h"
#include "model/iss/elf_loader.h"
#include "model/iss/flat_memory.h"
#include "model/iss/hart.h"

#include <cstdint>
#include <optional>
#include <string>

namespace strata::iss {

constexpr uint32_t kDefaultStackBytes = 256 * 1024;
// The largest span of executable segments: every code word is predecoded when the program is
// made, and real firmware is a few KiB.
constexpr uint64_t kMaxCodeBytes = uint64_t{64} << 20;

struct Program {
  ElfImage elf;
  FlatMemory memory;
  CodeImage code;
  uint32_t entry = 0;
  uint32_t stack_top = 0;  // 16-byte aligned top of the stack, above the segments
  uint32_t data_base = 0;  // start of the platform's data region above the stack (1 MiB aligned)
  std::optional<uint32_t> tohost;
};

// Throws ElfError (naming the file) for unreadable or unsuitable executables. `data_bytes`
// of zeroed memory follow the stack, for what the platform hands the program (scene, frame).
Program load_program(const std::string& path, uint32_t stack_bytes = kDefaultStackBytes,
                     uint32_t data_bytes = 0);
Program make_program(ElfImage elf, uint32_t stack_bytes = kDefaultStackBytes,
                     uint32_t data_bytes = 0);

// pc = entry, sp = stack top, and the tohost convention if the program has the symbol.
void prepare_hart(Hart<FlatMemory>& hart, const Program& program);

}  // namespace strata::iss
