// The operands and results of one fused pipeline operation, as the verilated pipelines take
// and give them: shared by the TLM-2.0 extension (fused_op_extension.h) and the code that
// drives the pins without SystemC (clocked_pipelines.h).
#pragma once

#include <cstdint>

#include "firmware/common/intersect.h"

namespace strata::rtl {

enum class FusedOpKind : uint8_t { kBox, kTriangle };

// The box pipeline's operands: one box against one ray (intersect_box's arguments).
struct BoxOperands {
  float bmin[3] = {0, 0, 0}, bmax[3] = {0, 0, 0};
  BoxRay ray{};
};

// out_hit = intersect_box, out_overlap = intersect_box_valid_ray, t_entry = the t_near both
// write (on a hit and on a miss).
struct BoxResult {
  bool hit = false, overlap = false;
  float t_entry = 0.0f;
};

// The triangle pipeline's operands (triangle_hit_test's arguments).
struct TriangleOperands {
  Vec3f v0{}, v1{}, v2{}, origin{}, dir{};
};

// out_hit = triangle_hit_test, partial = the TrianglePartial it writes (presented on a miss
// too); exact: the test took the exact edge fallback (2 cycles longer, docs/rtl-cosim.md).
struct TriangleResult {
  bool hit = false, exact = false;
  TrianglePartial partial{};
};

}  // namespace strata::rtl
