// Zero-time TLM-2.0 transactor for the verilated fused pipelines: see zero_time_transactor.h.
#include "rtl/cosim/zero_time_transactor.h"

#include <stdexcept>

namespace strata::rtl {

ZeroTimeTransactor::ZeroTimeTransactor(sc_core::sc_module_name name) : sc_core::sc_module(name), socket("socket") {
  socket.register_b_transport(this, &ZeroTimeTransactor::b_transport);
}

void ZeroTimeTransactor::b_transport(tlm::tlm_generic_payload& payload, sc_core::sc_time& /*delay: untouched*/) {
  FusedOpExtension* op = nullptr;
  payload.get_extension(op);
  if (op == nullptr || payload.get_command() != tlm::TLM_IGNORE_COMMAND) {
    payload.set_response_status(tlm::TLM_COMMAND_ERROR_RESPONSE);
    return;
  }
  OpTiming t;
  try {
    if (op->kind == FusedOpKind::kBox)
      op->box_result = pipelines_.box(op->box, &t);
    else
      op->triangle_result = pipelines_.triangle(op->triangle, &t);
  } catch (const std::runtime_error& e) {
    SC_REPORT_ERROR("strata/rtl/zero_time_transactor", e.what());
    payload.set_response_status(tlm::TLM_GENERIC_ERROR_RESPONSE);
    return;
  }
  op->accept_cycle = t.accept_cycle;
  op->done_cycle = t.done_cycle;
  op->latency_cycles = t.latency_cycles;
  op->queued_cycles = 0;
  op->lane = t.lane;
  payload.set_response_status(tlm::TLM_OK_RESPONSE);
}

}  // namespace strata::rtl
