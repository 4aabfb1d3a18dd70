#include "model/chip/chip.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "firmware/abi/boot_block.h"
#include "model/chip/design.h"
#include "model/memory/memory_level_factory.h"
#include "model/memory/stream_sram.h"

namespace strata::chip {
namespace {

// The predecoded code of the kernel's executable segments, shared by every TP of the chip.
iss::CodeImage build_code(const iss::ElfImage& elf) {
  uint64_t low = UINT64_MAX, high = 0;
  for (const iss::ElfSegment& s : elf.segments)
    if (s.executable) {
      low = std::min<uint64_t>(low, s.vaddr & ~3u);
      high = std::max<uint64_t>(high, align_up(uint64_t{s.vaddr} + s.memsz, 4));
    }
  if (high == 0) throw iss::ElfError(elf.path + ": no executable segment");
  std::vector<uint32_t> words(static_cast<size_t>((high - low) / 4), 0);
  for (const iss::ElfSegment& s : elf.segments)
    if (s.executable && !s.bytes.empty())
      std::memcpy(reinterpret_cast<uint8_t*>(words.data()) + (s.vaddr - low), s.bytes.data(), s.bytes.size());
  return iss::CodeImage(static_cast<uint32_t>(low), std::move(words));
}

// What the TMs need of the config (model/tm/tm_setup.h).
tm::TmSetup tm_setup_for(const ChipConfig& c) {
  tm::TmSetup s;
  s.tms = c.tms;
  s.tps_per_tm = c.tps_per_tm;
  s.tp_stack_bytes = c.tp_stack_bytes;
  s.l1d_line_bytes = c.l1d.line_bytes;
  s.l1d_size_bytes = c.l1d.size_bytes;
  s.l1i_line_bytes = c.l1i.line_bytes;
  s.streams = c.design.streams;
  s.global_register_latency_cycles = c.global_register_latency_cycles;
  s.tm = c.tm;
  s.timing = c.timing;
  s.clock = c.clock();
  for (uint32_t t = 0; t < c.tms; ++t) s.rtl_pipelines.push_back(c.rtl_pipelines(t));
  return s;
}

}  // namespace

Chip::Chip(sc_core::sc_module_name name, const ChipConfig& config, const FrameInputs& inputs)
    : sc_core::sc_module(name), config_(config), stats_("chip", "One simulated frame on the chip.") {
  const iss::ElfImage elf = iss::load_elf(inputs.kernel_elf);
  program_.code = build_code(elf);
  program_.name = std::filesystem::path(inputs.kernel_elf).filename().string();
  program_.digest = iss::image_digest(elf);
  program_.done_register = checked_design(config_.design).done_register;
  load(inputs, elf);

  // The shared levels through their interfaces (memory_levels.h), each the model its config
  // names, checked against the statistics the chip reads of it.
  dram_ = memory::make_dram_level("dram", config_.dram, backing_);
  l2_ = memory::make_l2_level("l2", config_.l2, backing_);
  stream_ = memory::make_stream_level("stream", config_.stream);
  interconnect_ = std::make_unique<memory::Interconnect>("interconnect", config_.interconnect);
  interconnect_->l2_side.bind(l2_->target_socket());
  interconnect_->stream_side.bind(stream_->target_socket());
  l2_->downstream_socket().bind(dram_->target_socket());
  const transport::Clock clock = config_.clock();
  dram_->set_clock(clock);
  l2_->set_clock(clock);
  stream_->set_clock(clock);
  interconnect_->set_clock(clock);

  if (config_.timing.mode == transport::TimingMode::kSampled) {
    schedule_ = std::make_unique<SamplingSchedule>(config_.timing);
    WindowSampler::plan_head(config_.timing, *schedule_);
  }
  // The window sampler takes its turn after the TMs' at the same cycle (id config_.tms).
  const bool sampled = config_.timing.mode == transport::TimingMode::kSampled;
  turns_ = std::make_unique<TurnOrder>(config_.tms + (sampled ? 1u : 0u), config_.tms, clock);
  tm_setup_ = tm_setup_for(config_);
  TmEnvironment env;
  env.setup = &tm_setup_;
  env.turns = turns_.get();
  env.schedule = schedule_.get();
  env.backing = &backing_;
  env.code = &program_.code;
  env.globals = &globals_;
  env.entry_pc = elf.entry;
  env.tohost = elf.symbol("tohost").value_or(0);
  env.guest_low = 0x1000;  // the first page stays unmapped, so a null pointer faults
  env.guest_high = layout_.end;
  env.stacks_base = static_cast<uint32_t>(layout_.stacks);
  env.data_classes = &data_classes_;
  env.path_state_on_chip = config_.design.streams && config_.design.path_state == PathStatePlacement::kOnChip;
  env.stream_ray_bytes = config_.stream.ray_bytes;
  env.path_begin = layout_.path_table;
  env.path_end = layout_.path_table + uint64_t{layout_.path_slots} * kernels::kPathRecordBytes;
  env.report_cycle = &snapshot_.report_cycle;
  env.node_treelets = frame_.node_treelets;
  pipeline_backend_ = inputs.pipeline_backend;
  if (config_.pipeline_impl == PipelineImpl::kRtl && !pipeline_backend_)
    throw ConfigError("tm.pipeline_impl: rtl, but the program running the chip supplied no RTL pipeline backend");
  env.pipeline_backend = &pipeline_backend_;
  for (uint32_t t = 0; t < config_.tms; ++t) {
    const std::string n = std::to_string(t);
    l1d_.push_back(std::make_unique<memory::L1DataCache>(("l1d_" + n).c_str(), config_.l1d, backing_));
    l1i_.push_back(std::make_unique<memory::L1InstructionCache>(("l1i_" + n).c_str(), config_.l1i, backing_));
    l1d_.back()->set_clock(clock);
    l1i_.back()->set_clock(clock);
    tms_.push_back(std::make_unique<ThreadMultiprocessor>(("tm_" + n).c_str(), env, t));
    tms_.back()->data_port.bind(l1d_.back()->target);
    tms_.back()->fetch_port.bind(l1i_.back()->target);
    l1d_.back()->downstream.bind(interconnect_->tm_side);
    l1i_.back()->downstream.bind(interconnect_->tm_side);
    tms_.back()->stream_port.bind(interconnect_->tm_side);
  }
  register_stats();
  if (config_.timing.mode == transport::TimingMode::kSampled)
    sampler_ = std::make_unique<WindowSampler>("window_sampler", config_.timing, config_.tms, *schedule_, stats_, *turns_, WindowSampler::Progress{
        [this] { return finished(); }, [this] { return pixel_count() ? double(pixels_done()) / pixel_count() : 0.0; },
        [this] { return uint64_t{cycles()}; },
        [this] {  // every work item handed out: the frame's drain has begun
          return frame_.samples_together ? globals_.values[kernels::kSampleCounterRegister] >= work_items()
                                   : globals_.values[kernels::kPixelCounterRegister] >= frame_.pixels;
        }});
}

Chip::~Chip() = default;

void Chip::load(const FrameInputs& in, const iss::ElfImage& elf) {
  uint64_t code_begin = UINT64_MAX, elf_end = 0;
  for (const iss::ElfSegment& s : elf.segments) {
    if (!s.bytes.empty()) backing_.write(s.vaddr, s.bytes.data(), s.bytes.size());
    code_begin = std::min<uint64_t>(code_begin, s.vaddr);
    elf_end = std::max<uint64_t>(elf_end, uint64_t{s.vaddr} + s.memsz);
  }
  const auto boot_symbol = elf.symbol(kernels::kBootBlockSymbol);
  if (!boot_symbol)
    throw std::runtime_error(elf.path + ": no '" + std::string(kernels::kBootBlockSymbol) + "' symbol: not a render kernel");
  if (in.scene_image_bytes < sizeof(SceneImageHeader))
    throw std::runtime_error("chip: the scene image is smaller than its header");
  frame_.pixels = in.frame.width * in.frame.height;
  frame_.spp = in.frame.samples_per_pixel;
  // The compact path state runs a pixel's samples together, each summed from its own slot.
  const bool compact = config_.design.streams && config_.design.path_state == PathStatePlacement::kCompact;
  const uint64_t sample_slots = compact ? sample_slots_for(frame_.pixels, frame_.spp) : 0u;
  frame_.samples_together = sample_slots > 0;
  // Per-TP stacks sit above the kernel, then the frame's data (guest_layout.h). Streaming
  // kernels keep one path record per ray the stream memory can hold.
  const uint64_t stacks = align_up(elf_end, 1 << 16);
  const uint64_t stacks_end = stacks + uint64_t{config_.threads()} * config_.tp_stack_bytes;
  FrameFootprint f;
  f.scene_image_bytes = in.scene_image_bytes;
  f.treelet_bytes = in.treelet_bytes;
  f.pixels = frame_.pixels;
  f.threads = config_.threads();
  f.sample_slots = sample_slots;
  f.path_slots = config_.design.streams && config_.design.path_state != PathStatePlacement::kCompact
                     ? path_slots_for(memory::make_stream_layout(config_.stream).capacity, frame_.pixels)
                     : 0u;
  layout_ = plan_frame_layout(stacks_end, f);
  layout_.code_begin = code_begin;
  layout_.code_end = elf_end;
  layout_.stacks = stacks;
  layout_.stacks_end = stacks_end;
  backing_.write(layout_.scene_image, in.scene_image, in.scene_image_bytes);
  backing_.write(layout_.frame, &in.frame, sizeof in.frame);
  const kernels::BootBlock boot = boot_block(layout_);
  backing_.write(*boot_symbol, &boot, sizeof boot);
  SceneImageHeader header;
  std::memcpy(&header, in.scene_image, sizeof header);
  data_classes_ = data_class_map(layout_, header);
  frame_.node_treelets = header.node_treelet_count;
}

void Chip::trace(sc_core::sc_trace_file* file, const memory::TraceWindow& window) {
  for (auto& tm : tms_) tm->trace(file, window);
  for (auto& c : l1d_) c->trace(file, window);
  for (auto& c : l1i_) c->trace(file, window);
  l2_->trace(file, window);
  stream_->trace(file, window);
  dram_->trace(file, window);
  interconnect_->trace(file, window);
}

bool Chip::finished() const {
  return std::all_of(tms_.begin(), tms_.end(), [](const auto& tm) { return tm->finished(); });
}

std::string Chip::error() const {
  for (const auto& tm : tms_)
    if (tm->failed()) return tm->error();
  return finished() ? "" : "the simulation stopped before every TM finished";
}

transport::Cycle Chip::cycles() const {
  transport::Cycle c = 0;
  for (const auto& tm : tms_) c = std::max(c, tm->counters().finished_cycle);
  if (!finished()) {  // stopped early (Ctrl-C): as far as global time got
    c = std::max(c, config_.clock().now());
  }
  return c;
}

uint32_t Chip::pixels_done() const {
  if (frame_.samples_together) return uint32_t(std::min<uint64_t>(globals_.values[kernels::kPixelsDoneRegister] / frame_.spp, frame_.pixels));
  return std::min(globals_.values[program_.done_register], frame_.pixels);
}

uint64_t Chip::instructions() const {
  uint64_t n = 0;
  for (const auto& tm : tms_) n += tm->counters().instructions;
  return n;
}

std::vector<kernels::Pixel> Chip::framebuffer() const {
  std::vector<kernels::Pixel> pixels(frame_.pixels);
  backing_.read(layout_.framebuffer, pixels.data(), pixels.size() * sizeof(kernels::Pixel));
  return pixels;
}

std::vector<kernels::RayCounters> Chip::ray_counters_per_thread() const {
  std::vector<kernels::RayCounters> c(config_.threads());
  backing_.read(layout_.counters, c.data(), c.size() * sizeof(kernels::RayCounters));
  return c;
}

kernels::RayCounters Chip::ray_counters() const {
  kernels::RayCounters sum{};
  for (const kernels::RayCounters& c : ray_counters_per_thread()) {
    for (uint32_t t = 0; t < kernels::kRayTypes; ++t) {
      sum.rays[t] += c.rays[t];
      sum.hits[t] += c.hits[t];
    }
    sum.node_visits += c.node_visits;
    sum.triangle_tests += c.triangle_tests;
    sum.paths += c.paths;
  }
  return sum;
}

}  // namespace strata::chip
