// The memory side of one initiator thread: its time against global time, and its blocking
// accesses to the memory modules, under the chip's timing rules. The chip's TMs use it
// (model/tm/thread_multiprocessor.cpp), and so does MemoryInitiator, which drives the memory
// tests and the memory benchmark: both exercise this one set of rules.
//
// Time. The thread runs ahead of global time, and asks global time to catch up with a cycle t
// it is about to act at (sync_to):
//   kLooselyTimed (and sampled timing's windows): only once t leads global time by a quantum
//                 or more, or when the caller needs global time at t exactly (`exact`: an op
//                 that must reach shared state in time order);
//   kPrecise:     whenever t is ahead, so every request reaches its target in time order.
// Never past `others` (a TM's other TPs, whose requests every calendar would move to global
// time if it overtook them). How the thread waits is its owner's (`WaitUntil`): the chip's TMs
// take turns (tlm/turn_order.h), a stand-alone initiator waits on the kernel.
//
// Accesses. A request carries its cycle as annotated delay against global time as of the last
// wait, and the target answers with the completion in the same delay. One payload and
// extension serve every access (b_transport blocks, and no target keeps a payload), set up in
// full each time: no pool round trip and no extension lookup per access.
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>

#include <systemc>
#include <tlm>

#include "tlm/clock.h"
#include "tlm/data_class.h"
#include "tlm/memory_extension.h"
#include "tlm/payload_pool.h"
#include "tlm/timing_mode.h"

namespace strata::transport {

// One access: what, where, when, and for whom.
struct PortAccess {
  AccessClass access = AccessClass::kDataLoad;
  uint64_t addr = 0;
  void* data = nullptr;
  uint32_t bytes = 0;
  Cycle at = 0;                   // the cycle the request is made in
  uint32_t thread = 0;            // the issuing thread's global id
  uint32_t treelet = kNoTreelet;  // stream ops: the treelet named
  bool timing_only = false;       // the data moved functionally already: time it only
  bool functional = false;        // sampled: a fast-forward batch's op (nothing is booked)
  bool uncounted = false;         // sampled: outside the measured parts (no statistics)
};

class MemoryPort {
 public:
  using WaitUntil = std::function<void(Cycle)>;  // returns with global time at the cycle or later
  static constexpr Cycle kNoLimit = ~Cycle{0};

  MemoryPort(const Clock& clock, TimingMode mode, Cycle quantum_cycles, uint32_t tm_id, WaitUntil wait_until)
      : clock_(clock),
        precise_(mode == TimingMode::kPrecise),
        quantum_(quantum_cycles == 0 ? 1 : quantum_cycles),
        tm_id_(tm_id),
        wait_until_(std::move(wait_until)),
        ext_(new MemoryExtension) {
    gp_.set_extension(ext_);  // owned by the payload from here
  }
  MemoryPort(const MemoryPort&) = delete;
  MemoryPort& operator=(const MemoryPort&) = delete;

  // Reads global time: after the owner's thread has waited outside the port (its first
  // registration, an event).
  void observe() {
    stamp_ = sc_core::sc_time_stamp().value();
    global_ = clock_.now_at(stamp_);
  }
  Cycle global_cycle() const { return global_; }
  const Clock& clock() const { return clock_; }
  bool precise() const { return precise_; }
  Cycle quantum_cycles() const { return quantum_; }

  // Lets global time catch up with `t` where the mode's rule (above) calls for it, never past
  // `others`. True when it waited (global time moved).
  bool sync_to(Cycle t, Cycle others = kNoLimit, bool exact = false) {
    if (t <= global_ || !(precise_ || exact || t - global_ >= quantum_)) return false;
    const Cycle target = t < others ? t : others;
    if (target <= global_) return false;
    wait_until_(target);
    observe();
    return true;
  }

  // Classifies data loads and stores by what their address holds (may be null: the access
  // class's default).
  void set_data_classes(const DataClassMap* map) { data_classes_ = map; }

  // One blocking access through `socket` (an initiator socket, or anything whose -> gives the
  // target's b_transport). Returns false if the target refused it (refusal() says why); else
  // `completed` is the cycle it completed in and answer() the target's reply.
  template <class Socket>
  bool access(Socket& socket, const PortAccess& a, Cycle* completed) {
    prepare_access(gp_, *ext_, a.access, a.addr, a.data, a.bytes, a.thread, tm_id_, a.treelet, a.timing_only,
                   a.functional, a.uncounted);
    if (data_classes_ != nullptr && (a.access == AccessClass::kDataLoad || a.access == AccessClass::kDataStore))
      ext_->data = data_classes_->of(a.addr);
    sc_core::sc_time delay = clock_.delay_until_at(stamp_, a.at);
    socket->b_transport(gp_, delay);
    if (gp_.get_response_status() != tlm::TLM_OK_RESPONSE) {
      *completed = a.at;
      return false;
    }
    *completed = clock_.request_cycle_at(stamp_, delay);
    return true;
  }
  const MemoryExtension& answer() const { return *ext_; }
  tlm::tlm_response_status response() const { return gp_.get_response_status(); }
  // Why the last access was refused: its address and the target's response.
  std::string refusal() const {
    char addr[24];
    std::snprintf(addr, sizeof addr, "0x%08llx", static_cast<unsigned long long>(gp_.get_address()));
    return std::string("memory access to ") + addr + " was refused: " + gp_.get_response_string();
  }

 private:
  Clock clock_;
  bool precise_;
  Cycle quantum_;
  uint32_t tm_id_;
  WaitUntil wait_until_;
  const DataClassMap* data_classes_ = nullptr;
  Cycle global_ = 0;    // global time, as of the last wait
  uint64_t stamp_ = 0;  // ... in kernel time units (it stands still between waits)
  tlm::tlm_generic_payload gp_;
  MemoryExtension* ext_;
};

}  // namespace strata::transport
