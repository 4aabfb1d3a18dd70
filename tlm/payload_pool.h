// A TLM memory manager that recycles payloads: after warm-up, acquiring one never allocates.
// Each payload keeps one MemoryExtension attached for its whole life.
#pragma once

#include "tlm/memory_extension.h"

#include <tlm>

#include <cstddef>
#include <memory>
#include <vector>

namespace strata::transport {

class PayloadPool : public tlm::tlm_mm_interface {
 public:
  explicit PayloadPool(std::size_t initial = 4);
  ~PayloadPool() override;
  PayloadPool(const PayloadPool&) = delete;
  PayloadPool& operator=(const PayloadPool&) = delete;

  // A payload with reference count 1, default fields and a cleared extension; give it back
  // with release() (or let PooledPayload do it).
  tlm::tlm_generic_payload* acquire();
  void free(tlm::tlm_generic_payload* gp) override;

  std::size_t allocated() const { return owned_.size(); }
  std::size_t available() const { return free_.size(); }

 private:
  void grow(std::size_t count);

  std::vector<std::unique_ptr<tlm::tlm_generic_payload>> owned_;
  std::vector<tlm::tlm_generic_payload*> free_;
};

// Scoped ownership of one pooled payload.
class PooledPayload {
 public:
  explicit PooledPayload(PayloadPool& pool) : gp_(pool.acquire()) {}
  ~PooledPayload() { gp_->release(); }
  PooledPayload(const PooledPayload&) = delete;
  PooledPayload& operator=(const PooledPayload&) = delete;

  tlm::tlm_generic_payload& operator*() const { return *gp_; }
  tlm::tlm_generic_payload* operator->() const { return gp_; }
  MemoryExtension& ext() const { return *gp_->get_extension<MemoryExtension>(); }

 private:
  tlm::tlm_generic_payload* gp_;
};

// Sets a payload up for one memory access of the given class: every field a target reads
// (command, address, data, byte enables, DMI hint, response) and the extension's request
// fields (its response fields are cleared). Complete, so a payload can be reused as is.
inline void prepare_access(tlm::tlm_generic_payload& gp, MemoryExtension& ext, AccessClass access, uint64_t addr,
                           void* data, uint32_t bytes, uint32_t initiator_id, uint32_t tm_id,
                           uint32_t treelet = kNoTreelet, bool timing_only = false, bool functional = false,
                           bool uncounted = false) {
  const bool write = access == AccessClass::kDataStore || access == AccessClass::kStreamPush ||
                     access == AccessClass::kStreamPathWrite;
  gp.set_command(write ? tlm::TLM_WRITE_COMMAND : tlm::TLM_READ_COMMAND);
  gp.set_address(addr);
  gp.set_data_ptr(static_cast<unsigned char*>(data));
  gp.set_data_length(bytes);
  gp.set_streaming_width(bytes);
  gp.set_byte_enable_ptr(nullptr);
  gp.set_byte_enable_length(0);
  gp.set_dmi_allowed(false);
  gp.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
  ext.initiator_id = initiator_id;
  ext.tm_id = tm_id;
  ext.access = access;
  ext.treelet = treelet;
  ext.timing_only = timing_only;
  ext.functional = functional;
  ext.uncounted = uncounted;
  ext.warm = false;
  ext.data = default_data_class(access);
  ext.reset_response();
}

// The same for a pooled payload.
inline void prepare_access(PooledPayload& gp, AccessClass access, uint64_t addr, void* data, uint32_t bytes,
                           uint32_t initiator_id, uint32_t tm_id, uint32_t treelet = kNoTreelet,
                           bool timing_only = false, bool functional = false, bool uncounted = false) {
  prepare_access(*gp, gp.ext(), access, addr, data, bytes, initiator_id, tm_id, treelet, timing_only, functional,
                 uncounted);
}

}  // namespace strata::transport
