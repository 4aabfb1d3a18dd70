// The ELF32 loader and program set-up, on executables built byte by byte in the test.
#include "iss_test_support.h"

#include "model/iss/elf_loader.h"
#include "model/iss/program.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace strata::iss::testing {
namespace {

struct SegmentSpec {
  uint32_t vaddr;
  std::vector<uint32_t> words;
  uint32_t extra_bss = 0;
  uint32_t flags = 5;  // R X
};

struct ElfSpec {
  uint8_t elf_class = 1;
  uint8_t data = 1;
  uint16_t type = 2;
  uint16_t machine = 243;
  uint32_t flags = 0x2;  // float ABI single
  uint32_t entry = 0x10000;
  std::vector<SegmentSpec> segments;
  std::vector<std::pair<std::string, uint32_t>> symbols;
};

void put16(std::vector<uint8_t>& b, size_t at, uint16_t v) {
  b[at] = static_cast<uint8_t>(v);
  b[at + 1] = static_cast<uint8_t>(v >> 8);
}
void put32(std::vector<uint8_t>& b, size_t at, uint32_t v) {
  put16(b, at, static_cast<uint16_t>(v));
  put16(b, at + 2, static_cast<uint16_t>(v >> 16));
}

std::vector<uint8_t> build_elf(const ElfSpec& spec) {
  const size_t phoff = 52, phnum = spec.segments.size();
  size_t offset = phoff + 32 * phnum;
  std::vector<uint8_t> b(offset, 0);
  const uint8_t ident[8] = {0x7F, 'E', 'L', 'F', spec.elf_class, spec.data, 1, 0};
  std::copy(ident, ident + 8, b.begin());
  put16(b, 16, spec.type);
  put16(b, 18, spec.machine);
  put32(b, 20, 1);
  put32(b, 24, spec.entry);
  put32(b, 28, static_cast<uint32_t>(phoff));
  put32(b, 36, spec.flags);
  put16(b, 40, 52);
  put16(b, 42, 32);
  put16(b, 44, static_cast<uint16_t>(phnum));
  put16(b, 46, 40);
  for (size_t i = 0; i < phnum; ++i) {
    const SegmentSpec& s = spec.segments[i];
    const size_t ph = phoff + 32 * i;
    const uint32_t filesz = static_cast<uint32_t>(s.words.size() * 4);
    put32(b, ph, 1);
    put32(b, ph + 4, static_cast<uint32_t>(b.size()));
    put32(b, ph + 8, s.vaddr);
    put32(b, ph + 12, s.vaddr);
    put32(b, ph + 16, filesz);
    put32(b, ph + 20, filesz + s.extra_bss);
    put32(b, ph + 24, s.flags);
    for (uint32_t w : s.words) {
      b.resize(b.size() + 4);
      put32(b, b.size() - 4, w);
    }
  }
  // .strtab, .symtab and three section headers (null, strtab, symtab).
  std::vector<uint8_t> strtab(1, 0);
  std::vector<uint8_t> symtab(16, 0);
  for (const auto& [name, value] : spec.symbols) {
    const uint32_t name_offset = static_cast<uint32_t>(strtab.size());
    strtab.insert(strtab.end(), name.begin(), name.end());
    strtab.push_back(0);
    symtab.resize(symtab.size() + 16, 0);
    const size_t at = symtab.size() - 16;
    put32(symtab, at, name_offset);
    put32(symtab, at + 4, value);
    symtab[at + 12] = 0x10;  // STB_GLOBAL
    put16(symtab, at + 14, 1);
  }
  const uint32_t str_off = static_cast<uint32_t>(b.size());
  b.insert(b.end(), strtab.begin(), strtab.end());
  const uint32_t sym_off = static_cast<uint32_t>(b.size());
  b.insert(b.end(), symtab.begin(), symtab.end());
  const uint32_t shoff = static_cast<uint32_t>(b.size());
  b.resize(b.size() + 3 * 40, 0);
  put32(b, shoff + 40 + 4, 3);  // SHT_STRTAB
  put32(b, shoff + 40 + 16, str_off);
  put32(b, shoff + 40 + 20, static_cast<uint32_t>(strtab.size()));
  put32(b, shoff + 80 + 4, 2);  // SHT_SYMTAB
  put32(b, shoff + 80 + 16, sym_off);
  put32(b, shoff + 80 + 20, static_cast<uint32_t>(symtab.size()));
  put32(b, shoff + 80 + 24, 1);  // link: the string table
  put32(b, 32, shoff);
  put16(b, 48, 3);
  return b;
}

// Stores (7 << 1) | 1 to tohost at 0x11000.
ElfSpec tohost_program() {
  using namespace enc;
  ElfSpec spec;
  spec.segments.push_back({0x10000, {lui(10, 0x11000), addi(11, 0, (7 << 1) | 1), sw(11, 10, 0), jal(0, 0)}});
  spec.segments.push_back({0x11000, {0, 0}, 64, 6});
  spec.symbols = {{"_start", 0x10000}, {"tohost", 0x11000}};
  return spec;
}

std::string error_of(const std::vector<uint8_t>& file) {
  try {
    parse_elf("prog.elf", file);
  } catch (const ElfError& e) {
    return e.what();
  }
  return "";
}

TEST(IssElf, ParsesSegmentsEntryAndSymbols) {
  const ElfImage image = parse_elf("prog.elf", build_elf(tohost_program()));
  EXPECT_EQ(image.entry, 0x10000u);
  ASSERT_EQ(image.segments.size(), 2u);
  EXPECT_TRUE(image.segments[0].executable);
  EXPECT_FALSE(image.segments[0].writable);
  EXPECT_EQ(image.segments[0].bytes.size(), 16u);
  EXPECT_TRUE(image.segments[1].writable);
  EXPECT_EQ(image.segments[1].memsz, 8u + 64u);
  EXPECT_EQ(image.symbol("tohost"), 0x11000u);
  EXPECT_EQ(image.symbol("_start"), 0x10000u);
  EXPECT_FALSE(image.symbol("missing").has_value());
}

// The digest names what the program puts in memory: a changed instruction, a moved segment or a
// longer zero tail changes it; symbols do not.
TEST(IssElf, ImageDigestFollowsTheLoadedBytesOnly) {
  const ElfSpec base = tohost_program();
  const std::string digest = image_digest(parse_elf("prog.elf", build_elf(base)));
  EXPECT_EQ(digest.size(), 16u);
  EXPECT_EQ(image_digest(parse_elf("other-name.elf", build_elf(base))), digest);
  ElfSpec renamed = base;
  renamed.symbols = {{"_start", 0x10000}, {"tohost", 0x11000}, {"extra", 0x10004}};
  EXPECT_EQ(image_digest(parse_elf("prog.elf", build_elf(renamed))), digest);
  ElfSpec changed = base;
  changed.segments[0].words[1] = enc::addi(11, 0, (8 << 1) | 1);
  EXPECT_NE(image_digest(parse_elf("prog.elf", build_elf(changed))), digest);
  ElfSpec moved = base;
  moved.segments[1].vaddr = 0x12000;
  moved.symbols = {{"_start", 0x10000}, {"tohost", 0x12000}};
  EXPECT_NE(image_digest(parse_elf("prog.elf", build_elf(moved))), digest);
  ElfSpec longer = base;
  longer.segments[1].extra_bss += 4;
  EXPECT_NE(image_digest(parse_elf("prog.elf", build_elf(longer))), digest);
}

TEST(IssElf, RejectsUnsuitableFilesNamingThem) {
  const std::vector<uint8_t> good = build_elf(tohost_program());
  auto with = [&](auto change) {
    ElfSpec spec = tohost_program();
    change(spec);
    return error_of(build_elf(spec));
  };
  EXPECT_EQ(error_of(good), "");
  EXPECT_EQ(error_of({'h', 'e', 'l', 'l', 'o'}), "prog.elf: not an ELF file");
  EXPECT_NE(with([](ElfSpec& s) { s.elf_class = 2; }).find("prog.elf: 64-bit ELF"), std::string::npos);
  EXPECT_NE(with([](ElfSpec& s) { s.data = 2; }).find("little-endian"), std::string::npos);
  EXPECT_NE(with([](ElfSpec& s) { s.machine = 62; }).find("machine 62 is not RISC-V"), std::string::npos);
  EXPECT_NE(with([](ElfSpec& s) { s.type = 1; }).find("not an executable"), std::string::npos);
  EXPECT_NE(with([](ElfSpec& s) { s.flags |= 1; }).find("EF_RISCV_RVC"), std::string::npos);
  EXPECT_NE(with([](ElfSpec& s) { s.segments.clear(); }).find("no program headers"), std::string::npos);

  std::vector<uint8_t> truncated(good.begin(), good.begin() + 70);  // inside the program headers
  EXPECT_NE(error_of(truncated).find("prog.elf: truncated: program header table"), std::string::npos)
      << error_of(truncated);
  std::vector<uint8_t> header_only(good.begin(), good.begin() + 30);
  EXPECT_NE(error_of(header_only).find("truncated: ELF header"), std::string::npos);
  std::vector<uint8_t> bad_segment = good;
  put32(bad_segment, 52 + 4, 0x100000);  // segment data offset past the end
  EXPECT_NE(error_of(bad_segment).find("truncated: segment data"), std::string::npos);

  try {
    load_elf("/nonexistent/firmware.elf");
    FAIL() << "no exception";
  } catch (const ElfError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/firmware.elf: cannot open file");
  }
}

TEST(IssElf, ProgramMemoryCoversSegmentsAndStack) {
  const Program p = make_program(parse_elf("prog.elf", build_elf(tohost_program())), 4096);
  EXPECT_EQ(p.memory.base(), 0x10000u);
  EXPECT_EQ(p.memory.end(), 0x11050u + 4096u);  // segments rounded up to 16 bytes, then the stack
  EXPECT_EQ(p.stack_top % 16, 0u);
  EXPECT_GT(p.stack_top, 0x11000u + 72u);
  EXPECT_EQ(p.code.base(), 0x10000u);
  EXPECT_EQ(p.code.size_bytes(), 16u);
  EXPECT_EQ(p.tohost, 0x11000u);
  EXPECT_EQ(p.memory.read32(0x10000), enc::lui(10, 0x11000));

  ElfSpec bad_entry = tohost_program();
  bad_entry.entry = 0x11000;  // data, not code
  EXPECT_THROW(make_program(parse_elf("prog.elf", build_elf(bad_entry))), ElfError);
}

TEST(IssElf, RunsALoadedProgramToTohost) {
  const std::string path = ::testing::TempDir() + "/iss_elf_test.elf";
  {
    const std::vector<uint8_t> bytes = build_elf(tohost_program());
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  }
  Program p = load_program(path);
  Hart<FlatMemory> hart(p.code, p.memory);
  prepare_hart(hart, p);
  EXPECT_EQ(hart.x(2), p.stack_top);
  const RunResult r = hart.run(100);
  EXPECT_EQ(r.reason, StopReason::kToHost);
  EXPECT_EQ(r.exit_code, 7u);
  EXPECT_EQ(r.executed, 3u);
  std::remove(path.c_str());
}

// The riscv-tests linked by binutils 2.40 with their own link.ld: one PT_LOAD, p_flags 0 (the
// code and tohost in one segment). Its code is the segment holding the entry point.
TEST(IssElf, ASegmentWithoutFlagsHoldingTheEntryIsCode) {
  using namespace enc;
  ElfSpec spec;
  spec.segments.push_back({0x10000, {lui(10, 0x10000), addi(11, 0, (5 << 1) | 1), sw(11, 10, 0x40), jal(0, 0)}, 128, 0});
  spec.symbols = {{"_start", 0x10000}, {"tohost", 0x10040}};
  const ElfImage image = parse_elf("riscv-test.elf", build_elf(spec));
  ASSERT_EQ(image.segments.size(), 1u);
  EXPECT_TRUE(image.segments[0].executable);
  EXPECT_TRUE(image.segments[0].writable);
  EXPECT_TRUE(image.segments[0].flags_inferred);
  Program p = make_program(image, 4096);
  Hart<FlatMemory> hart(p.code, p.memory);
  prepare_hart(hart, p);
  const RunResult r = hart.run(100);
  EXPECT_EQ(r.reason, StopReason::kToHost);
  EXPECT_EQ(r.exit_code, 5u);
}

// Every code word is predecoded up front, so executable segments may span at most 64 MiB (a
// fuzz-found hang: an executable p_memsz of 1.75 GiB took minutes). One word past the limit
// is refused, naming the file and the span; two segments 1 MiB apart still run.
TEST(IssElf, ExecutableSpanAbove64MiBIsRefusedNamingTheFile) {
  ElfSpec spec = tohost_program();
  spec.segments.push_back({static_cast<uint32_t>(0x10000 + kMaxCodeBytes), {enc::jal(0, 0)}, 0, 5});
  const ElfImage image = parse_elf("huge.elf", build_elf(spec));
  try {
    make_program(image, 4096);
    FAIL() << "a 64 MiB + 4 byte code span was accepted";
  } catch (const ElfError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("huge.elf"), std::string::npos) << what;
    EXPECT_NE(what.find("executable segments span " + std::to_string(kMaxCodeBytes + 4) + " bytes"), std::string::npos)
        << what;
  }
  ElfSpec near = tohost_program();
  near.segments.push_back({0x10000 + (1u << 20), {enc::jal(0, 0)}, 0, 5});
  Program p = make_program(parse_elf("near.elf", build_elf(near)), 4096);
  Hart<FlatMemory> hart(p.code, p.memory);
  prepare_hart(hart, p);
  EXPECT_EQ(hart.run(100).reason, StopReason::kToHost);
}

TEST(IssElf, FlagsAreNeverInferredWhenSomeSegmentSaysExecutable) {
  ElfSpec spec = tohost_program();
  spec.segments[1].flags = 0;  // a data segment without flags stays data
  const ElfImage image = parse_elf("prog.elf", build_elf(spec));
  EXPECT_TRUE(image.segments[0].executable);
  EXPECT_FALSE(image.segments[1].executable);
  EXPECT_FALSE(image.segments[1].flags_inferred);
}

}  // namespace
}  // namespace strata::iss::testing
