// Transactions per second of each memory module, in both timing modes.
//
//   bench_memory [transactions per system, default 400000]
//
// SystemC elaborates once per process, so every system (module x mode) is built up front and
// they run one after another inside one simulation: a driver starts a system's traffic,
// waits until all its threads are done and reads the wall clock around it. Each system is
// 32 initiator threads (TPs or TMs) feeding the module under test, with a fixed-latency sink
// below it where it has one. A transaction is one request the module under test serves.
#include "model/memory/dram.h"
#include "model/memory/interconnect.h"
#include "model/memory/l1_data_cache.h"
#include "model/memory/l1_instruction_cache.h"
#include "model/memory/l2_cache.h"
#include "model/memory/stream_memory.h"
#include "tlm/memory_initiator.h"

#include <systemc>
#include <tlm_utils/multi_passthrough_target_socket.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace strata::memory;
using strata::transport::AccessResult;
using strata::transport::Clock;
using strata::transport::Cycle;
using strata::transport::InitiatorConfig;
using strata::transport::kNoTreelet;
using strata::transport::MemoryExtension;
using strata::transport::MemoryInitiator;
using strata::transport::StreamStatus;
using strata::transport::TimingMode;

constexpr uint32_t kThreads = 32;

struct Sink : sc_core::sc_module {
  tlm_utils::simple_target_socket<Sink> socket{"socket"};
  Clock clock;
  Cycle latency;
  Sink(sc_core::sc_module_name n, Cycle lat) : sc_core::sc_module(n), latency(lat) {
    socket.register_b_transport(this, &Sink::b_transport);
  }
  void b_transport(tlm::tlm_generic_payload& gp, sc_core::sc_time& delay) {
    delay = clock.delay_until(clock.request_cycle(delay) + latency);
    gp.set_response_status(tlm::TLM_OK_RESPONSE);
  }
};

// The TM side of a module with one target socket: many threads, one port.
struct Fanin : sc_core::sc_module {
  tlm_utils::multi_passthrough_target_socket<Fanin> in{"in"};
  tlm_utils::simple_initiator_socket<Fanin> out{"out"};
  explicit Fanin(sc_core::sc_module_name n) : sc_core::sc_module(n) { in.register_b_transport(this, &Fanin::b_transport); }
  void b_transport(int, tlm::tlm_generic_payload& gp, sc_core::sc_time& d) { out->b_transport(gp, d); }
};

struct System {
  std::string module;
  TimingMode mode;
  uint64_t per_thread;
  std::function<void(MemoryInitiator&, uint32_t, uint64_t)> traffic;  // (initiator, thread, count)
  std::vector<std::shared_ptr<void>> parts;  // owns the modules of this system
  std::vector<MemoryInitiator*> threads;
  sc_core::sc_event start, finished;
  uint32_t running = 0;
  double seconds = 0;
};

struct Runner : sc_core::sc_module {
  std::vector<std::unique_ptr<System>>& systems;
  SC_HAS_PROCESS(Runner);
  Runner(sc_core::sc_module_name n, std::vector<std::unique_ptr<System>>& s) : sc_core::sc_module(n), systems(s) {
    SC_THREAD(drive);
  }
  void drive() {
    for (auto& s : systems) {
      s->running = kThreads;
      const auto t0 = std::chrono::steady_clock::now();
      s->start.notify();
      sc_core::wait(s->finished);
      s->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
  }
};

struct Thread : sc_core::sc_module {
  System& system;
  MemoryInitiator& initiator;
  uint32_t index;
  SC_HAS_PROCESS(Thread);
  Thread(sc_core::sc_module_name n, System& s, MemoryInitiator& i, uint32_t idx)
      : sc_core::sc_module(n), system(s), initiator(i), index(idx) {
    SC_THREAD(run);
  }
  void run() {
    sc_core::wait(system.start);
    system.traffic(initiator, index, system.per_thread);
    initiator.sync();
    if (--system.running == 0) system.finished.notify();
  }
};

template <typename T, typename... Args>
T& make(System& s, Args&&... args) {
  auto p = std::make_shared<T>(std::forward<Args>(args)...);
  T& ref = *p;
  s.parts.push_back(std::move(p));
  return ref;
}

// 32 initiators bound through `bind` (to a Fanin or a multi-socket), driving `traffic`.
void add_threads(System& s, const std::string& tag, const std::function<void(MemoryInitiator&)>& bind) {
  for (uint32_t i = 0; i < kThreads; ++i) {
    InitiatorConfig c;
    c.mode = s.mode;
    c.quantum_cycles = 1000;
    c.initiator_id = i;
    c.tm_id = 0;
    auto& init = make<MemoryInitiator>(s, (tag + "_tp" + std::to_string(i)).c_str(), c);
    bind(init);
    s.threads.push_back(&init);
    make<Thread>(s, (tag + "_thread" + std::to_string(i)).c_str(), s, init, i);
  }
}

}  // namespace

