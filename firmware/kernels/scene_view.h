// Read access to a scene image at any base address: a host buffer in the native twin, a
// simulated-DRAM address on the thread processors. It is the Memory policy of traverse.h.
#pragma once

#include <stdint.h>

#include "firmware/common/scene_layout.h"

namespace strata::kernels {

class SceneView {
 public:
  SceneView() = default;
  explicit SceneView(const uint8_t* image)
      : header_(reinterpret_cast<const SceneImageHeader*>(image)),
        nodes_(image + header_->node_offset),
        triangles_(image + header_->triangle_offset),
        materials_(reinterpret_cast<const MaterialRecord*>(image + header_->material_offset)) {}

  const SceneImageHeader& header() const { return *header_; }
  const BvhNode& node(uint32_t index) const {
    return reinterpret_cast<const BvhNode*>(nodes_)[index];
  }
  const TriangleRecord& triangle(uint32_t byte_offset) const {
    return *reinterpret_cast<const TriangleRecord*>(triangles_ + byte_offset);
  }
  const MaterialRecord& material(uint32_t index) const { return materials_[index]; }

 private:
  const SceneImageHeader* header_ = nullptr;
  const uint8_t* nodes_ = nullptr;
  const uint8_t* triangles_ = nullptr;
  const MaterialRecord* materials_ = nullptr;
};

}  // namespace strata::kernels
