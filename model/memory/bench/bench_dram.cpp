// The banked DRAM's bandwidth and loaded latency through its own TLM socket (issue 36, part 4).
//
//   bench_dram [requests per point, default 200000] [CSV file]
//
// One driver stands for the L2's misses: it offers 64 B reads at a fixed rate (open loop),
// holding at most kWindow requests in flight, as a controller's queue bounds them. Each
// request's time is annotated on the TLM call (loosely timed, as the chip's L2 sends them), and
// global time follows the requests so that the channel and bank calendars retire behind it.
// Printed per pattern and offered load: achieved bandwidth (share of the 256 B/cycle peak),
// mean read latency (request to last data, in cycles of the 1 GHz chip clock) and the row
// outcomes. For random reads the expected saturated efficiency is derived from the preset's
// tRC, tRRD, tFAW, tRFC and tREFI and printed beside the model's (they must agree within 5%).
// Deterministic: fixed seeds, no wall-clock time in the figures.
#include "model/memory/dram.h"
#include "tlm/memory_extension.h"

#include <systemc>
#include <tlm_utils/simple_initiator_socket.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace strata::memory;
using strata::transport::Cycle;

constexpr uint32_t kLine = 64;
constexpr uint32_t kWindow = 512;  // requests in flight at most (the controller's queue)
constexpr Cycle kLead = 256;       // how far a request may be ahead of global time

enum class Pattern { kSequential, kRandom };
const char* name(Pattern p) { return p == Pattern::kSequential ? "sequential" : "random"; }

struct Point {
  Pattern pattern;
  double offered;  // bytes per cycle offered (above the peak: as fast as the window allows)
  uint64_t requests;
  double achieved = 0, latency = 0;
  uint64_t hits = 0, misses = 0, conflicts = 0, overflows = 0;
};

struct Driver : sc_core::sc_module {
  tlm_utils::simple_initiator_socket<Driver> socket{"socket"};
  std::vector<Point>& points;
  std::vector<Dram*>& drams;
  SC_HAS_PROCESS(Driver);
  Driver(sc_core::sc_module_name n, std::vector<Point>& p, std::vector<Dram*>& d)
      : sc_core::sc_module(n), points(p), drams(d) {
    SC_THREAD(run);
  }

  // Each point runs on its own DRAM (bound in turn by a router below), from a clean state.
  void run() {
    for (size_t i = 0; i < points.size(); ++i) {
      target = i;
      measure(points[i], *drams[i]);
    }
  }

  void measure(Point& p, const Dram& dram) {
    std::mt19937_64 rng(1);
    const uint64_t lines = (1ull << 30) / kLine;  // 1 GB
    const Cycle start = now();
    std::deque<Cycle> in_flight;  // completion cycles, in issue order
    double next = double(start);
    Cycle first = ~Cycle{0}, last = 0;
    double latency = 0;
    uint8_t data[kLine];
    tlm::tlm_generic_payload gp;
    strata::transport::MemoryExtension ext;
    ext.timing_only = true;
    gp.set_extension(&ext);
    for (uint64_t k = 0; k < p.requests; ++k) {
      Cycle t = static_cast<Cycle>(next);
      next += double(kLine) / p.offered;
      if (in_flight.size() >= kWindow) {  // the queue is full: wait for its oldest
        t = std::max(t, in_flight.front());
        in_flight.pop_front();
      }
      t = std::max(t, now());  // never before global time (a request cannot go back in time)
      if (t > now() + kLead) wait(sc_core::sc_time(double(t - kLead), sc_core::SC_NS) - sc_core::sc_time_stamp());
      const uint64_t line = p.pattern == Pattern::kSequential ? k % lines : rng() % lines;
      gp.set_command(tlm::TLM_READ_COMMAND);
      gp.set_address(line * kLine);
      gp.set_data_ptr(data);
      gp.set_data_length(kLine);
      gp.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
      sc_core::sc_time delay(double(t - now()), sc_core::SC_NS);
      socket->b_transport(gp, delay);
      const Cycle end = now() + static_cast<Cycle>(delay.to_seconds() * 1e9 + 0.5);
      in_flight.push_back(end);
      first = std::min(first, t);
      last = std::max(last, end);
      latency += double(end - t);
    }
    gp.clear_extension(&ext);
    p.achieved = double(p.requests * kLine) / double(last - first);
    p.latency = latency / double(p.requests);
    for (uint32_t c = 0; c < dram.config().channels; ++c) {
      const BankedDram::ChannelCounters& k = dram.banked()->channel(c);
      p.hits += k.row_hits;
      p.misses += k.row_misses;
      p.conflicts += k.row_conflicts;
    }
    p.overflows = dram.overflow_bookings();
    wait(sc_core::sc_time(double(last + 1000), sc_core::SC_NS) - sc_core::sc_time_stamp());
  }

  Cycle now() const { return static_cast<Cycle>(sc_core::sc_time_stamp().to_seconds() * 1e9 + 0.5); }
  size_t target = 0;
};

// Sends the driver's requests to the DRAM of the point being measured.
struct Router : sc_core::sc_module {
  tlm_utils::simple_target_socket<Router> in{"in"};
  std::vector<std::unique_ptr<tlm_utils::simple_initiator_socket<Router>>> out;
  const Driver* driver = nullptr;
  Router(sc_core::sc_module_name n, size_t ways) : sc_core::sc_module(n) {
    in.register_b_transport(this, &Router::b_transport);
    for (size_t i = 0; i < ways; ++i)
      out.push_back(std::make_unique<tlm_utils::simple_initiator_socket<Router>>(("out" + std::to_string(i)).c_str()));
  }
  void b_transport(tlm::tlm_generic_payload& gp, sc_core::sc_time& d) { (*out[driver->target])->b_transport(gp, d); }
};

