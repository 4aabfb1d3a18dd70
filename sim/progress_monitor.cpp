#include "sim/progress_monitor.h"

#include <algorithm>
#include <csignal>
#include <cstdio>

namespace strata::sim {
namespace {

// The one piece of global state: a signal handler can only talk through a flag like this.
volatile std::sig_atomic_t g_signal = 0;
void on_signal(int signo) { g_signal = signo; }
void (*g_previous_int)(int) = SIG_DFL;
void (*g_previous_term)(int) = SIG_DFL;

}  // namespace

ProgressMonitor::ProgressMonitor(sc_core::sc_module_name name, const chip::Chip& chip, uint64_t interval,
                                 bool show, bool terminal)
    : sc_core::sc_module(name), chip_(chip), interval_(interval > 0 ? interval : 1), show_(show), terminal_(terminal) {
  SC_THREAD(run);
}

void ProgressMonitor::arm() {
  g_signal = 0;
  g_previous_int = std::signal(SIGINT, on_signal);
  g_previous_term = std::signal(SIGTERM, on_signal);
  start_ = std::chrono::steady_clock::now();
  print_line(false);  // the first line says the simulation has started (and Ctrl-C now stops it cleanly)
}

void ProgressMonitor::disarm() {
  std::signal(SIGINT, g_previous_int);
  std::signal(SIGTERM, g_previous_term);
}

void ProgressMonitor::print_line(bool final) {
  if (!show_) return;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const uint32_t done = chip_.pixels_done(), total = chip_.pixel_count();
  const double fraction = total ? double(done) / total : 0.0;
  const double eta = fraction > 0 ? wall / fraction - wall : 0.0;
  const double mcycles = sc_core::sc_time_stamp().to_seconds() * chip_.config().clock_ghz * 1e3;
  std::fprintf(stderr,
               "%sprogress: %u/%u pixels (%.1f%%), %.3f M cycles simulated, %.2f M simulated instructions/s, "
               "%.0f s elapsed, ETA %.0f s   %s",
               terminal_ ? "\r" : "", done, total, 100.0 * fraction, mcycles,
               wall > 0 ? double(chip_.instructions()) / wall * 1e-6 : 0.0, wall, eta,
               final || !terminal_ ? "\n" : "");
  std::fflush(stderr);
}

void ProgressMonitor::run() {
  const transport::Clock clock = chip_.config().clock();
  const uint64_t check = std::min(interval_, kStopCheckCycles);
  uint64_t cycles = 0, next_print = interval_;
  for (;;) {
    // Never past the cycle limit, so a limited run stops at it exactly.
    uint64_t step = check;
    if (cycle_limit_ > 0) step = std::min(step, cycle_limit_ - cycles);
    sc_core::wait(clock.duration(step));
    cycles += step;
    if (chip_.finished()) {
      print_line(true);
      return;
    }
    if (cycles >= next_print) {
      print_line(false);
      next_print += interval_;
    }
    if (g_signal != 0 || (cycle_limit_ > 0 && cycles >= cycle_limit_)) {
      signal_ = g_signal;
      limit_reached_ = signal_ == 0;
      if (show_)
        std::fprintf(stderr, "\n%s: stopping the simulation and writing what exists\n",
                     signal_ ? "interrupted" : "cycle limit reached");
      sc_core::sc_stop();
      return;
    }
  }
}

}  // namespace strata::sim
