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

}  // namespace strata::transport
