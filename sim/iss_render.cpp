#include "sim/iss_render.h"

#include <chrono>
#include <cstring>
#include <stdexcept>

#include "firmware/kernels/boot_block.h"
#include "model/iss/functional_strata_hook.h"
#include "model/iss/hart.h"
#include "model/iss/program.h"

namespace strata::sim {
namespace {

uint64_t align_up(uint64_t v, uint64_t a) { return (v + a - 1) / a * a; }

// Guest addresses of everything the kernel reads or writes, relative to the data region.
struct DataLayout {
  uint64_t image, frame, framebuffer, counters, total;
};

DataLayout plan(const scenes::SceneImage& image, const RenderSettings& s) {
  DataLayout d{};
  d.image = 0;  // the data region is 1 MiB aligned; the image is re-aligned below if needed
  d.frame = align_up(image.size_bytes(), 64);
  d.framebuffer = align_up(d.frame + sizeof(kernels::FrameParams), 64);
  d.counters = align_up(d.framebuffer + uint64_t(s.width) * s.height * sizeof(kernels::Pixel), 64);
  d.total = d.counters + sizeof(kernels::RayCounters);
  return d;
}

}  // namespace

std::string default_kernel_elf(const std::string& kernel) {
  return std::string(STRATA_FIRMWARE_KERNEL_DIR) + "/" + kernel + ".elf";
}

RenderResult render_on_iss(const scenes::SceneImage& image, const RenderSettings& settings,
                           const std::string& elf_path, uint64_t max_instructions,
                           IssRunStats* stats) {
  check_render_settings(settings);
  const uint32_t treelet_bytes = image.header().treelet_bytes;
  DataLayout d = plan(image, settings);
  const uint64_t slack = treelet_bytes;  // room to align the image to its treelet size
  if (d.total + slack > 0xC0000000ull)
    throw std::runtime_error("iss render: scene image and frame do not fit the 32-bit guest address space");
  iss::Program program = iss::load_program(elf_path, iss::kDefaultStackBytes, uint32_t(d.total + slack));
  const uint64_t base = align_up(program.data_base, treelet_bytes);
  const auto boot_addr = program.elf.symbol(kernels::kBootBlockSymbol);
  if (!boot_addr) throw std::runtime_error(elf_path + ": no '" + std::string(kernels::kBootBlockSymbol) + "' symbol: not a render kernel");

  const kernels::FrameParams frame = make_frame_params(image.header(), settings);
  program.memory.write(uint32_t(base + d.image), image.bytes(), image.size_bytes());
  program.memory.write(uint32_t(base + d.frame), &frame, sizeof frame);
  const kernels::BootBlock boot{uint32_t(base + d.frame), uint32_t(base + d.image),
                                uint32_t(base + d.framebuffer), uint32_t(base + d.counters), 0, 0, {0, 0}};
  program.memory.write(*boot_addr, &boot, sizeof boot);

  iss::FunctionalStrataHook hook;  // one hart: thread 0 of TM 0; global registers start at 0
  iss::Hart<iss::FlatMemory> hart(program.code, program.memory, &hook);
  iss::prepare_hart(hart, program);
  const auto t0 = std::chrono::steady_clock::now();
  const iss::RunResult r = hart.run(max_instructions);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!r.ok()) throw std::runtime_error(elf_path + ": firmware did not finish: " + iss::describe(r));

  RenderResult result;
  result.seconds = seconds;
  result.image.resize(size_t(settings.width) * settings.height);
  program.memory.read(uint32_t(base + d.framebuffer), result.image.data(),
                      result.image.size() * sizeof(kernels::Pixel));
  program.memory.read(uint32_t(base + d.counters), &result.counters, sizeof result.counters);
  if (stats) {
    stats->instructions = hart.instructions_retired();
    stats->seconds = seconds;
    stats->counters = hart.counters();
  }
  return result;
}

}  // namespace strata::sim
