#include "model/memory/downstream_port.h"

namespace strata::memory {

DownstreamResult DownstreamPort::send(tlm::tlm_command cmd, uint64_t addr, uint32_t bytes, transport::Cycle at,
                                      const transport::MemoryExtension* origin, transport::DataClass data) {
  transport::PooledPayload p(pool_);
  p->set_command(cmd);
  p->set_address(addr);
  p->set_data_ptr(scratch_.data());
  p->set_data_length(bytes);
  p->set_streaming_width(bytes);
  transport::MemoryExtension& ext = p.ext();
  ext.uncounted = !transport::counts(origin);  // what the requester did not count, below neither
  if (origin != nullptr) {
    ext.initiator_id = origin->initiator_id;
    ext.tm_id = origin->tm_id;
  }
  ext.access = cmd == tlm::TLM_WRITE_COMMAND ? transport::AccessClass::kDataStore : transport::AccessClass::kDataLoad;
  ext.timing_only = true;
  ext.data = data;

  const uint64_t stamp = sc_core::sc_time_stamp().value();
  sc_core::sc_time delay = clock_.delay_until_at(stamp, at);
  socket_->b_transport(*p, delay);
  if (!ext.uncounted) {
    ++requests_;
    bytes_ += bytes;
  }
  return DownstreamResult{p->is_response_ok(), clock_.request_cycle_at(stamp, delay), ext.served_by};
}

void DownstreamPort::warm(tlm::tlm_command cmd, uint64_t addr, const transport::MemoryExtension* origin,
                          transport::DataClass data) {
  transport::PooledPayload p(pool_);
  p->set_command(cmd);
  p->set_address(addr);
  p->set_data_ptr(scratch_.data());
  p->set_data_length(4);
  p->set_streaming_width(4);
  transport::MemoryExtension& ext = p.ext();
  ext.initiator_id = origin != nullptr ? origin->initiator_id : 0;
  ext.tm_id = origin != nullptr ? origin->tm_id : 0;
  ext.access = cmd == tlm::TLM_WRITE_COMMAND ? transport::AccessClass::kDataStore : transport::AccessClass::kDataLoad;
  ext.timing_only = ext.functional = ext.warm = true;
  ext.uncounted = false;
  ext.data = data;
  sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
  socket_->b_transport(*p, delay);
}

}  // namespace strata::memory
