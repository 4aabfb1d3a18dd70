// Progress of a long chip simulation on the terminal, and stopping it. A SystemC process wakes
// every kStopCheckCycles simulated cycles (never per cycle) and stops the simulation when SIGINT
// or SIGTERM arrived or the cycle limit is reached, so the caller can write what it has; every
// `interval` cycles it also prints pixels done, simulated cycles, simulation speed and an ETA
// on stderr. It returns when every TM has finished.
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

  // How often the stop conditions are checked: about 0.5 s of a 128-TM chip in precise mode,
  // the slowest, so Ctrl-C is honoured within a second whatever --progress-cycles says.
  static constexpr uint64_t kStopCheckCycles = 8192;

  bool interrupted() const { return signal_ != 0; }
  int signal() const { return signal_; }  // SIGINT or SIGTERM, 0 if none arrived
  bool cycle_limit_reached() const { return limit_reached_; }
  // Stop once `cycles` have been simulated (0: no limit).
  void set_cycle_limit(uint64_t cycles) { cycle_limit_ = cycles; }
  // Installs the SIGINT and SIGTERM handlers for the lifetime of the monitor (restored afterwards).
  void arm();
  void disarm();

 private:
  void run();
  void print_line(bool final);

  const chip::Chip& chip_;
  uint64_t interval_;
  bool show_;
  bool terminal_;
  int signal_ = 0;
  uint64_t cycle_limit_ = 0;
  bool limit_reached_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace strata::sim
