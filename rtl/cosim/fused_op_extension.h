// One fused pipeline operation carried through TLM-2.0 to the RTL transactor
// (rtl/cosim/pipeline_transactor.h): the operands of a box test or a triangle test, the
// results the verilated pipeline produced, and the timing the transactor observed at the
// pipeline's handshake. The payload's data pointer is not used: everything is in this
// extension (tlm_generic_payload::set_extension, command TLM_IGNORE_COMMAND).
#pragma once

#include <cstdint>

#include <tlm>

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

class FusedOpExtension : public tlm::tlm_extension<FusedOpExtension> {
 public:
  // Request.
  FusedOpKind kind = FusedOpKind::kBox;
  BoxOperands box;
  TriangleOperands triangle;

  // Response.
  BoxResult box_result;
  TriangleResult triangle_result;
  // Observed timing, in cycles of the transactor's clock (rising edges since its start):
  // accept_cycle, the edge at which the pipeline accepted the operation (in_valid &&
  // in_ready); done_cycle, the edge at which its result left (out_valid && out_ready);
  // latency_cycles = done - accept, the RTL's own latency. A request is put on the pins at the
  // first edge after it arrives and can be accepted at the next one; queued_cycles counts the
  // edges it waited beyond that for a free slot (the initiation interval of earlier
  // operations). lane: the triangle lane that ran it (0 for a box test).
  uint64_t accept_cycle = 0, done_cycle = 0;
  uint32_t latency_cycles = 0, queued_cycles = 0;
  uint32_t lane = 0;

  tlm::tlm_extension_base* clone() const override { return new FusedOpExtension(*this); }
  void copy_from(const tlm::tlm_extension_base& other) override {
    *this = static_cast<const FusedOpExtension&>(other);
  }
};

}  // namespace strata::rtl
