// The scene memory image: BVH nodes in node treelets, triangles in triangle treelets,
// materials, the treelet table, camera and light, in one blob laid out exactly as it sits
// in simulated DRAM (firmware/common/scene_layout.h, docs/scene-image.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "firmware/common/scene_layout.h"
#include "scenes/bvh_builder.h"
#include "scenes/scene.h"
#include "scenes/treelets.h"

namespace strata::scenes {

struct SceneImageParams {
  BvhBuildParams bvh;
  uint32_t treelet_bytes = 32 * 1024;  // = L1 data cache size
  TreeletPolicy treelet_policy = TreeletPolicy::surface_area;
};

// Build-time measurements, for `scene info`; not part of the image.
struct SceneBuildReport {
  double bvh_seconds = 0, treelet_seconds = 0, layout_seconds = 0;
  bool from_cache = false;
  std::string cache_note;  // what the cache did and why
};

class SceneImage {
 public:
  SceneImage() = default;
  // Takes a blob and checks it completely; throws SceneError naming `source` if invalid.
  SceneImage(std::vector<uint64_t> words, const std::string& source);

  const SceneImageHeader& header() const { return *reinterpret_cast<const SceneImageHeader*>(words_.data()); }
  const uint8_t* bytes() const { return reinterpret_cast<const uint8_t*>(words_.data()); }
  uint64_t size_bytes() const { return header().image_bytes; }
  const std::vector<uint64_t>& words() const { return words_; }

  // Accessors in the form firmware/common/traverse.h expects of its Memory policy.
  const BvhNode& node(uint32_t index) const {
    return *reinterpret_cast<const BvhNode*>(bytes() + header().node_offset + uint64_t(index) * sizeof(BvhNode));
  }
  const TriangleRecord& triangle(uint32_t byte_offset) const {
    return *reinterpret_cast<const TriangleRecord*>(bytes() + header().triangle_offset + byte_offset);
  }
  const TreeletRecord& treelet(uint32_t i) const {
    return reinterpret_cast<const TreeletRecord*>(bytes() + header().treelet_table_offset)[i];
  }
  const MaterialRecord& material(uint32_t i) const {
    return reinterpret_cast<const MaterialRecord*>(bytes() + header().material_offset)[i];
  }
  uint32_t treelet_of_triangle(uint32_t byte_offset) const {
    return header().node_treelet_count + byte_offset / header().treelet_bytes;
  }

 private:
  std::vector<uint64_t> words_;  // 8-byte aligned storage for the blob
};

// Deterministic: the same scene and parameters give a bit-identical image.
SceneImage build_scene_image(const Scene& scene, const SceneImageParams& params,
                             SceneBuildReport* report);

// The checksum stored in the header: the whole image, with the checksum field read as 0.
uint64_t scene_image_checksum(const uint8_t* bytes, uint64_t size);

// Cache key: hash of the scene content, the build parameters and the image version.
uint64_t scene_content_key(const Scene& scene, const SceneImageParams& params);

void check_image_params(const SceneImageParams& params);

}  // namespace strata::scenes
