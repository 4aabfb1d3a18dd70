// The chip top: N thread multiprocessors, each with its L1 data and instruction caches, an
// interconnect to the banked L2 and the ray stream memory, DRAM channels behind the L2, the
// global registers, and one sparse backing store holding the firmware, the TP stacks, the
// scene image, the frame parameters, the framebuffer and the per-thread ray counters.
// Everything is connected through TLM-2.0 sockets.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <systemc>

#include "firmware/abi/frame_abi.h"
#include "model/chip/chip_config.h"
#include "model/tm/fused_backend_factory.h"
#include "model/tm/global_registers.h"
#include "model/chip/guest_layout.h"
#include "model/tm/thread_multiprocessor.h"
#include "model/sampling/window_sampler.h"
#include "model/iss/code_image.h"
#include "model/iss/elf_loader.h"
#include "model/memory/interconnect.h"
#include "model/memory/l1_data_cache.h"
#include "model/memory/l1_instruction_cache.h"
#include "model/memory/memory_levels.h"
#include "model/memory/sparse_memory.h"
#include "model/stats/stat_group.h"
#include "tlm/data_class.h"

namespace strata::chip {

// The TM's types the chip's interface names (model/tm/).
using tm::FusedBackendFactory;
using tm::FusedBackendSetup;
using tm::GlobalRegisters;
using sampling::SamplingSchedule;
using sampling::WindowSampler;
using tm::ThreadMultiprocessor;
using tm::TmCounters;
using tm::TmEnvironment;
using transport::TurnOrder;

// What one frame needs besides the chip: the kernel, the scene image and the frame setup.
struct FrameInputs {
  std::string kernel_elf;
  const uint8_t* scene_image = nullptr;
  uint64_t scene_image_bytes = 0;
  uint32_t treelet_bytes = 0;  // the image is placed at an address aligned to it
  kernels::FrameParams frame{};
  // tm.pipeline_impl=rtl: makes each such TM's fused-pipeline backend (fused_backend_factory.h).
  FusedBackendFactory pipeline_backend;
};

// The chip top owns every module it wires (the memory levels, the L1s and TMs, the turn order,
// the sampler) and the frame's shared state, grouped by job (the program, the frame's shape, what
// the statistics read): about twenty members, each a part of the chip rather than a job of its own.
class Chip : public sc_core::sc_module {
 public:
  // Throws ConfigError / iss::ElfError / std::runtime_error naming what is wrong.
  Chip(sc_core::sc_module_name name, const ChipConfig& config, const FrameInputs& inputs);
  ~Chip() override;

  // Registers every module's VCD traces; call before sc_start.
  using sc_core::sc_object::trace;  // ours adds a window; the base's stays visible
  void trace(sc_core::sc_trace_file* file, const memory::TraceWindow& window);

  // After the simulation: did every TM finish, and the first error if not.
  bool finished() const;
  std::string error() const;
  transport::Cycle cycles() const;  // when the last TP finished (stopped early: global time reached)

  // Pixels whose every sample is finished (streaming kernels), or handed out (baseline). With a
  // pixel's samples in flight together, the samples finished, in pixels' worth.
  uint32_t pixels_done() const;
  uint32_t pixel_count() const { return frame_.pixels; }
  // What the kernel hands out as work: pixels, or (the compact path state at more than one
  // sample per pixel) samples, whose paths are in flight together.
  uint64_t work_items() const { return frame_.samples_together ? uint64_t{frame_.pixels} * frame_.spp : frame_.pixels; }
  bool samples_together() const { return frame_.samples_together; }
  uint64_t instructions() const;

  std::vector<kernels::Pixel> framebuffer() const;
  kernels::RayCounters ray_counters() const;  // summed over the threads
  std::vector<kernels::RayCounters> ray_counters_per_thread() const;

