#include "model/iss/elf_loader.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace strata::iss {
namespace {

constexpr uint16_t kEmRiscv = 243;
constexpr uint16_t kEtExec = 2;
constexpr uint32_t kPtLoad = 1;
constexpr uint32_t kPfX = 1, kPfW = 2;
constexpr uint32_t kShtSymtab = 2;
constexpr uint32_t kEfRiscvRvc = 1;
constexpr uint32_t kEhdrSize = 52, kPhdrSize = 32, kShdrSize = 40, kSymSize = 16;

class Reader {
 public:
  Reader(const std::string& path, const std::vector<uint8_t>& file) : path_(path), file_(file) {}

  [[noreturn]] void fail(const std::string& why) const { throw ElfError(path_ + ": " + why); }

  void need(uint64_t offset, uint64_t size, const char* what) const {
    if (offset + size > file_.size())
      fail(std::string("truncated: ") + what + " at offset " + std::to_string(offset) + " (+" +
           std::to_string(size) + " bytes) lies past the end of the " + std::to_string(file_.size()) +
           "-byte file");
  }
  uint8_t u8(uint64_t off) const { return file_[off]; }
  uint16_t u16(uint64_t off) const { return static_cast<uint16_t>(file_[off] | (file_[off + 1] << 8)); }
  uint32_t u32(uint64_t off) const { return uint32_t{u16(off)} | (uint32_t{u16(off + 2)} << 16); }
  const uint8_t* at(uint64_t off) const { return file_.data() + off; }

 private:
  const std::string& path_;
  const std::vector<uint8_t>& file_;
};

void read_symbols(const Reader& r, uint32_t shoff, uint16_t shentsize, uint16_t shnum, ElfImage& image) {
  if (shoff == 0 || shnum == 0) return;
  if (shentsize < kShdrSize) r.fail("section header entries are too small");
  r.need(shoff, uint64_t{shentsize} * shnum, "section header table");
  std::unordered_map<std::string, bool> is_global;
  for (uint16_t i = 0; i < shnum; ++i) {
    const uint64_t sh = shoff + uint64_t{i} * shentsize;
    if (r.u32(sh + 4) != kShtSymtab) continue;
    const uint32_t sym_off = r.u32(sh + 16), sym_size = r.u32(sh + 20), link = r.u32(sh + 24);
    if (link >= shnum) r.fail("symbol table links to a missing string table");
    const uint64_t str_sh = shoff + uint64_t{link} * shentsize;
    const uint32_t str_off = r.u32(str_sh + 16), str_size = r.u32(str_sh + 20);
    r.need(sym_off, sym_size, "symbol table");
    r.need(str_off, str_size, "string table");
    for (uint64_t s = sym_off; s + kSymSize <= uint64_t{sym_off} + sym_size; s += kSymSize) {
      const uint32_t name = r.u32(s), value = r.u32(s + 4);
      const uint8_t info = r.u8(s + 12);
      const uint16_t shndx = r.u16(s + 14);
      if (name == 0 || shndx == 0 || name >= str_size) continue;
      const char* begin = reinterpret_cast<const char*>(r.at(str_off + name));
      const size_t length = strnlen(begin, str_size - name);
      if (length == str_size - name) r.fail("unterminated symbol name");
      const std::string key(begin, length);
      const bool global = (info >> 4) != 0;  // STB_GLOBAL or STB_WEAK
      auto found = is_global.find(key);
      if (found == is_global.end() || (global && !found->second)) {
        image.symbols[key] = value;
        is_global[key] = global;
      }
    }
  }
}

}  // namespace

std::optional<uint32_t> ElfImage::symbol(const std::string& name) const {
  auto it = symbols.find(name);
  if (it == symbols.end()) return std::nullopt;
  return it->second;
}

