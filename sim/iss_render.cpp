#include "sim/iss_render.h"

#include <chrono>
#include <cstring>
#include <stdexcept>

#include "firmware/abi/boot_block.h"
#include "model/chip/guest_layout.h"
#include "model/iss/functional_strata_hook.h"
#include "model/iss/hart.h"
#include "model/iss/program.h"

namespace strata::sim {

std::string default_kernel_elf(const std::string& kernel) {
  return std::string(STRATA_FIRMWARE_KERNEL_DIR) + "/" + kernel + ".elf";
}

RenderResult render_on_iss(const scenes::SceneImage& image, const RenderSettings& settings,
                           const std::string& elf_path, uint64_t max_instructions,
                           IssRunStats* stats) {
  check_render_settings(settings);
  chip::FrameFootprint footprint;
  footprint.scene_image_bytes = image.size_bytes();
  footprint.treelet_bytes = image.header().treelet_bytes;
  footprint.pixels = settings.width * settings.height;
  footprint.threads = 1;
  // Path records for a streaming kernel, planned as on the chip: without them it starts no
  // path and waits for pixels forever.
  const iss::FunctionalStrataHook::Config hook_config;
  footprint.path_slots = chip::path_slots_for(hook_config.stream_capacity, footprint.pixels);
  // Per-sample slots: a compact streaming kernel then runs a pixel's samples together (the
  // other kernels leave them unused).
  footprint.sample_slots = chip::sample_slots_for(footprint.pixels, settings.samples_per_pixel);
  const uint64_t data_bytes = chip::frame_layout_bytes(footprint);
  if (data_bytes > 0xC0000000ull)
    throw std::runtime_error("iss render: scene image and frame do not fit the 32-bit guest address space");
  iss::Program program = iss::load_program(elf_path, iss::kDefaultStackBytes, uint32_t(data_bytes));
  const chip::GuestLayout g = chip::plan_frame_layout(program.data_base, footprint);
  const auto boot_addr = program.elf.symbol(kernels::kBootBlockSymbol);
  if (!boot_addr) throw std::runtime_error(elf_path + ": no '" + std::string(kernels::kBootBlockSymbol) + "' symbol: not a render kernel");

  const kernels::FrameParams frame = make_frame_params(image.header(), settings);
  program.memory.write(uint32_t(g.scene_image), image.bytes(), image.size_bytes());
  program.memory.write(uint32_t(g.frame), &frame, sizeof frame);
  const kernels::BootBlock boot = chip::boot_block(g);
  program.memory.write(*boot_addr, &boot, sizeof boot);

  iss::FunctionalStrataHook hook(hook_config);  // one hart: thread 0 of TM 0; global registers start at 0
  iss::Hart<iss::FlatMemory> hart(program.code, program.memory, &hook);
  iss::prepare_hart(hart, program);
  const auto t0 = std::chrono::steady_clock::now();
  const iss::RunResult r = hart.run(max_instructions);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!r.ok()) throw std::runtime_error(elf_path + ": firmware did not finish: " + iss::describe(r));

  RenderResult result;
  result.seconds = seconds;
  result.image.resize(size_t(settings.width) * settings.height);
  program.memory.read(uint32_t(g.framebuffer), result.image.data(),
                      result.image.size() * sizeof(kernels::Pixel));
  program.memory.read(uint32_t(g.counters), &result.counters, sizeof result.counters);
  if (stats) {
    stats->instructions = hart.instructions_retired();
    stats->seconds = seconds;
    stats->counters = hart.counters();
  }
  return result;
}

}  // namespace strata::sim
