// Reads a little-endian ELF32 RISC-V executable: its PT_LOAD segments, entry point and
// symbol table. Every error names the file.
//
// Which segments are code: those with PF_X. Real toolchain output does not always say so
// (the official riscv-tests, linked with their own link.ld by binutils 2.40, have one PT_LOAD
// with p_flags 0), so when no segment has PF_X, the segment holding the entry point is code
// (and is also writable data, as such a file's flags give no other answer).
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace strata::iss {

class ElfError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ElfSegment {
  uint32_t vaddr = 0;
  uint32_t memsz = 0;             // bytes in memory; the tail past the file bytes is zero
  std::vector<uint8_t> bytes;     // p_filesz bytes from the file
  bool executable = false;
  bool writable = false;
  bool flags_inferred = false;  // p_flags said nothing; executable because it holds the entry
};

struct ElfImage {
  std::string path;
  uint32_t entry = 0;
  std::vector<ElfSegment> segments;  // PT_LOAD with memsz > 0, in file order
  std::unordered_map<std::string, uint32_t> symbols;  // defined symbols; globals win over locals

  std::optional<uint32_t> symbol(const std::string& name) const;
};

ElfImage load_elf(const std::string& path);

// A 64-bit FNV-1a digest of what the ELF puts in memory (each segment's address, size and
// bytes, in file order), as 16 hex digits. It names the program a run executed: two frames are
// comparable only when their kernels' digests match, since a kernel's code layout alone moves
// frame timing by a few percent. Symbols and other sections do not count.
std::string image_digest(const ElfImage& elf);
ElfImage parse_elf(const std::string& path, const std::vector<uint8_t>& file);  // path for messages

}  // namespace strata::iss
