// Small chips and small frames for the chip tests, set up as `strata-sim run` sets up a frame
// (sim/frame_setup.h): the design's kernel, the config completed from the scene image.
#pragma once

#include <cstring>

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/chip/chip.h"
#include "model/chip/design.h"
#include "scenes/procedural/procedural.h"
#include "scenes/scene_image.h"
#include "sim/frame_setup.h"
#include "sim/iss_render.h"
#include "sim/native_render.h"

namespace strata::chip::test {

// The build always makes the kernels (it stops without the RISC-V toolchain), so a missing
// one is a failure, never a skip.
#define REQUIRE_KERNEL(name)                                                                       \
  ASSERT_TRUE(std::filesystem::exists(sim::default_kernel_elf(name)))                              \
      << sim::default_kernel_elf(name) << " was not built"

inline ChipConfig small_chip(transport::TimingMode mode, uint32_t tms = 2, uint32_t tps = 8) {
  ChipConfig c;
  c.design = design_config("trax-baseline");
  c.tms = tms;
  c.tps_per_tm = tps;
  c.timing.mode = mode;
  c.l2.size_bytes = 1 << 20;
  c.finalize();
  return c;
}

// A small frame: a scene's image (treelets of the default L1 data cache) and its settings.
struct SmallFrame {
  scenes::SceneImage image;
  sim::RenderSettings settings;
  SmallFrame(const scenes::Scene& scene, uint32_t size) {
    image = scenes::build_scene_image(scene, sim::scene_image_params_for(ChipConfig{}), nullptr);
    settings.width = settings.height = size;
  }
  // This frame on `config`'s chip: the config completed from the image, and the design's
  // kernel unless `kernel_elf` names another.
  sim::PreparedFrame on(const ChipConfig& config, const std::string& kernel_elf = "") const {
    return sim::prepare_frame(config, image, settings, kernel_elf);
  }
};

// A small chip (2 TMs of 8 TPs) of `design`, with a 512 KB stream memory (unused by a design
// without streams).
inline ChipConfig small_design_chip(transport::TimingMode mode, const DesignConfig& design) {
  ChipConfig config = small_chip(mode, 2, 8);
  config.design = design;
  config.stream.size_bytes = 512 * 1024;
  config.finalize();
  return config;
}

// The chip's image and ray counters equal the native twin's, computed with the path arithmetic
// the design's path state implies (packed where the rays carry the state).
inline void expect_equals_native_twin(const Chip& chip, const SmallFrame& frame, PathStatePlacement path_state) {
  sim::RenderSettings twin_settings = frame.settings;
  if (path_state == PathStatePlacement::kCompact) twin_settings.path_arithmetic = sim::PathArithmetic::kPacked;
  const sim::RenderResult twin = sim::render_native(frame.image, twin_settings);
  const std::vector<kernels::Pixel> image = chip.framebuffer();
  EXPECT_EQ(std::memcmp(image.data(), twin.image.data(), image.size() * sizeof(kernels::Pixel)), 0)
      << "image differs from the native twin";
  const kernels::RayCounters rays = chip.ray_counters();
  EXPECT_EQ(std::memcmp(&rays, &twin.counters, sizeof rays), 0) << "ray statistics differ from the native twin";
}

// Every level's traffic by data class sums exactly to its totals.
inline void expect_by_data_sums_to_totals(const nlohmann::json& r) {
  struct Level {
    const char* name;
    const char* accesses;  // the total the classes' accesses sum to
    bool misses;
    std::vector<const char*> bytes;  // the totals the classes' bytes sum to
  };
  const Level levels[] = {{"l1d", "accesses", true, {"bytes_read", "bytes_written"}},
                          {"l1i", "accesses", true, {"bytes_read"}},
                          {"l2", "accesses", true, {"bytes_read", "bytes_written"}},
                          {"interconnect", "transfers", false, {"bytes"}},
                          {"stream", "accesses", false, {"bytes_read", "bytes_written"}},
                          {"dram", "accesses", false, {"bytes"}}};
  for (const Level& l : levels) {
    const nlohmann::json& g = r["memory"][l.name];
    uint64_t accesses = 0, misses = 0, bytes = 0;
    for (const auto& [cls, c] : g["by_data"].items()) {
      accesses += c["accesses"].get<uint64_t>();
      if (l.misses) {
        misses += c["misses"].get<uint64_t>();
      }
      bytes += c["bytes"].get<uint64_t>();
    }
    uint64_t total_bytes = 0;
    for (const char* b : l.bytes) total_bytes += g[b].get<uint64_t>();
    EXPECT_EQ(accesses, g[l.accesses].get<uint64_t>()) << l.name;
    if (l.misses) {
      EXPECT_EQ(misses, g["misses"].get<uint64_t>()) << l.name;
    }
    EXPECT_EQ(bytes, total_bytes) << l.name;
    EXPECT_EQ(g["by_data"]["other"]["accesses"], 0) << l.name << ": the chip classifies every access";
  }
}

// The fidelity sentinels at the default settings: no calendar overflowed and no XU request
// came too late. Reordered lookups are loosely timed's corrections; precise mode makes only the
// few that a cache's own downstream requests, sent ahead of global time, cause.
inline void expect_sentinels_quiet(const nlohmann::json& r, transport::TimingMode mode) {
  EXPECT_EQ(r["fidelity"]["calendar_overflow_bookings"], 0);
  EXPECT_EQ(r["fidelity"]["xu_late_requests"], 0);
  if (mode == transport::TimingMode::kPrecise) {
    EXPECT_LT(r["fidelity"]["reordered_share"].get<double>(), 1e-3);
  }
}

}  // namespace strata::chip::test
