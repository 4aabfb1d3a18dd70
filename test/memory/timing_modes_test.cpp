// Loosely timed against precise, under contention: several temporally decoupled initiators
// share one resource, and the same traffic runs in both modes side by side in one simulation.
// Precise (every access synchronised) is the reference; the bounds below are what LT is
// allowed to differ by. Calendars make shared-resource timing exact in both modes, so what
// differs is the order in which requests reach the tags (a later-in-time request can arrive
// first under decoupling) and, through it, hits, misses and bank and link conflicts.
#include "memory_test_support.h"

#include "model/memory/dram.h"
#include "model/memory/interconnect.h"
#include "model/memory/l1_data_cache.h"
#include "model/memory/l2_cache.h"
#include "tlm/memory_initiator.h"

#include <memory>
#include <random>

namespace strata::memory::test {
namespace {

using transport::MemoryInitiator;
using transport::TimingMode;

std::unique_ptr<MemoryInitiator> make_tp(const std::string& name, TimingMode mode, uint32_t id, uint32_t tm) {
  transport::InitiatorConfig c;
  c.mode = mode;
  c.quantum_cycles = 1000;
  c.initiator_id = id;
  c.tm_id = tm;
  return std::make_unique<MemoryInitiator>(name.c_str(), c);
}

struct Outcome {
  Cycle makespan = 0;  // the cycle the last initiator finished
  double mean_latency = 0;
  uint64_t accesses = 0;
};

// Eight threads each read 2000 random lines straight from DRAM, computing 0..20 cycles in
// between. Contention is all on the channels' calendars.
struct DramSystem {
  TimingMode mode;
  SparseMemory backing;
  Interconnect xbar;
  Dram dram;
  LatencySink unused;
  std::vector<std::unique_ptr<MemoryInitiator>> tp;
  std::vector<std::unique_ptr<Script>> scripts;
  Outcome out;
  double latency_sum = 0;
  explicit DramSystem(TimingMode m, const std::string& tag)
      : mode(m), xbar((tag + "_xbar").c_str(), xbar_config()), dram((tag + "_dram").c_str(), DramConfig{}, backing),
        unused((tag + "_stream").c_str(), 1) {
    xbar.l2_side.bind(dram.target);
    xbar.stream_side.bind(unused.socket);
    for (uint32_t i = 0; i < 8; ++i) {
      tp.push_back(make_tp(tag + "_tp" + std::to_string(i), m, i, i));
      tp.back()->socket.bind(xbar.tm_side);
      scripts.push_back(std::make_unique<Script>((tag + "_run" + std::to_string(i)).c_str(), [this, i] { run(i); }));
    }
  }
  static InterconnectConfig xbar_config() {
    InterconnectConfig c;
    c.tm_ports = 8;
    return c;
  }
  void run(uint32_t i) {
    MemoryInitiator& me = *tp[i];
    std::mt19937 rng(100 + i);
    uint8_t line[64];
    for (int k = 0; k < 2000; ++k) {
      const uint64_t addr = (rng() % (1u << 20)) * 64;  // 64 MB of lines: every access goes to DRAM
      const transport::AccessResult r = me.load(addr, line, 64);
      latency_sum += static_cast<double>(r.latency());
      ++out.accesses;
      me.advance(rng() % 21);
    }
    me.sync();
    out.makespan = std::max(out.makespan, me.local_cycle());
    out.mean_latency = latency_sum / static_cast<double>(out.accesses);
  }
};

TEST(TimingModes, DecoupledInitiatorsSharingDramAgreeWithPreciseWithinOnePercent) {
  REQUIRE_FRESH_SYSTEMC();
  DramSystem lt(TimingMode::kLooselyTimed, "lt");
  DramSystem precise(TimingMode::kPrecise, "precise");
  sc_core::sc_start();
  ASSERT_EQ(lt.out.accesses, precise.out.accesses);
  EXPECT_EQ(lt.dram.counters().bytes_read, precise.dram.counters().bytes_read);
  const double makespan_error = std::abs(static_cast<double>(lt.out.makespan) - static_cast<double>(precise.out.makespan)) /
                                static_cast<double>(precise.out.makespan);
  const double latency_error = std::abs(lt.out.mean_latency - precise.out.mean_latency) / precise.out.mean_latency;
  RecordProperty("makespan_lt", std::to_string(lt.out.makespan));
  RecordProperty("makespan_precise", std::to_string(precise.out.makespan));
  std::printf("DRAM: makespan LT %llu precise %llu (%.3f%%), mean latency LT %.2f precise %.2f (%.3f%%)\n",
              static_cast<unsigned long long>(lt.out.makespan), static_cast<unsigned long long>(precise.out.makespan),
              100 * makespan_error, lt.out.mean_latency, precise.out.mean_latency, 100 * latency_error);
  EXPECT_LT(makespan_error, 0.01);
  EXPECT_LT(latency_error, 0.01);
  EXPECT_EQ(lt.dram.overflow_bookings(), 0u);
}

// Two TMs of eight TPs each: TPs -> L1 (per TM) -> interconnect -> L2 -> DRAM. Each TP reads
// random words from a 256 KB working set (8x the L1, half the L2), so L1 hits, L1 misses that
// hit the L2, merged misses and bank conflicts all occur.
struct HierarchySystem {
  SparseMemory backing;
  std::vector<std::unique_ptr<Fanin>> tm_port;
  std::vector<std::unique_ptr<L1DataCache>> l1;
  Interconnect xbar;
  L2Cache l2;
  Dram dram;
  LatencySink unused;
  std::vector<std::unique_ptr<MemoryInitiator>> tp;
  std::vector<std::unique_ptr<Script>> scripts;
  Outcome out;
  double latency_sum = 0;
  HierarchySystem(TimingMode m, const std::string& tag)
      : xbar((tag + "_xbar").c_str(), xbar_config()), l2((tag + "_l2").c_str(), L2Config{}, backing),
        dram((tag + "_dram").c_str(), DramConfig{}, backing), unused((tag + "_stream").c_str(), 1) {
    for (uint32_t t = 0; t < 2; ++t) {
      tm_port.push_back(std::make_unique<Fanin>((tag + "_port" + std::to_string(t)).c_str()));
      l1.push_back(std::make_unique<L1DataCache>((tag + "_l1_" + std::to_string(t)).c_str(), L1DataCacheConfig{}, backing));
      tm_port.back()->out.bind(l1.back()->target);
      l1.back()->downstream.bind(xbar.tm_side);
    }
    xbar.l2_side.bind(l2.target);
    xbar.stream_side.bind(unused.socket);
    l2.downstream.bind(dram.target);
    for (uint32_t i = 0; i < 16; ++i) {
      tp.push_back(make_tp(tag + "_tp" + std::to_string(i), m, i, i / 8));
      tp.back()->socket.bind(tm_port[i / 8]->in);
      scripts.push_back(std::make_unique<Script>((tag + "_run" + std::to_string(i)).c_str(), [this, i] { run(i); }));
    }
  }
  static InterconnectConfig xbar_config() {
    InterconnectConfig c;
    c.tm_ports = 2;
    return c;
  }
  void run(uint32_t i) {
    MemoryInitiator& me = *tp[i];
    std::mt19937 rng(500 + i);
    uint32_t word = 0;
    for (int k = 0; k < 3000; ++k) {
      const uint64_t addr = 0x100000 + (rng() % (256 * 1024 / 4)) * 4;
      const transport::AccessResult r = me.load(addr, &word, 4);
      latency_sum += static_cast<double>(r.latency());
      ++out.accesses;
      me.advance(rng() % 5);
    }
    me.sync();
    out.makespan = std::max(out.makespan, me.local_cycle());
    out.mean_latency = latency_sum / static_cast<double>(out.accesses);
  }
  uint64_t l1_hits() const { return l1[0]->counters().hits + l1[1]->counters().hits; }
};

double relative(double a, double b) { return std::abs(a - b) / b; }

TEST(TimingModes, CacheHierarchyUnderContentionAgreesWithPreciseWithinStatedBounds) {
  REQUIRE_FRESH_SYSTEMC();
  HierarchySystem lt(TimingMode::kLooselyTimed, "lt");
  HierarchySystem precise(TimingMode::kPrecise, "precise");
  sc_core::sc_start();
  ASSERT_EQ(lt.out.accesses, precise.out.accesses);
  const double makespan = relative(static_cast<double>(lt.out.makespan), static_cast<double>(precise.out.makespan));
  const double latency = relative(lt.out.mean_latency, precise.out.mean_latency);
  const double hits = relative(static_cast<double>(lt.l1_hits()), static_cast<double>(precise.l1_hits()));
  const double l2_misses = relative(static_cast<double>(lt.l2.counters().misses), static_cast<double>(precise.l2.counters().misses));
  std::printf("hierarchy: makespan LT %llu precise %llu (%.3f%%); mean latency %.2f vs %.2f (%.3f%%); "
              "L1 hits %llu vs %llu (%.3f%%); L2 misses %llu vs %llu (%.3f%%); DRAM bytes %llu vs %llu\n",
              static_cast<unsigned long long>(lt.out.makespan), static_cast<unsigned long long>(precise.out.makespan),
              100 * makespan, lt.out.mean_latency, precise.out.mean_latency, 100 * latency,
              static_cast<unsigned long long>(lt.l1_hits()), static_cast<unsigned long long>(precise.l1_hits()), 100 * hits,
              static_cast<unsigned long long>(lt.l2.counters().misses),
              static_cast<unsigned long long>(precise.l2.counters().misses), 100 * l2_misses,
              static_cast<unsigned long long>(lt.dram.counters().bytes_read),
              static_cast<unsigned long long>(precise.dram.counters().bytes_read));
  // The stated bounds: LT (quantum 1000 cycles) within 2 % of precise on finishing time and
  // mean latency, 3 % on L1 hits, and within 1 % on L2 misses. Measured with the L2's hashed
  // banks: 1.06 %, 0.32 %, 2.84 %, 0 %. The L1 hits are few (12 % of the accesses), so their
  // relative error is the noisiest: over the seeds 500, 1000, ..., 4000 it ranged 0.35-2.84 %
  // hashed and 0.09-1.30 % with the low-bit interleave. Without CacheCore's time-consistent
  // tags (an early request waiting for a fill that a later one started) it was 33 %, 26 %,
  // 8.3 %: this test fails on that.
  EXPECT_LT(makespan, 0.02);
  EXPECT_LT(latency, 0.02);
  EXPECT_LT(hits, 0.03);
  EXPECT_LT(l2_misses, 0.01);
  EXPECT_EQ(precise.l1[0]->counters().reordered + precise.l1[1]->counters().reordered, 0u);
}

}  // namespace
}  // namespace strata::memory::test
