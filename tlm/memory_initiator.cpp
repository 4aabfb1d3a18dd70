#include "tlm/memory_initiator.h"

namespace strata::transport {

MemoryInitiator::MemoryInitiator(sc_core::sc_module_name name, const InitiatorConfig& config)
    : sc_core::sc_module(name),
      config_(config),
      port_(Clock(), config.mode, config.quantum_cycles, config.tm_id,
            [](Cycle target) { sc_core::wait(Clock().delay_until(target)); }) {}

Cycle MemoryInitiator::now() {
  port_.observe();
  return port_.global_cycle() + lead_;
}

void MemoryInitiator::sync() {
  const Cycle t = now();
  port_.sync_to(t, MemoryPort::kNoLimit, true);
  lead_ = t - port_.global_cycle();
}

void MemoryInitiator::keep_within_quantum() {
  if (config_.mode != TimingMode::kPrecise && lead_ >= port_.quantum_cycles()) sync();
}

AccessResult MemoryInitiator::access(AccessClass access, uint64_t addr, void* data, uint32_t bytes,
                                     uint32_t treelet) {
  if (config_.mode == TimingMode::kPrecise) sync();
  PortAccess a;
  a.access = access;
  a.addr = addr;
  a.data = data;
  a.bytes = bytes;
  a.at = now();
  a.thread = config_.initiator_id;
  a.treelet = treelet;
  AccessResult r;
  r.issued = a.at;
  const bool ok = port_.access(socket, a, &r.completed);
  r.response = port_.response();
  const MemoryExtension& ext = port_.answer();
  r.stream_status = ext.stream_status;
  r.result = ext.result;
  r.served_by = ext.served_by;
  // Blocking access: this thread's time moves to the completion.
  if (ok) lead_ = r.completed - port_.global_cycle();
  keep_within_quantum();
  return r;
}

void MemoryInitiator::advance(Cycle cycles) {
  lead_ += cycles;
  keep_within_quantum();
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