  const ChipConfig& config() const { return config_; }
  // The kernel that ran: its file name and the digest of its loaded image (iss::image_digest).
  const std::string& kernel_name() const { return program_.name; }
  const std::string& kernel_digest() const { return program_.digest; }
  const GuestLayout& layout() const { return layout_; }
  const std::vector<std::unique_ptr<ThreadMultiprocessor>>& tms() const { return tms_; }
  const std::vector<std::unique_ptr<memory::L1DataCache>>& l1d() const { return l1d_; }
  const std::vector<std::unique_ptr<memory::L1InstructionCache>>& l1i() const { return l1i_; }
  const memory::L2Level& l2() const { return *l2_; }
  const memory::StreamLevel& stream() const { return *stream_; }
  const memory::DramLevel& dram() const { return *dram_; }
  const memory::Interconnect& interconnect() const { return *interconnect_; }
  const memory::SparseMemory& backing() const { return backing_; }
  const transport::DataClassMap& data_classes() const { return data_classes_; }

  // The statistics tree of the whole chip (docs/statistics.md): frame, rays, the TMs'
  // instructions and XUs, every memory level, energy and the fidelity sentinels.
  const stats::Group& statistics() const { return stats_; }
  // Sampled timing: the windows' samples for the confidence intervals (null in other modes).
  const stats::BatchMeans* window_batches() const { return sampler_ ? &sampler_->batches() : nullptr; }
  // Sampled timing with an error target: the named statistics the plan left out as out of reach.
  const std::vector<WindowSampler::OutOfReach>& targets_out_of_reach() const {
    static const std::vector<WindowSampler::OutOfReach> none;
    return sampler_ ? sampler_->out_of_reach() : none;
  }

 private:
  void load(const FrameInputs& inputs, const iss::ElfImage& elf);
  void register_stats();  // chip_statistics.cpp
  void register_rtl_pipeline_stats(stats::Group& group);
  void register_treelet_stats(stats::Group& group);  // treelet_statistics.cpp

  ChipConfig config_;
  memory::SparseMemory backing_;
  GlobalRegisters globals_;
  tm::TmSetup tm_setup_;  // the chip as its TMs see it (from config_)
  // The kernel: its code (predecoded once, shared by every TP), which one it is, and where it
  // counts finished work.
  struct Program {
    iss::CodeImage code;
    std::string name, digest;    // the ELF's file name; iss::image_digest of what it loads
    uint32_t done_register = 0;  // the design's (design.h)
  };
  Program program_;
  GuestLayout layout_;
  transport::DataClassMap data_classes_;
  // The frame's shape, as the kernel sees it.
  struct FrameShape {
    uint32_t pixels = 0;
    uint32_t spp = 1;
    bool samples_together = false;  // the kernel got per-sample slots (guest_layout.h)
    uint32_t node_treelets = 0;     // from the scene header: treelets [0, n) hold nodes
  };
  FrameShape frame_;
  std::unique_ptr<memory::DramLevel> dram_;
  std::unique_ptr<memory::L2Level> l2_;
  std::unique_ptr<memory::StreamLevel> stream_;
  std::unique_ptr<memory::Interconnect> interconnect_;
  std::vector<std::unique_ptr<memory::L1DataCache>> l1d_;
  std::vector<std::unique_ptr<memory::L1InstructionCache>> l1i_;
  std::vector<std::unique_ptr<ThreadMultiprocessor>> tms_;
  std::unique_ptr<TurnOrder> turns_;  // the TMs', and the window sampler's, turns at global time

  // Statistics: the tree, the groups the chip owns, and what they read at a snapshot.
  stats::Group stats_;
  std::vector<std::unique_ptr<stats::Group>> stat_groups_;
  // What the statistics read, gathered before each snapshot.
  struct Snapshot {
    transport::Cycle report_cycle = 0;  // the cycle the statistics are taken at
    kernels::RayCounters ray_totals{};
    uint64_t ray_total = 0;
    memory::StreamOccupancy::Summary occupancy{};  // the stream memory's levels up to report_cycle
  };
  Snapshot snapshot_;
  FusedBackendFactory pipeline_backend_;  // the TMs' environment points at it
  std::unique_ptr<SamplingSchedule> schedule_;  // sampled timing only
  std::unique_ptr<WindowSampler> sampler_;     // sampled timing only
};

}  // namespace strata::chip
