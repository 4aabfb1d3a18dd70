// One fused pipeline operation carried through TLM-2.0 to the RTL transactor
// (rtl/cosim/pipeline_transactor.h): the operands of a box test or a triangle test, the
// results the verilated pipeline produced, and the timing the transactor observed at the
// pipeline's handshake. The payload's data pointer is not used: everything is in this
// extension (tlm_generic_payload::set_extension, command TLM_IGNORE_COMMAND). The zero-time
// transactor (zero_time_transactor.h) takes the same transactions.
#pragma once

#include <cstdint>

#include <tlm>

#include "rtl/cosim/fused_op.h"

namespace strata::rtl {

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
