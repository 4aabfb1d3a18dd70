// The ELF loader and program builder on arbitrary bytes: ElfError or a program, and a program
// runs (briefly) without escaping the trap model.
#include "model/iss/elf_loader.h"
#include "model/iss/hart_impl.h"
#include "model/iss/program.h"

#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::vector<uint8_t> bytes(data, data + size);
  try {
    strata::iss::Program p = strata::iss::make_program(strata::iss::parse_elf("fuzz.elf", bytes), 4096);
    strata::iss::Hart<strata::iss::FlatMemory> hart(p.code, p.memory);
    strata::iss::prepare_hart(hart, p);
    (void)hart.run(2000);
  } catch (const strata::iss::ElfError&) {
  }
  return 0;
}
