// Where a frame's data sit in guest memory, for every platform that runs a render kernel (the
// chip, and the single-hart ISS render): one plan, one set of alignments. Above `base` come
// the scene image (aligned to its treelet size, so each treelet is cache-aligned), the frame
// parameters, the framebuffer, one RayCounters per thread and, for the streaming kernels,
// the path table. Also what each range holds, for the traffic-by-data statistics.
#pragma once

#include <cstdint>

#include "firmware/abi/boot_block.h"
#include "firmware/common/scene_layout.h"
#include "tlm/data_class.h"

namespace strata::chip {

struct FrameFootprint {
  uint64_t scene_image_bytes = 0;
  uint32_t treelet_bytes = 64;  // the image's alignment
  uint32_t pixels = 0;
  uint32_t threads = 1;        // RayCounters records
  uint32_t path_slots = 0;     // PathRecords (0: no path table)
  uint64_t sample_slots = 0;   // Pixels, one per sample (0: none; BootBlock::sample_slots)
};

struct GuestLayout {
  uint64_t code_begin = 0, code_end = 0;  // the kernel's loaded segments (set by the loader)
  uint64_t stacks = 0, stacks_end = 0;    // the chip's per-TP stacks (none on the ISS render)
  uint64_t scene_image = 0, frame = 0, framebuffer = 0, sample_slots = 0, counters = 0, path_table = 0;
  uint32_t path_slots = 0;
  uint64_t end = 0;  // one past the last byte
};

uint64_t align_up(uint64_t v, uint64_t alignment);

// Path records a streaming kernel gets: one per ray the stream memory holds, and no more than
// the frame's pixels (at least one). The chip and the one-hart ISS render both plan with it.
uint32_t path_slots_for(uint32_t stream_capacity_rays, uint32_t pixels);
// The most paths a streaming kernel has in flight: its fill starts one per ray the stream
// memory holds, less one ray's room per thread (a thread that popped a ray holds a slot for its
// successor), and no more than the frame's work items (firmware/kernels/streams_kernel.h,
// run()): its pixels when a pixel's samples run one after another, its samples when they run
// together (sample_slots_for).
uint32_t paths_in_flight_for(uint32_t stream_capacity_rays, uint32_t threads, uint64_t work_items);
// The per-sample slots a compact streaming kernel sums its pixels from: one per sample when
// there is more than one sample per pixel, else none (the sample is the pixel).
uint64_t sample_slots_for(uint32_t pixels, uint32_t samples_per_pixel);

// The data above `base`. Throws std::runtime_error when it leaves the 32-bit address space.
GuestLayout plan_frame_layout(uint64_t base, const FrameFootprint& f);
// Bytes plan_frame_layout can need above any base (alignment slack included).
uint64_t frame_layout_bytes(const FrameFootprint& f);

// What the kernel's strata_boot block gets.
kernels::BootBlock boot_block(const GuestLayout& g);

// Code, stacks and thread data, the scene image by section, the framebuffer and the path
// table. `image` is the scene image header as loaded at g.scene_image.
transport::DataClassMap data_class_map(const GuestLayout& g, const SceneImageHeader& image);

}  // namespace strata::chip