ElfImage load_elf(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw ElfError(path + ": cannot open file: not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ElfError(path + ": cannot open file");
  std::vector<uint8_t> file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw ElfError(path + ": read error");
  return parse_elf(path, file);
}

ElfImage parse_elf(const std::string& path, const std::vector<uint8_t>& file) {
  const Reader r(path, file);
  if (file.size() < 16 || std::memcmp(file.data(), "\x7f" "ELF", 4) != 0) r.fail("not an ELF file");
  if (file[4] != 1)
    r.fail(file[4] == 2 ? "64-bit ELF (ELFCLASS64); the ISS runs RV32 executables only" : "unknown ELF class");
  if (file[5] != 1) r.fail("not little-endian (EI_DATA)");
  r.need(0, kEhdrSize, "ELF header");
  const uint16_t type = r.u16(16), machine = r.u16(18);
  if (machine != kEmRiscv) r.fail("machine " + std::to_string(machine) + " is not RISC-V (243)");
  if (type != kEtExec) r.fail("not an executable (e_type " + std::to_string(type) + ")");
  if (r.u32(36) & kEfRiscvRvc)
    r.fail("uses the C extension (EF_RISCV_RVC); the ISS implements RV32IMF without compressed instructions");

  ElfImage image;
  image.path = path;
  image.entry = r.u32(24);
  const uint32_t phoff = r.u32(28), shoff = r.u32(32);
  const uint16_t phentsize = r.u16(42), phnum = r.u16(44), shentsize = r.u16(46), shnum = r.u16(48);
  if (phnum == 0) r.fail("no program headers");
  if (phentsize < kPhdrSize) r.fail("program header entries are too small");
  r.need(phoff, uint64_t{phentsize} * phnum, "program header table");
  for (uint16_t i = 0; i < phnum; ++i) {
    const uint64_t ph = phoff + uint64_t{i} * phentsize;
    if (r.u32(ph) != kPtLoad) continue;
    const uint32_t offset = r.u32(ph + 4), vaddr = r.u32(ph + 8), filesz = r.u32(ph + 16), memsz = r.u32(ph + 20),
                   flags = r.u32(ph + 24);
    if (memsz == 0) continue;
    if (filesz > memsz) r.fail("segment " + std::to_string(i) + " has p_filesz > p_memsz");
    if (uint64_t{vaddr} + memsz > (uint64_t{1} << 32)) r.fail("segment " + std::to_string(i) + " wraps past 2^32");
    r.need(offset, filesz, "segment data");
    ElfSegment seg;
    seg.vaddr = vaddr;
    seg.memsz = memsz;
    seg.bytes.assign(r.at(offset), r.at(offset) + filesz);
    seg.executable = (flags & kPfX) != 0;
    seg.writable = (flags & kPfW) != 0;
    image.segments.push_back(std::move(seg));
  }
  if (image.segments.empty()) r.fail("no loadable (PT_LOAD) segments");
  const bool any_code = std::any_of(image.segments.begin(), image.segments.end(),
                                    [](const ElfSegment& s) { return s.executable; });
  if (!any_code)
    for (ElfSegment& s : image.segments)
      if (s.vaddr <= image.entry && image.entry - s.vaddr < s.memsz) {
        s.executable = s.writable = s.flags_inferred = true;
        break;
      }
  read_symbols(r, shoff, shentsize, shnum, image);
  return image;
}

std::string image_digest(const ElfImage& elf) {
  uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a 64 offset basis and prime
  const auto mix = [&h](uint8_t b) {
    h ^= b;
    h *= 0x100000001b3ull;
  };
  const auto mix_word = [&mix](uint32_t w) {
    for (int i = 0; i < 4; ++i) mix(static_cast<uint8_t>(w >> (8 * i)));
  };
  for (const ElfSegment& s : elf.segments) {
    mix_word(s.vaddr);
    mix_word(s.memsz);
    mix_word(static_cast<uint32_t>(s.bytes.size()));
    for (uint8_t b : s.bytes) mix(b);
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

}  // namespace strata::iss
