// Harness for driving one memory module through its TLM sockets with scripted traffic:
//   Script          runs a lambda as an SC_THREAD (the traffic), so sockets are bound first;
//   RawInitiator    sends one request for an exact absolute cycle and reports completion;
//   LatencySink     a level below that answers every request after a fixed latency and
//                   records what it was asked.
// SystemC elaborates once per process: ctest runs every test in its own process; a direct run
// of the whole binary skips the SystemC tests after the first (REQUIRE_FRESH_SYSTEMC).
#pragma once

#include "tlm/clock.h"
#include "tlm/memory_extension.h"
#include "tlm/payload_pool.h"

#include <gtest/gtest.h>
#include <systemc>
#include <tlm>
#include <tlm_utils/multi_passthrough_target_socket.h>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace strata::memory::test {

using transport::AccessClass;
using transport::Cycle;
using transport::MemoryExtension;
using transport::ServedBy;
using transport::StreamStatus;

#define REQUIRE_FRESH_SYSTEMC()                                                             \
  do {                                                                                      \
    if (sc_core::sc_get_status() != sc_core::SC_ELABORATION)                                \
      GTEST_SKIP() << "SystemC already elaborated in this process; run through ctest";      \
  } while (0)

struct Script : sc_core::sc_module {
  std::function<void()> body;
  SC_HAS_PROCESS(Script);
  Script(sc_core::sc_module_name name, std::function<void()> b) : sc_core::sc_module(name), body(std::move(b)) {
    SC_THREAD(run);
  }
  void run() { body(); }
};

struct Sent {
  tlm::tlm_response_status response = tlm::TLM_INCOMPLETE_RESPONSE;
  Cycle done = 0;
  ServedBy served_by = ServedBy::kNone;
  StreamStatus stream_status = StreamStatus::kOk;
  uint32_t result = 0;
};

struct RawInitiator : sc_core::sc_module {
  tlm_utils::simple_initiator_socket<RawInitiator> socket{"socket"};
  transport::Clock clock;
  transport::PayloadPool pool;
  uint32_t initiator_id = 0, tm_id = 0;

  explicit RawInitiator(sc_core::sc_module_name name, uint32_t id = 0, uint32_t tm = 0)
      : sc_core::sc_module(name), initiator_id(id), tm_id(tm) {}

  // One request for absolute cycle `at` (>= global time); returns when and how it completed.
  Sent send(AccessClass access, uint64_t addr, void* data, uint32_t bytes, Cycle at,
            uint32_t treelet = transport::kNoTreelet, bool timing_only = false) {
    transport::PooledPayload gp(pool);
    transport::prepare_access(gp, access, addr, data, bytes, initiator_id, tm_id, treelet, timing_only);
    const MemoryExtension& ext = gp.ext();
    sc_core::sc_time delay = clock.delay_until(at);
    socket->b_transport(*gp, delay);
    return Sent{gp->get_response_status(), clock.request_cycle(delay), ext.served_by, ext.stream_status, ext.result};
  }
  Sent load(uint64_t addr, Cycle at, uint32_t bytes = 4) {
    uint8_t buf[64] = {};
    return send(AccessClass::kDataLoad, addr, buf, bytes, at);
  }
  Sent store(uint64_t addr, Cycle at, uint32_t bytes = 4) {
    uint8_t buf[64] = {};
    return send(AccessClass::kDataStore, addr, buf, bytes, at);
  }
  Sent fetch(uint64_t addr, Cycle at) {
    uint8_t buf[4] = {};
    return send(AccessClass::kInstructionFetch, addr, buf, 4, at);
  }
};

struct SinkRecord {
  tlm::tlm_command command;
  uint64_t address;
  uint32_t bytes;
  Cycle cycle;  // absolute request cycle
  bool timing_only;
  AccessClass access;
};

struct LatencySink : sc_core::sc_module {
  tlm_utils::simple_target_socket<LatencySink> socket{"socket"};
  transport::Clock clock;
  Cycle latency;
  std::vector<SinkRecord> seen;

  LatencySink(sc_core::sc_module_name name, Cycle lat) : sc_core::sc_module(name), latency(lat) {
    socket.register_b_transport(this, &LatencySink::b_transport);
  }
  void b_transport(tlm::tlm_generic_payload& gp, sc_core::sc_time& delay) {
    MemoryExtension* ext = gp.get_extension<MemoryExtension>();
    const Cycle t = clock.request_cycle(delay);
    seen.push_back(SinkRecord{gp.get_command(), gp.get_address(), gp.get_data_length(), t,
                              ext != nullptr && ext->timing_only,
                              ext != nullptr ? ext->access : AccessClass::kDataLoad});
    if (ext != nullptr) ext->served_by = ServedBy::kSink;
    gp.set_response_status(tlm::TLM_OK_RESPONSE);
    delay = clock.delay_until(t + latency);
  }
};

// Joins several initiators (the TPs of a TM) onto one target socket, as the TM's port to its
// L1 does; it adds no time.
struct Fanin : sc_core::sc_module {
  tlm_utils::multi_passthrough_target_socket<Fanin> in{"in"};
  tlm_utils::simple_initiator_socket<Fanin> out{"out"};
  explicit Fanin(sc_core::sc_module_name name) : sc_core::sc_module(name) {
    in.register_b_transport(this, &Fanin::b_transport);
  }
  void b_transport(int, tlm::tlm_generic_payload& gp, sc_core::sc_time& delay) { out->b_transport(gp, delay); }
};

}  // namespace strata::memory::test
