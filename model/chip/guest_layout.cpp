#include "model/chip/guest_layout.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "firmware/abi/frame_abi.h"
#include "model/iss/hex_text.h"

namespace strata::chip {

using transport::DataClass;

uint64_t align_up(uint64_t v, uint64_t a) { return (v + a - 1) / a * a; }

uint32_t path_slots_for(uint32_t stream_capacity_rays, uint32_t pixels) {
  return std::min(stream_capacity_rays, std::max(pixels, 1u));
}

uint32_t paths_in_flight_for(uint32_t stream_capacity_rays, uint32_t threads, uint64_t work_items) {
  const uint32_t fill = stream_capacity_rays > threads ? stream_capacity_rays - threads : 1u;
  return uint32_t(std::min<uint64_t>(fill, std::max<uint64_t>(work_items, 1u)));
}

uint64_t sample_slots_for(uint32_t pixels, uint32_t samples_per_pixel) {
  return samples_per_pixel > 1 ? uint64_t{pixels} * samples_per_pixel : 0u;
}

GuestLayout plan_frame_layout(uint64_t base, const FrameFootprint& f) {
  GuestLayout g;
  const uint64_t treelet = f.treelet_bytes > 64 ? f.treelet_bytes : 64;
  g.scene_image = align_up(base, treelet);
  g.frame = align_up(g.scene_image + f.scene_image_bytes, 64);
  g.framebuffer = align_up(g.frame + sizeof(kernels::FrameParams), 64);
  g.sample_slots = align_up(g.framebuffer + uint64_t{f.pixels} * sizeof(kernels::Pixel), 64);
  g.counters = align_up(g.sample_slots + f.sample_slots * sizeof(kernels::Pixel), 64);
  g.path_table = align_up(g.counters + uint64_t{f.threads} * sizeof(kernels::RayCounters), 64);
  g.path_slots = f.path_slots;
  g.end = align_up(g.path_table + uint64_t{f.path_slots} * kernels::kPathRecordBytes, 64);
  if (f.sample_slots == 0) g.sample_slots = 0;  // the boot block's "none"
  if (g.end > 0xFFFFFFFFull)
    throw std::runtime_error(
        "guest memory: the scene image and frame need " + std::to_string(g.end - base) + " bytes above " +
        iss::hex_text(base) + ", beyond the 32-bit guest address space" +
        (f.sample_slots ? " (of which " + std::to_string(f.sample_slots * sizeof(kernels::Pixel)) +
                              " bytes are the per-sample slots, one per pixel and sample: fewer samples per pixel "
                              "or a smaller frame)"
                        : std::string()));
  return g;
}

uint64_t frame_layout_bytes(const FrameFootprint& f) {
  const GuestLayout g = plan_frame_layout(0, f);
  return g.end + (f.treelet_bytes > 64 ? f.treelet_bytes : 64);
}

kernels::BootBlock boot_block(const GuestLayout& g) {
  return kernels::BootBlock{static_cast<uint32_t>(g.frame),      static_cast<uint32_t>(g.scene_image),
                            static_cast<uint32_t>(g.framebuffer), static_cast<uint32_t>(g.counters),
                            static_cast<uint32_t>(g.path_table), g.path_slots,
                            static_cast<uint32_t>(g.sample_slots), 0};
}

transport::DataClassMap data_class_map(const GuestLayout& g, const SceneImageHeader& h) {
  transport::DataClassMap m;
  // The kernel's data (.rodata, .data, .bss) share the loaded segments with its code; a data
  // load from them is thread data, and fetches are tagged as instructions by the fetch path.
  m.add(g.code_begin, g.code_end, DataClass::kThreadData);
  m.add(g.stacks, g.stacks_end, DataClass::kThreadData);
  const uint64_t img = g.scene_image;
  const uint64_t nodes_begin = img + h.node_offset, nodes_end = nodes_begin + uint64_t{h.node_slots} * sizeof(BvhNode);
  const uint64_t tris_begin = img + h.triangle_offset, tris_end = tris_begin + h.triangle_bytes;
  // Header, materials and treelet table come before the node section; whatever lies between
  // and after the sections (alignment padding) is scene data too.
  m.add(img, nodes_begin, DataClass::kScene);
  m.add(nodes_begin, nodes_end, DataClass::kNodes);
  if (tris_begin >= nodes_end) {
    m.add(nodes_end, tris_begin, DataClass::kScene);
    m.add(tris_begin, tris_end, DataClass::kTriangles);
    m.add(tris_end, g.frame, DataClass::kScene);
  }
  m.add(g.frame, g.framebuffer, DataClass::kThreadData);  // the frame parameters
  m.add(g.framebuffer, g.counters, DataClass::kFramebuffer);  // with the per-sample slots, if any
  m.add(g.counters, g.path_table, DataClass::kThreadData);  // per-thread ray counters
  m.add(g.path_table, g.end, DataClass::kPathState);
  return m;
}

}  // namespace strata::chip
