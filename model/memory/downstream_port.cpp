#include "model/memory/downstream_port.h"

namespace strata::memory {

void DownstreamPort::prepare(transport::PooledPayload& p, tlm::tlm_command cmd, uint64_t addr, uint32_t bytes,
                             const transport::MemoryExtension* origin, transport::DataClass data) {
  p->set_command(cmd);
  p->set_address(addr);
  p->set_data_ptr(scratch_.data());
  p->set_data_length(bytes);
  p->set_streaming_width(bytes);
  transport::MemoryExtension& ext = p.ext();
  if (origin != nullptr) {
    ext.initiator_id = origin->initiator_id;
    ext.tm_id = origin->tm_id;
  }
  ext.access = cmd == tlm::TLM_WRITE_COMMAND ? transport::AccessClass::kDataStore : transport::AccessClass::kDataLoad;
  ext.timing_only = true;
  ext.data = data;
}

DownstreamResult DownstreamPort::send(tlm::tlm_command cmd, uint64_t addr, uint32_t bytes, transport::Cycle at,
                                      const transport::MemoryExtension* origin, transport::DataClass data) {
  transport::PooledPayload p(pool_);
  prepare(p, cmd, addr, bytes, origin, data);
  transport::MemoryExtension& ext = p.ext();
  ext.uncounted = !transport::counts(origin);  // what the requester did not count, below neither

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
  prepare(p, cmd, addr, 4, origin, data);
  p.ext().functional = p.ext().warm = true;
  sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
  socket_->b_transport(*p, delay);
}

}  // namespace strata::memory
