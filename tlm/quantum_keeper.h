// Temporal decoupling for one initiator thread: it runs ahead of global time by up to a
// quantum, keeping its own local offset, and waits only when the offset reaches the quantum.
// Unlike tlm_utils::tlm_quantumkeeper, the quantum is per keeper rather than the process-wide
// tlm_global_quantum singleton, so two systems in one simulation can use different quanta.
#pragma once

#include <systemc>

namespace strata::transport {

class QuantumKeeper {
 public:
  explicit QuantumKeeper(const sc_core::sc_time& quantum) : quantum_(quantum) {}

  const sc_core::sc_time& local_time() const { return local_; }  // offset ahead of global time
  sc_core::sc_time current_time() const { return sc_core::sc_time_stamp() + local_; }
  void set(const sc_core::sc_time& local) { local_ = local; }
  void inc(const sc_core::sc_time& t) { local_ += t; }
  bool need_sync() const { return local_ >= quantum_; }
  // Lets global time catch up with this thread (other threads run meanwhile).
  void sync() {
    if (local_ != sc_core::SC_ZERO_TIME) {
      sc_core::wait(local_);
      local_ = sc_core::SC_ZERO_TIME;
    }
  }
  const sc_core::sc_time& quantum() const { return quantum_; }

 private:
  sc_core::sc_time quantum_;
  sc_core::sc_time local_ = sc_core::SC_ZERO_TIME;
};

}  // namespace strata::transport
