// How a cache talks to the level below: one timing-only request (a line fill, a write-through
// or a write-back), made at an absolute cycle, answered with the cycle it completes. The data
// already moved through the backing store, so the payload points at a scratch buffer that the
// level below leaves alone. Pooled payloads: nothing is allocated per request.
#pragma once

#include "tlm/clock.h"
#include "tlm/memory_extension.h"
#include "tlm/payload_pool.h"

#include <tlm>

#include <cstdint>
#include <vector>

namespace strata::memory {

struct DownstreamResult {
  bool ok = false;
  transport::Cycle done = 0;
  transport::ServedBy served_by = transport::ServedBy::kNone;
};

class DownstreamPort {
 public:
  DownstreamPort(tlm::tlm_initiator_socket<>& socket, uint32_t max_bytes)
      : socket_(socket), scratch_(max_bytes, 0) {}

  // `origin` (may be null) names the thread and TM the request is made for; `data` is what
  // the line holds.
  DownstreamResult send(tlm::tlm_command cmd, uint64_t addr, uint32_t bytes, transport::Cycle at,
                        const transport::MemoryExtension* origin, transport::DataClass data);

  // Functional warming: the same request as a tag update only (no time, no counts).
  void warm(tlm::tlm_command cmd, uint64_t addr, const transport::MemoryExtension* origin, transport::DataClass data);

  void set_clock(const transport::Clock& clock) { clock_ = clock; }

  uint64_t requests() const { return requests_; }
  uint64_t bytes() const { return bytes_; }

 private:
  // What send() and warm() set alike: command, address, the scratch buffer, the origin's ids,
  // the access class and data class, timing only.
  void prepare(transport::PooledPayload& p, tlm::tlm_command cmd, uint64_t addr, uint32_t bytes,
               const transport::MemoryExtension* origin, transport::DataClass data);

  tlm::tlm_initiator_socket<>& socket_;
  transport::Clock clock_;
  transport::PayloadPool pool_{2};
  std::vector<uint8_t> scratch_;
  uint64_t requests_ = 0;
  uint64_t bytes_ = 0;
};

}  // namespace strata::memory
