// The ELF loader and program builder on arbitrary bytes: ElfError or a program, and a program
// runs (briefly) without escaping the trap model.
#include "model/iss/elf_loader.h"
#include "model/iss/hart_impl.h"
#include "model/iss/program.h"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::vector<uint8_t> bytes(data, data + size);
  try {
    strata::iss::ElfImage elf = strata::iss::parse_elf("fuzz.elf", bytes);
    // Guest memory up to 4 GiB is legal (render --engine iss uses up to 3 GiB) and costs only the
    // pages touched, but ASan's shadow bookkeeping for a region of gigabytes takes seconds:
    // a span (lowest to highest segment address) past 256 MiB stops the harness at the parse,
    // so the time goes to new inputs.
    uint64_t low = UINT64_MAX, high = 0;
    for (const auto& s : elf.segments) {
      low = std::min<uint64_t>(low, s.vaddr);
      high = std::max<uint64_t>(high, uint64_t{s.vaddr} + s.memsz);
    }
    if (high > low && high - low > (uint64_t{256} << 20)) return 0;
    strata::iss::Program p = strata::iss::make_program(std::move(elf), 4096);
    strata::iss::Hart<strata::iss::FlatMemory> hart(p.code, p.memory);
    strata::iss::prepare_hart(hart, p);
    (void)hart.run(2000);
  } catch (const strata::iss::ElfError&) {
  }
  return 0;
}
