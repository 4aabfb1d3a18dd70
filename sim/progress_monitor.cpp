#include "sim/progress_monitor.h"

#include <csignal>
#include <cstdio>

namespace strata::sim {
namespace {

// The one piece of global state: a signal handler can only talk through a flag like this.
volatile std::sig_atomic_t g_sigint = 0;
void on_sigint(int) { g_sigint = 1; }
void (*g_previous_handler)(int) = SIG_DFL;

}  // namespace

ProgressMonitor::ProgressMonitor(sc_core::sc_module_name name, const chip::Chip& chip, uint64_t interval,
                                 bool show, bool terminal)
    : sc_core::sc_module(name), chip_(chip), interval_(interval > 0 ? interval : 1), show_(show), terminal_(terminal) {
  SC_THREAD(run);
}

void ProgressMonitor::arm() {
  g_sigint = 0;
  g_previous_handler = std::signal(SIGINT, on_sigint);
  start_ = std::chrono::steady_clock::now();
}

void ProgressMonitor::disarm() { std::signal(SIGINT, g_previous_handler); }

void ProgressMonitor::print(bool final) {
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
  const sc_core::sc_time step = sc_core::sc_time(1.0 / chip_.config().clock_ghz, sc_core::SC_NS) * double(interval_);
  for (;;) {
    sc_core::wait(step);
    if (chip_.finished()) {
      print(true);
      return;
    }
    print(false);
    if (g_sigint) {
      interrupted_ = true;
      if (show_) std::fprintf(stderr, "\ninterrupted: stopping the simulation and writing what exists\n");
      sc_core::sc_stop();
      return;
    }
  }
}

}  // namespace strata::sim