// Random reads are bounded by activates: each is a row conflict (PRE, ACT, two RD). Per
// channel at most one ACT per tRRD (any bank group: tRRD_S = tRRD_L here), four per tFAW, one
// per bank per tRC, and the data bus moves a line in kLine / channel bytes per cycle; refresh
// takes tRFC of every tREFI.
double expected_random_efficiency(const DramConfig& c) {
  const DramTiming t = DramTiming::at(c.banked, 1.0, c.channel_bytes_per_cycle());
  const double acts_per_cycle =
      std::min({1.0 / double(std::max(t.rrd_s, t.rrd_l)), 4.0 / double(t.faw), double(c.banked.banks()) / double(t.rc)});
  const double lines_per_cycle = std::min(acts_per_cycle, double(c.channel_bytes_per_cycle()) / kLine);
  const double refresh = 1.0 - double(t.rfc) / double(t.refi);
  return lines_per_cycle * kLine / double(c.channel_bytes_per_cycle()) * refresh;
}

}  // namespace

int sc_main(int argc, char* argv[]) {
  const uint64_t requests = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 200000;
  // Finer steps near the random reads' knee (about 27% of the peak).
  if (requests == 0) {
    std::fprintf(stderr, "bench_dram: the number of requests must be a positive integer (got '%s')\n", argv[1]);
    return 1;
  }
  sc_core::sc_report_handler::set_actions(sc_core::SC_INFO, sc_core::SC_DO_NOTHING);
  DramConfig config;
  config.model = DramModel::kBanked;
  config.validate();

  std::vector<Point> points;
  for (const Pattern p : {Pattern::kSequential, Pattern::kRandom}) {
    for (const double load : {0.02, 0.05, 0.1, 0.15, 0.2, 0.22, 0.24, 0.26, 0.28, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 2.0})
      points.push_back(Point{p, load * config.bytes_per_cycle, requests});
  }
  SparseMemory backing;
  std::vector<std::unique_ptr<Dram>> owned;
  std::vector<Dram*> drams;
  for (size_t i = 0; i < points.size(); ++i) {
    owned.push_back(std::make_unique<Dram>(("dram" + std::to_string(i)).c_str(), config, backing));
    drams.push_back(owned.back().get());
  }
  Driver driver("driver", points, drams);
  Router router("router", points.size());
  router.driver = &driver;
  driver.socket.bind(router.in);
  for (size_t i = 0; i < points.size(); ++i) router.out[i]->bind(drams[i]->target);
  sc_core::sc_start();

  const double peak = config.bytes_per_cycle;
  std::printf("banked DRAM, GDDR5 preset: %u channels, %.0f B/cycle peak at 1 GHz (256 GB/s); 64 B reads, "
              "at most %u in flight; %llu requests per point [precise calendars, loosely timed]\n",
              config.channels, peak, kWindow, static_cast<unsigned long long>(requests));
  std::printf("%-10s %8s %10s %9s %12s %7s %7s %9s %9s\n", "pattern", "offered", "achieved", "of peak",
              "latency", "hits", "misses", "conflicts", "overflows");
  for (const Point& p : points)
    std::printf("%-10s %6.0f%% %6.1f B/c %8.1f%% %8.1f cyc %6.1f%% %6.1f%% %8.1f%% %9llu\n", name(p.pattern),
                100 * p.offered / peak, p.achieved, 100 * p.achieved / peak, p.latency,
                100.0 * double(p.hits) / double(p.requests), 100.0 * double(p.misses) / double(p.requests),
                100.0 * double(p.conflicts) / double(p.requests), static_cast<unsigned long long>(p.overflows));
  if (argc > 2) {  // the same table for plots (experiments/plot_dram_latency.py)
    FILE* csv = std::fopen(argv[2], "w");
    if (csv == nullptr) {
      std::fprintf(stderr, "bench_dram: %s: cannot write the CSV\n", argv[2]);
      return 1;
    }
    std::fprintf(csv, "pattern,offered_bytes_per_cycle,achieved_bytes_per_cycle,peak_bytes_per_cycle,"
                      "mean_latency_cycles,row_hits,row_misses,row_conflicts,requests,derived_random_efficiency\n");
    for (const Point& p : points)
      std::fprintf(csv, "%s,%.3f,%.3f,%.0f,%.3f,%llu,%llu,%llu,%llu,%.4f\n", name(p.pattern), p.offered, p.achieved, peak,
                   p.latency, static_cast<unsigned long long>(p.hits), static_cast<unsigned long long>(p.misses),
                   static_cast<unsigned long long>(p.conflicts), static_cast<unsigned long long>(p.requests),
                   expected_random_efficiency(config));
    if (std::fclose(csv) != 0) {
      std::fprintf(stderr, "bench_dram: %s: cannot write the CSV\n", argv[2]);
      return 1;
    }
  }
  const double expected = expected_random_efficiency(config);
  double best = 0;
  for (const Point& p : points)
    if (p.pattern == Pattern::kRandom) best = std::max(best, p.achieved / peak);
  std::printf("random reads, saturated: model %.1f%% of peak, derived from tRC/tRRD/tFAW/tRFC %.1f%% (%+.1f%%)\n",
              100 * best, 100 * expected, 100 * (best / expected - 1));
  return 0;
}
