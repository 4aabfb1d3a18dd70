// A stand-alone initiator of memory accesses in either timing mode, for the memory benchmark
// (model/memory/bench) and the memory system's timing tests. A thread calls
// load/store/fetch/stream_* from its SC_THREAD; each call is blocking, as an in-order TP waits
// for its access, and returns when and where the access completed. Its time and its accesses go
// through a MemoryPort (tlm/memory_port.h), the class the chip's TMs use, so the tests and the
// benchmark exercise the chip's timing rules:
//
//   kLooselyTimed: the thread runs ahead of global time; a request carries its lead as annotated
//                  delay and the answer moves the thread to the completion. The thread waits
//                  only when its lead reaches the quantum.
//   kPrecise:      global time catches up with the thread before every access, so requests
//                  reach the targets in time order. This is the accuracy reference.
//   kSampled:      the chip's TMs alternate short loosely-timed windows with functional
//                  fast-forward (docs/sampled-timing.md); an initiator here treats it as
//                  loosely timed.
// Targets are the same in every mode: they compute completion from request time + calendars.
// The thread may also wait on its own (an event): its lead over global time stays what it was.
#pragma once

#include "tlm/clock.h"
#include "tlm/memory_extension.h"
#include "tlm/memory_port.h"
#include "tlm/timing_mode.h"

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include <cstdint>

namespace strata::transport {

struct InitiatorConfig {
  TimingMode mode = TimingMode::kLooselyTimed;
  Cycle quantum_cycles = 1000;  // LT only
  uint32_t initiator_id = 0;    // global thread id
  uint32_t tm_id = 0;
};

struct AccessResult {
  tlm::tlm_response_status response = tlm::TLM_INCOMPLETE_RESPONSE;
  Cycle issued = 0;     // absolute cycle the request was made for
  Cycle completed = 0;  // absolute cycle it completed
  StreamStatus stream_status = StreamStatus::kOk;
  uint32_t result = 0;
  ServedBy served_by = ServedBy::kNone;
  Cycle latency() const { return completed - issued; }
  bool ok() const { return response == tlm::TLM_OK_RESPONSE; }
};

class MemoryInitiator : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<MemoryInitiator> socket{"socket"};

  MemoryInitiator(sc_core::sc_module_name name, const InitiatorConfig& config);

  AccessResult load(uint64_t addr, void* data, uint32_t bytes);
  AccessResult store(uint64_t addr, const void* data, uint32_t bytes);
  AccessResult fetch(uint64_t addr, void* data, uint32_t bytes);
  AccessResult stream_push(uint32_t treelet, const void* ray48);
  AccessResult stream_pop(uint32_t treelet, void* ray48);  // kNoTreelet: the TM's buffer
  AccessResult stream_size(uint32_t treelet);
  AccessResult stream_assign();
  AccessResult stream_capacity();
  // A push that the stream memory refuses because it is full is retried after `retry_cycles`
  // until it is stored: the TP stalls, the ray is never dropped.
  AccessResult stream_push_blocking(uint32_t treelet, const void* ray48, Cycle retry_cycles,
                                    uint64_t* retries = nullptr);

  AccessResult access(AccessClass access, uint64_t addr, void* data, uint32_t bytes,
                      uint32_t treelet = kNoTreelet);

  // Work between accesses (compute cycles): advances this thread's local time.
  void advance(Cycle cycles);
  // Waits until global time reaches this thread's local time.
  void sync();
  Cycle local_cycle() const { return Clock().now() + lead_; }
  const InitiatorConfig& config() const { return config_; }

 private:
  // Global time as it stands (the thread may have waited outside the port) plus the lead.
  Cycle now();
  // The mode's rule: LT waits once the lead reaches the quantum.
  void keep_within_quantum();

  InitiatorConfig config_;
  MemoryPort port_;
  Cycle lead_ = 0;  // this thread's time ahead of global time
};

}  // namespace strata::transport