int sc_main(int argc, char** argv) {
  const uint64_t total = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 400000;
  SparseMemory backing;
  std::vector<std::unique_ptr<System>> systems;
  std::vector<std::function<std::string()>> describe;  // module statistics after the run

  for (TimingMode mode : {TimingMode::kLooselyTimed, TimingMode::kPrecise}) {
    const std::string m = mode == TimingMode::kPrecise ? "precise" : "lt";
    auto new_system = [&](const std::string& module) -> System& {
      systems.push_back(std::make_unique<System>());
      System& s = *systems.back();
      s.module = module;
      s.mode = mode;
      s.per_thread = total / kThreads;
      return s;
    };
    {  // L1 data cache: random words in 64 KB (2x the cache), 10 % stores; L2 behind it: 20 cycles
      System& s = new_system("l1_data_cache");
      auto& l1 = make<L1DataCache>(s, ("l1d_" + m).c_str(), L1DataCacheConfig{}, backing);
      auto& fan = make<Fanin>(s, ("l1d_fan_" + m).c_str());
      auto& sink = make<Sink>(s, ("l1d_sink_" + m).c_str(), 20);
      fan.out.bind(l1.target);
      l1.downstream.bind(sink.socket);
      add_threads(s, "l1d_" + m, [&](MemoryInitiator& i) { i.socket.bind(fan.in); });
      s.traffic = [](MemoryInitiator& me, uint32_t t, uint64_t n) {
        std::mt19937 rng(t);
        uint32_t word = 0;
        for (uint64_t k = 0; k < n; ++k) {
          const uint64_t addr = (rng() % (64 * 1024 / 4)) * 4;
          if (rng() % 10 == 0) me.store(addr, &word, 4);
          else me.load(addr, &word, 4);
          me.advance(rng() % 4);
        }
      };
      describe.push_back([&l1] {
        const auto& c = l1.counters();
        return "hit rate " + std::to_string(static_cast<double>(c.hits) / static_cast<double>(c.loads));
      });
    }
    {  // L1 instruction cache: 8 KB of code in 64-instruction basic blocks, misses modelled
      System& s = new_system("l1_instruction_cache");
      auto& l1 = make<L1InstructionCache>(s, ("l1i_" + m).c_str(), L1InstructionCacheConfig{}, backing);
      auto& fan = make<Fanin>(s, ("l1i_fan_" + m).c_str());
      auto& sink = make<Sink>(s, ("l1i_sink_" + m).c_str(), 20);
      fan.out.bind(l1.target);
      l1.downstream.bind(sink.socket);
      add_threads(s, "l1i_" + m, [&](MemoryInitiator& i) { i.socket.bind(fan.in); });
      s.traffic = [](MemoryInitiator& me, uint32_t t, uint64_t n) {
        std::mt19937 rng(t);
        uint32_t insn = 0;
        uint64_t pc = 0;
        for (uint64_t k = 0; k < n; ++k) {
          if (k % 64 == 0) pc = (rng() % (8 * 1024 / 256)) * 256;
          me.fetch(pc, &insn, 4);
          pc += 4;
        }
      };
      describe.push_back([&l1] {
        const auto& c = l1.counters();
        return "hit rate " + std::to_string(static_cast<double>(c.hits) / static_cast<double>(c.accesses));
      });
    }
    {  // L2 (512 KB, 16 banks): random lines in 1 MB; DRAM behind it: 100 cycles
      System& s = new_system("l2_cache");
      auto& l2 = make<L2Cache>(s, ("l2_" + m).c_str(), L2Config{}, backing);
      auto& fan = make<Fanin>(s, ("l2_fan_" + m).c_str());
      auto& sink = make<Sink>(s, ("l2_sink_" + m).c_str(), 100);
      fan.out.bind(l2.target);
      l2.downstream.bind(sink.socket);
      add_threads(s, "l2_" + m, [&](MemoryInitiator& i) { i.socket.bind(fan.in); });
      s.traffic = [](MemoryInitiator& me, uint32_t t, uint64_t n) {
        std::mt19937 rng(t);
        uint8_t line[64];
        for (uint64_t k = 0; k < n; ++k) me.load((rng() % (1024 * 1024 / 64)) * 64, line, 64);
      };
      describe.push_back([&l2] {
        const auto& c = l2.counters();
        return "hit rate " + std::to_string(static_cast<double>(c.hits) / static_cast<double>(c.accesses));
      });
    }
    {  // DRAM (8 channels, 256 B/cycle): random lines over 1 GB, timing-only like cache fills
      System& s = new_system("dram");
      auto& dram = make<Dram>(s, ("dram_" + m).c_str(), DramConfig{}, backing);
      auto& fan = make<Fanin>(s, ("dram_fan_" + m).c_str());
      fan.out.bind(dram.target);
      add_threads(s, "dram_" + m, [&](MemoryInitiator& i) { i.socket.bind(fan.in); });
      s.traffic = [](MemoryInitiator& me, uint32_t t, uint64_t n) {
        std::mt19937 rng(t);
        uint8_t line[64];
        for (uint64_t k = 0; k < n; ++k) me.load((rng() % (1u << 24)) * 64, line, 64);
      };
      describe.push_back([&dram] {
        return "resident MB " + std::to_string(dram.backing().resident_bytes() >> 20) + ", queued cycles ch0 " +
               std::to_string(dram.channel(0).queued_cycles);
      });
    }
    {  // Banked DRAM (the GDDR5 preset, memory.dram.model = banked): the same random lines
      System& s = new_system("dram_banked");
      DramConfig banked;
      banked.model = DramModel::kBanked;
      auto& dram = make<Dram>(s, ("dram_banked_" + m).c_str(), banked, backing);
      auto& fan = make<Fanin>(s, ("dram_banked_fan_" + m).c_str());
      fan.out.bind(dram.target);
      add_threads(s, "dram_banked_" + m, [&](MemoryInitiator& i) { i.socket.bind(fan.in); });
      s.traffic = [](MemoryInitiator& me, uint32_t t, uint64_t n) {
        std::mt19937 rng(t);
        uint8_t line[64];
        for (uint64_t k = 0; k < n; ++k) me.load((rng() % (1u << 24)) * 64, line, 64);
      };
      describe.push_back([&dram] {
        const BankedDram::ChannelCounters& k = dram.banked()->channel(0);
        return "row conflicts ch0 " + std::to_string(k.row_conflicts) + ", mean read latency ch0 " +
               std::to_string(k.read_requests ? double(k.read_latency_cycles) / double(k.read_requests) : 0.0);
      });
    }
    {  // Interconnect: 32 TM ports, 16 L2 banks behind (3 cycles), 10 % stream operations
      System& s = new_system("interconnect");
      InterconnectConfig xc;
      xc.tm_ports = kThreads;
      auto& xbar = make<Interconnect>(s, ("xbar_" + m).c_str(), xc);
      auto& l2 = make<Sink>(s, ("xbar_l2_" + m).c_str(), 3);
      auto& stream = make<Sink>(s, ("xbar_stream_" + m).c_str(), 3);
      xbar.l2_side.bind(l2.socket);
      xbar.stream_side.bind(stream.socket);
      add_threads(s, "xbar_" + m, [&](MemoryInitiator& i) { i.socket.bind(xbar.tm_side); });
      s.traffic = [](MemoryInitiator& me, uint32_t t, uint64_t n) {
        std::mt19937 rng(t);
        uint8_t line[64];
        for (uint64_t k = 0; k < n; ++k) {
          if (rng() % 10 == 0) me.stream_size(0);
          else me.load((rng() % (1u << 20)) * 64, line, 64);
        }
      };
      describe.push_back([&xbar] {
        return "conflict cycles " + std::to_string(xbar.counters().conflict_cycles);
      });
    }
    {  // Stream memory (512 KB): pop a ray from the TM's buffer, push it on to a random treelet
      System& s = new_system("stream_memory");
      StreamMemoryConfig sc;
      sc.tms = 1;
      auto& mem = make<StreamMemory>(s, ("stream_" + m).c_str(), sc);
      auto& fan = make<Fanin>(s, ("stream_fan_" + m).c_str());
      fan.out.bind(mem.target);
      add_threads(s, "stream_" + m, [&](MemoryInitiator& i) { i.socket.bind(fan.in); });
      s.traffic = [](MemoryInitiator& me, uint32_t t, uint64_t n) {
        std::mt19937 rng(t);
        uint32_t ray[12] = {t};
        for (uint64_t k = 0; k < 64; ++k) me.stream_push(static_cast<uint32_t>(rng() % 64), ray);  // fill
        for (uint64_t k = 64; k < n;) {
          if (me.stream_pop(kNoTreelet, ray).stream_status != StreamStatus::kOk) {
            me.stream_assign();
            k += 2;
            continue;
          }
          me.advance(rng() % 8);
          me.stream_push(static_cast<uint32_t>(rng() % 64), ray);
          k += 2;
        }
      };
      describe.push_back([&mem] { return "stored " + std::to_string(mem.stored()); });
    }
  }

  Runner runner("runner", systems);
  sc_core::sc_start();

  std::printf("%-22s %-14s %12s %10s %14s  %s\n", "module", "mode", "transactions", "seconds", "transactions/s",
              "check");
  for (std::size_t i = 0; i < systems.size(); ++i) {
    const System& s = *systems[i];
    const double n = static_cast<double>(s.per_thread * kThreads);
    std::printf("%-22s %-14s %12.0f %10.3f %14.0f  %s\n", s.module.c_str(), strata::transport::to_string(s.mode), n,
                s.seconds, n / s.seconds, describe[i]().c_str());
  }
  return 0;
}
