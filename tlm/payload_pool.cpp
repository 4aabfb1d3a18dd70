#include "tlm/payload_pool.h"

namespace strata::transport {

PayloadPool::PayloadPool(std::size_t initial) { grow(initial == 0 ? 1 : initial); }

PayloadPool::~PayloadPool() {
  // Payloads still referenced elsewhere would dangle; TLM initiators release before the end.
  for (auto& gp : owned_) gp->set_mm(nullptr);
}

void PayloadPool::grow(std::size_t count) {
  owned_.reserve(owned_.size() + count);
  for (std::size_t i = 0; i < count; ++i) {
    auto gp = std::make_unique<tlm::tlm_generic_payload>(this);
    // set_extension (not set_auto_extension): reset() keeps it, and ~tlm_generic_payload frees it.
    gp->set_extension(new MemoryExtension);
    free_.push_back(gp.get());
    owned_.push_back(std::move(gp));
  }
  // free() must never allocate: keep room for every payload we own.
  free_.reserve(owned_.size());
}

tlm::tlm_generic_payload* PayloadPool::acquire() {
  if (free_.empty()) grow(owned_.size());
  tlm::tlm_generic_payload* gp = free_.back();
  free_.pop_back();
  gp->acquire();
  gp->set_command(tlm::TLM_IGNORE_COMMAND);
  gp->set_address(0);
  gp->set_data_ptr(nullptr);
  gp->set_data_length(0);
  gp->set_streaming_width(0);
  gp->set_byte_enable_ptr(nullptr);
  gp->set_byte_enable_length(0);
  gp->set_dmi_allowed(false);
  gp->set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
  *gp->get_extension<MemoryExtension>() = MemoryExtension{};
  return gp;
}

void PayloadPool::free(tlm::tlm_generic_payload* gp) {
  gp->reset();  // drops auto extensions only; ours stays attached
  free_.push_back(gp);
}

}  // namespace strata::transport
