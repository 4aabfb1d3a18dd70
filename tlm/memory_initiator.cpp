#include "tlm/memory_initiator.h"

namespace strata::transport {

namespace {
sc_core::sc_time quantum_of(const InitiatorConfig& c) {
  const Clock clock;
  return clock.duration(c.mode == TimingMode::kPrecise ? 1 : (c.quantum_cycles == 0 ? 1 : c.quantum_cycles));
}
}  // namespace

MemoryInitiator::MemoryInitiator(sc_core::sc_module_name name, const InitiatorConfig& config)
    : sc_core::sc_module(name), config_(config), keeper_(quantum_of(config)), pool_(2) {}

AccessResult MemoryInitiator::access(AccessClass access, uint64_t addr, void* data, uint32_t bytes,
                                     uint32_t treelet) {
  if (config_.mode == TimingMode::kPrecise) keeper_.sync();

  PooledPayload gp(pool_);
  prepare_access(gp, access, addr, data, bytes, config_.initiator_id, config_.tm_id, treelet);
  const MemoryExtension& ext = gp.ext();

  sc_core::sc_time delay = keeper_.local_time();
  AccessResult r;
  r.issued = clock_.request_cycle(delay);
  socket->b_transport(*gp, delay);
  r.completed = clock_.request_cycle(delay);
  r.response = gp->get_response_status();
  r.stream_status = ext.stream_status;
  r.result = ext.result;
  r.served_by = ext.served_by;

  // Blocking access: this thread's time moves to the completion.
  keeper_.set(delay);
  if (config_.mode != TimingMode::kPrecise && keeper_.need_sync()) keeper_.sync();
  return r;
}

void MemoryInitiator::advance(Cycle cycles) {
  keeper_.inc(clock_.duration(cycles));
  if (config_.mode != TimingMode::kPrecise && keeper_.need_sync()) keeper_.sync();
}

AccessResult MemoryInitiator::load(uint64_t addr, void* data, uint32_t bytes) {
  return access(AccessClass::kDataLoad, addr, data, bytes);
}
AccessResult MemoryInitiator::store(uint64_t addr, const void* data, uint32_t bytes) {
  // TLM payloads carry a non-const pointer; a store's data is only read.
  return access(AccessClass::kDataStore, addr, const_cast<void*>(data), bytes);
}
AccessResult MemoryInitiator::fetch(uint64_t addr, void* data, uint32_t bytes) {
  return access(AccessClass::kInstructionFetch, addr, data, bytes);
}
AccessResult MemoryInitiator::stream_push(uint32_t treelet, const void* ray48) {
  return access(AccessClass::kStreamPush, 0, const_cast<void*>(ray48), 48, treelet);
}
AccessResult MemoryInitiator::stream_pop(uint32_t treelet, void* ray48) {
  return access(AccessClass::kStreamPop, 0, ray48, 48, treelet);
}
AccessResult MemoryInitiator::stream_size(uint32_t treelet) {
  return access(AccessClass::kStreamSize, 0, nullptr, 0, treelet);
}
AccessResult MemoryInitiator::stream_assign() { return access(AccessClass::kStreamAssign, 0, nullptr, 0); }
AccessResult MemoryInitiator::stream_capacity() {
  return access(AccessClass::kStreamCapacity, 0, nullptr, 0);
}

AccessResult MemoryInitiator::stream_push_blocking(uint32_t treelet, const void* ray48, Cycle retry_cycles,
                                                   uint64_t* retries) {
  for (;;) {
    AccessResult r = stream_push(treelet, ray48);
    if (!r.ok() || r.stream_status != StreamStatus::kFull) return r;
    if (retries != nullptr) ++*retries;
    advance(retry_cycles == 0 ? 1 : retry_cycles);
    // A stalled TP must let the others run, or nobody could make room.
    sync();
  }
}

}  // namespace strata::transport
