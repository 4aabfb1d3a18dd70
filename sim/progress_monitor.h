// Progress of a long chip simulation on the terminal, and Ctrl-C. A SystemC process wakes every
// `interval` simulated cycles (never per cycle), prints pixels done, simulated cycles,
// simulation speed and an ETA on stderr, and stops the simulation when SIGINT arrived, so the
// caller can write what it has. It returns when every TM has finished.
#pragma once

#include <chrono>
#include <cstdint>

#include <systemc>

#include "model/chip/chip.h"

namespace strata::sim {

class ProgressMonitor : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(ProgressMonitor);
  // `show`: print progress lines; `terminal`: rewrite one line (else one line per report).
  ProgressMonitor(sc_core::sc_module_name name, const chip::Chip& chip, uint64_t interval_cycles, bool show,
                  bool terminal = true);

  bool interrupted() const { return interrupted_; }
  // Installs the SIGINT handler for the lifetime of the monitor (restored afterwards).
  void arm();
  void disarm();

 private:
  void run();
  void print(bool final);

  const chip::Chip& chip_;
  uint64_t interval_;
  bool show_;
  bool terminal_;
  bool interrupted_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace strata::sim
