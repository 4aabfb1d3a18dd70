// The ISS on random instruction words: whatever the words, a run ends in one of the documented
// stop reasons within its instruction limit, with memory accesses inside the trap model.
#include "model/iss/hart_impl.h"
#include "model/iss/program.h"

#include <cstdlib>
#include <cstring>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  constexpr uint32_t kBase = 0x1000, kMemory = 0x8000;
  std::vector<uint32_t> words(size / 4 + 1, 0);
  if (size) std::memcpy(words.data(), data, size);
  using namespace strata::iss;
  FlatMemory memory(kBase, kMemory);
  memory.write(kBase, words.data(), words.size() * 4);
  CodeImage code(kBase, words);
  Hart<FlatMemory> hart(code, memory);
  hart.set_pc(kBase);
  hart.set_x(2, kBase + kMemory - 16);
  hart.write_csr(csr::kMstatus, 1u << 13);  // FP on: reach the F extension too
  const RunResult r = hart.run(10000);
  switch (r.reason) {
    case StopReason::kInstructionLimit:
    case StopReason::kToHost:
    case StopReason::kHalt:
    case StopReason::kTrap:
    case StopReason::kHookError:
    case StopReason::kYield:
    case StopReason::kDeferred:
      break;
    default:
      std::abort();
  }
  if (r.executed > 10000) std::abort();
  return 0;
}
