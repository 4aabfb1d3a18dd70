// strata-iss: runs one RV32IMF firmware ELF on a single functional hart.
//   strata-iss program.elf [--max-instructions N] [--trace] [--stats]
// The exit status is the program's tohost code (capped at 255); a fault, a hook error or the
// instruction limit exits with 1 after printing the reason.
#include "model/iss/functional_strata_hook.h"
#include "model/iss/hart.h"
#include "model/iss/program.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  using namespace strata::iss;
  CLI::App app{"Functional RV32IMF + STRaTA instruction-set simulator (one hart)"};
  std::string path;
  uint64_t max_instructions = 10'000'000'000ull;
  uint32_t stack_bytes = kDefaultStackBytes;
  bool trace = false, stats = false;
  app.add_option("program", path, "RISC-V ELF32 executable")->required();
  app.add_option("--max-instructions", max_instructions, "stop after this many instructions");
  app.add_option("--stack-bytes", stack_bytes, "stack placed above the highest segment");
  app.add_flag("--trace", trace, "print pc, disassembly and register writes of every instruction");
  app.add_flag("--stats", stats, "print retired instructions by class and register-file accesses");
  CLI11_PARSE(app, argc, argv);

  try {
    Program program = load_program(path, stack_bytes);
    FunctionalStrataHook hook;
    Hart<FlatMemory> hart(program.code, program.memory, &hook);
    prepare_hart(hart, program);
    if (trace) hart.set_trace(stdout);
    if (!program.tohost) std::fprintf(stderr, "strata-iss: %s has no tohost symbol; it must halt\n", path.c_str());

    const auto start = std::chrono::steady_clock::now();
    const RunResult result = hart.run(max_instructions);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const uint64_t n = hart.instructions_retired();
    std::fprintf(stderr, "strata-iss: %llu instructions in %.3f s (%.1f MIPS)\n", static_cast<unsigned long long>(n),
                 seconds, seconds > 0 ? static_cast<double>(n) / seconds / 1e6 : 0.0);
    if (stats) std::fprintf(stderr, "%s", format_counters(hart.counters()).c_str());

    switch (result.reason) {
      case StopReason::kToHost:
        if (result.exit_code != 0) std::fprintf(stderr, "strata-iss: %s\n", describe(result).c_str());
        return result.exit_code > 255 ? 255 : static_cast<int>(result.exit_code);
      case StopReason::kHalt: return 0;
      default: std::fprintf(stderr, "strata-iss: %s: %s\n", path.c_str(), describe(result).c_str()); return 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "strata-iss: %s\n", e.what());
    return 1;
  }
}
