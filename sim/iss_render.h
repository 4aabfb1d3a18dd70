// Runs a render kernel as RISC-V firmware on one functional ISS hart: the scene image,
// frame parameters, framebuffer and counters are placed in guest memory, the kernel loops
// over every pixel, and the results are read back. Used to prove the firmware computes
// exactly what the native twin computes, and to measure the ISS on real firmware.
#pragma once

#include <cstdint>
#include <string>

#include "model/iss/counters.h"
#include "sim/native_render.h"

namespace strata::sim {

struct IssRunStats {
  uint64_t instructions = 0;
  double seconds = 0;  // wall clock of the hart's run alone
  double mips() const { return seconds > 0 ? double(instructions) / seconds * 1e-6 : 0.0; }
  iss::Counters counters;  // instruction mix and register-file traffic
};

// The kernel ELF built by this tree, e.g. default_kernel_elf("baseline").
std::string default_kernel_elf(const std::string& kernel);

// Throws std::runtime_error naming the ELF and the fault if the firmware does not finish
// cleanly (trap, instruction limit, non-zero exit).
RenderResult render_on_iss(const scenes::SceneImage& image, const RenderSettings& settings,
                           const std::string& elf_path, uint64_t max_instructions,
                           IssRunStats* stats);

}  // namespace strata::sim
