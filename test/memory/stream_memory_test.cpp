// The ray stream memory controller: SRAM layout and capacity, list operations through TLM
// with exact latencies, random push/pop against a reference model, full-memory backpressure
// (no ray lost, no deadlock) and the scheduling policies.
#include "memory_test_support.h"

#include "model/memory/interconnect.h"
#include "model/memory/stream_memory.h"
#include "tlm/memory_initiator.h"

#include <algorithm>
#include <memory>
#include <random>
#include <set>

namespace strata::memory::test {
namespace {

using transport::kNoTreelet;

struct Ray {
  uint32_t words[12] = {};
};
Ray make_ray(uint32_t id) {
  Ray r;
  for (uint32_t i = 0; i < 12; ++i) r.words[i] = id * 13 + i;  // the id, checkably spread over 48 B
  return r;
}
uint32_t id_of(const Ray& r) {
  const uint32_t id = r.words[0] / 13;
  for (uint32_t i = 0; i < 12; ++i) EXPECT_EQ(r.words[i], id * 13 + i) << "ray corrupted";
  return id;
}

// A memory of exactly `rays` entries for `treelets` treelets and `threads` threads.
StreamMemoryConfig tiny(uint32_t rays, uint32_t treelets, uint32_t threads, uint32_t tms) {
  StreamMemoryConfig c;
  c.treelets = treelets;
  c.threads = threads;
  c.tms = tms;
  const uint32_t header = 16 + 8 * treelets + (threads + 31) / 32 * 4;
  c.size_bytes = header + rays * StreamLayout{}.entry_bytes();
  c.access_energy_nj = 0.5;  // below the CACTI table's range: give it
  return c;
}

TEST(StreamMemoryLayout, HeadsCountsCreditsAndLinksComeOutOfTheCapacity) {
  const StreamLayout l = make_stream_layout(StreamMemoryConfig{});  // 512 KB, 1024 treelets, 4096 threads
  EXPECT_EQ(l.entries_offset, 16u + 4096u + 4096u + 512u);
  EXPECT_EQ(l.capacity, (512u * 1024u - 8720u) / 52u);
  EXPECT_EQ(l.capacity, 9914u);
  // A 64-byte ray (the compact path state) takes a 68-byte entry.
  StreamMemoryConfig compact;
  compact.ray_bytes = 64;
  EXPECT_EQ(make_stream_layout(compact).capacity, (512u * 1024u - 8720u) / 68u);
  EXPECT_LT(l.overhead_fraction(), 0.10);  // links alone are 4/52 = 7.7 %
  StreamMemoryConfig big;
  big.size_bytes = 16 * 1024 * 1024;
  EXPECT_LT(make_stream_layout(big).overhead_fraction(), 0.08);
  EXPECT_EQ(make_stream_layout(tiny(10, 4, 4, 1)).capacity, 10u);
  StreamMemoryConfig too_small = tiny(0, 4, 4, 1);
  EXPECT_THROW(make_stream_layout(too_small), std::invalid_argument);
}

TEST(StreamMemory, OperationsThroughTlmWithExactLatencies) {
  REQUIRE_FRESH_SYSTEMC();
  StreamMemoryConfig c = tiny(77, 8, 4, 2);
  c.ports = 1;
  StreamMemory mem("stream", c);
  RawInitiator tp("tp", 0, 0);
  tp.socket.bind(mem.target);
  std::vector<Sent> r;
  Ray popped[3];
  Script s("script", [&] {
    Ray a = make_ray(1), b = make_ray(2), cc = make_ray(3);
    r.push_back(tp.send(AccessClass::kStreamCapacity, 0, nullptr, 0, 0));           // 1
    r.push_back(tp.send(AccessClass::kStreamPush, 0, a.words, 48, 0, 3));           // port 0: 3
    r.push_back(tp.send(AccessClass::kStreamPush, 0, b.words, 48, 0, 3));           // port busy: 4
    r.push_back(tp.send(AccessClass::kStreamPush, 0, cc.words, 48, 10, 5));         // 13
    r.push_back(tp.send(AccessClass::kStreamSize, 0, nullptr, 0, 20, 3));           // 21
    r.push_back(tp.send(AccessClass::kStreamAssign, 0, nullptr, 0, 20));            // fullest: 3
    r.push_back(tp.send(AccessClass::kStreamPop, 0, popped[0].words, 48, 30));      // TM's: b, 33
    r.push_back(tp.send(AccessClass::kStreamPop, 0, popped[1].words, 48, 31));      // a, 34
    r.push_back(tp.send(AccessClass::kStreamPop, 0, popped[2].words, 48, 40));      // empty
    r.push_back(tp.send(AccessClass::kStreamAssign, 0, nullptr, 0, 50));            // now 5
    r.push_back(tp.send(AccessClass::kStreamPush, 0, a.words, 48, 60, 99));         // bad treelet
  });
  sc_core::sc_start();
  ASSERT_EQ(r.size(), 11u);
  EXPECT_EQ(r[0].result, 77u);
  EXPECT_EQ(r[0].done, 1u);
  EXPECT_EQ(r[1].done, 3u);
  EXPECT_EQ(r[1].result, 1u);
  EXPECT_EQ(r[2].done, 4u);
  EXPECT_EQ(r[3].done, 13u);
  EXPECT_EQ(r[4].result, 2u);
  EXPECT_EQ(r[4].done, 21u);
  EXPECT_EQ(r[5].result, 3u);
  EXPECT_EQ(r[6].done, 33u);
  EXPECT_EQ(id_of(popped[0]), 2u);  // LIFO
  EXPECT_EQ(r[7].done, 34u);
  EXPECT_EQ(id_of(popped[1]), 1u);
  EXPECT_EQ(r[8].stream_status, StreamStatus::kEmpty);
  EXPECT_EQ(r[8].result, 0u);
  EXPECT_EQ(r[9].result, 5u);
  EXPECT_EQ(r[10].stream_status, StreamStatus::kBadRequest);
  EXPECT_EQ(r[10].response, tlm::TLM_GENERIC_ERROR_RESPONSE);
  const auto& k = mem.counters();
  EXPECT_EQ(k.pushes, 4u);
  EXPECT_EQ(k.pops, 3u);
  EXPECT_EQ(k.empty_pops, 1u);
  EXPECT_EQ(k.port_conflicts, 1u);
  EXPECT_EQ(k.accesses, 11u);
  EXPECT_DOUBLE_EQ(k.energy_nj, 11 * 0.5);
  EXPECT_EQ(mem.stored(), 1u);
}

// Banks: ray entries are interleaved over the banks, each with its own port and link, so two
// pushes in one cycle go to two banks without waiting; with one bank the second waits. The
// link is booked for the data: a push's on the way in, a pop's on the way out.
TEST(StreamMemory, BanksServeInterleavedEntriesInParallelEachWithItsOwnLink) {
  REQUIRE_FRESH_SYSTEMC();
  StreamMemoryConfig one = tiny(64, 8, 4, 2);
  one.ports = 1;
  one.link_bytes_per_cycle = 64;
  StreamMemoryConfig two = one;
  two.banks = 2;
  StreamMemory single("single", one), banked("banked", two);
  RawInitiator a("a", 0, 0), b("b", 1, 0);
  a.socket.bind(single.target);
  b.socket.bind(banked.target);
  std::vector<Sent> ra, rb;
  Script s("script", [&] {
    Ray x = make_ray(1), y = make_ray(2);
    for (auto* r : {&ra, &rb}) {
      RawInitiator& tp = r == &ra ? a : b;
      r->push_back(tp.send(AccessClass::kStreamPush, 0, x.words, 48, 0, 3));  // entry 0: bank 0
      r->push_back(tp.send(AccessClass::kStreamPush, 0, y.words, 48, 0, 3));  // entry 1: bank 1 (or 0)
      r->push_back(tp.send(AccessClass::kStreamPop, 0, x.words, 48, 20, 3));  // entry 1 (LIFO)
    }
  });
  sc_core::sc_start();
  // Link (1 cycle for 48 B) then port, then the 3-cycle access; a pop's data leaves after it.
  EXPECT_EQ(ra[0].done, 1u + 3u);
  EXPECT_EQ(ra[1].done, 2u + 3u);  // one bank: its link and port were taken a cycle earlier
  EXPECT_EQ(rb[0].done, 1u + 3u);
  EXPECT_EQ(rb[1].done, 1u + 3u);  // two banks: in parallel
  EXPECT_EQ(rb[2].done, 20u + 3u + 1u);
  EXPECT_EQ(single.counters().port_conflicts + single.counters().link_conflicts, 1u);
  EXPECT_EQ(banked.counters().port_conflicts + banked.counters().link_conflicts, 0u);
}

// The reference: one std::vector stack per treelet plus the credit rule, stated plainly.
struct ReferenceStreams {
  std::vector<std::vector<uint32_t>> stacks;
  std::set<uint32_t> credits;
  uint32_t capacity, stored = 0;
  ReferenceStreams(uint32_t treelets, uint32_t cap) : stacks(treelets), capacity(cap) {}
  bool push(uint32_t thread, uint32_t treelet, uint32_t id) {
    if (credits.erase(thread) == 0 && stored + credits.size() >= capacity) return false;
    stacks[treelet].push_back(id);
    ++stored;
    return true;
  }
  bool pop(uint32_t thread, uint32_t treelet, uint32_t* id) {
    if (stacks[treelet].empty()) return false;
    *id = stacks[treelet].back();
    stacks[treelet].pop_back();
    --stored;
    credits.insert(thread);
    return true;
  }
};

TEST(StreamSram, RandomPushPopMatchesReferenceAndNoRayIsLostOrDuplicated) {
  const StreamLayout layout = make_stream_layout(tiny(300, 16, 64, 1));
  StreamSram sram(layout);
  ReferenceStreams ref(16, layout.capacity);
  std::mt19937 rng(1234);
  std::set<uint32_t> live;  // rays stored in the memory
  uint32_t next_id = 1;
  uint64_t full = 0, empty = 0;
  for (int op = 0; op < 200000; ++op) {
    const uint32_t thread = rng() % 64, treelet = rng() % 16;
    if (rng() % 100 < 52) {
      const uint32_t id = next_id++;
      const Ray ray = make_ray(id);
      const bool stored = sram.push(thread, treelet, reinterpret_cast<const uint8_t*>(ray.words)) == StreamStatus::kOk;
      ASSERT_EQ(stored, ref.push(thread, treelet, id)) << "op " << op;
      if (stored) live.insert(id);
      else ++full;
    } else {
      Ray ray;
      uint32_t expected = 0;
      const bool got = sram.pop(thread, treelet, reinterpret_cast<uint8_t*>(ray.words)) == StreamStatus::kOk;
      ASSERT_EQ(got, ref.pop(thread, treelet, &expected)) << "op " << op;
      if (got) {
        ASSERT_EQ(id_of(ray), expected);
        ASSERT_EQ(live.erase(expected), 1u) << "ray popped twice";
      } else {
        ++empty;
      }
    }
    ASSERT_LE(uint64_t{sram.stored()} + sram.credits(), layout.capacity);
  }
  EXPECT_GT(full, 1000u);  // the memory was full often: the test exercised backpressure
  EXPECT_GT(empty, 1000u);
  // Drain: every stored ray comes out exactly once.
  for (uint32_t t = 0; t < 16; ++t) {
    Ray ray;
    while (sram.pop(0, t, reinterpret_cast<uint8_t*>(ray.words)) == StreamStatus::kOk)
      ASSERT_EQ(live.erase(id_of(ray)), 1u);
  }
  EXPECT_TRUE(live.empty());
  EXPECT_EQ(sram.stored(), 0u);
}

TEST(StreamMemory, RandomTrafficThroughTlmMatchesReference) {
  REQUIRE_FRESH_SYSTEMC();
  const StreamMemoryConfig c = tiny(100, 8, 16, 1);
  StreamMemory mem("stream", c);
  RawInitiator tp("tp");
  tp.socket.bind(mem.target);
  ReferenceStreams ref(8, mem.capacity());
  bool all_matched = true;
  Script s("script", [&] {
    std::mt19937 rng(99);
    uint32_t next_id = 1;
    for (Cycle cycle = 0; cycle < 20000; ++cycle) {
      tp.initiator_id = rng() % 16;
      const uint32_t treelet = rng() % 8;
      if (rng() % 2 == 0) {
        Ray ray = make_ray(next_id++);
        const Sent r = tp.send(AccessClass::kStreamPush, 0, ray.words, 48, cycle, treelet);
        all_matched &= (r.stream_status == StreamStatus::kOk) == ref.push(tp.initiator_id, treelet, ray.words[0] / 13);
      } else {
        Ray ray;
        uint32_t expected = 0;
        const Sent r = tp.send(AccessClass::kStreamPop, 0, ray.words, 48, cycle, treelet);
        const bool got = r.stream_status == StreamStatus::kOk;
        all_matched &= got == ref.pop(tp.initiator_id, treelet, &expected);
        if (got) all_matched &= id_of(ray) == expected;
      }
    }
  });
  sc_core::sc_start();
  EXPECT_TRUE(all_matched);
  EXPECT_EQ(mem.stored(), ref.stored);
  EXPECT_GT(mem.counters().full_rejections, 0u);
}

// TPs as loosely timed MemoryInitiators reaching the stream memory through the interconnect.
struct StreamSystem {
  Interconnect xbar;
  StreamMemory mem;
  LatencySink l2{"l2", 10};
  std::vector<std::unique_ptr<transport::MemoryInitiator>> tp;
  StreamSystem(const StreamMemoryConfig& c, uint32_t threads)
      : xbar("xbar", xbar_config(threads)), mem("stream", c) {
    for (uint32_t i = 0; i < threads; ++i) {
      transport::InitiatorConfig ic;
      ic.initiator_id = i;
      ic.tm_id = 0;
      ic.quantum_cycles = 200;
      tp.push_back(std::make_unique<transport::MemoryInitiator>(("tp" + std::to_string(i)).c_str(), ic));
      tp.back()->socket.bind(xbar.tm_side);
    }
    xbar.l2_side.bind(l2.socket);
    xbar.stream_side.bind(mem.target);
  }
  static InterconnectConfig xbar_config(uint32_t ports) {
    InterconnectConfig x;
    x.tm_ports = ports;
    return x;
  }
};

TEST(StreamMemory, FullMemoryPushesStallUntilThereIsRoomAndNoRayIsLost) {
  REQUIRE_FRESH_SYSTEMC();
  StreamSystem sys(tiny(10, 4, 4, 1), 3);
  auto& filler = *sys.tp[0];
  auto& worker = *sys.tp[1];
  auto& extra = *sys.tp[2];
  std::vector<uint32_t> accepted, held, drained;
  bool refused_before_replacement = false, replacement_ok = false;
  uint64_t retries = 0;
  Cycle stalled_push_done = 0, room_made_at = 0;
  sc_core::sc_event filled, stalled_push_stored;
  Script fill("fill", [&] {
    for (uint32_t id = 1;; ++id) {  // firmware fills the root treelet until the memory says full
      const Ray ray = make_ray(id);
      if (filler.stream_push(0, ray.words).stream_status == StreamStatus::kFull) break;
      accepted.push_back(id);
    }
    filler.sync();
    filled.notify();
  });
  Script stall("stall", [&] {
    sc_core::wait(filled);
    extra.advance(10);
    const Ray ray = make_ray(2000);
    const transport::AccessResult r = extra.stream_push_blocking(3, ray.words, 16, &retries);
    EXPECT_EQ(r.stream_status, StreamStatus::kOk);
    stalled_push_done = r.completed;
    accepted.push_back(2000);
    stalled_push_stored.notify();
  });
  Script work("work", [&] {
    sc_core::wait(filled);
    Ray ray;
    EXPECT_EQ(worker.stream_pop(0, ray.words).stream_status, StreamStatus::kOk);  // holds a slot now
    const Ray other = make_ray(1000);
    // Another thread's new ray may not take the slot the worker holds...
    refused_before_replacement = extra.stream_push(1, other.words).stream_status == StreamStatus::kFull;
    // ...so one-for-one replacement succeeds although stored + held == capacity.
    replacement_ok = worker.stream_push(2, ray.words).stream_status == StreamStatus::kOk;
    worker.advance(1000);
    worker.sync();
    room_made_at = worker.local_cycle();
    for (int i = 0; i < 2; ++i) {  // the first of these rays ends without a successor: room
      EXPECT_EQ(worker.stream_pop(0, ray.words).stream_status, StreamStatus::kOk);
      held.push_back(id_of(ray));
    }
    sc_core::wait(stalled_push_stored);
    for (uint32_t t = 0; t < 4; ++t)
      while (worker.stream_pop(t, ray.words).stream_status == StreamStatus::kOk) drained.push_back(id_of(ray));
  });
  sc_core::sc_start();
  EXPECT_EQ(accepted.size(), 11u);  // 10 to fill the memory, then the stalled one
  EXPECT_TRUE(refused_before_replacement);
  EXPECT_TRUE(replacement_ok);
  EXPECT_GT(retries, 10u);  // it really stalled, for about 1000 cycles at 16 per retry
  EXPECT_GE(stalled_push_done, room_made_at);
  // Every accepted ray is accounted for exactly once: taken by the worker or still stored.
  std::multiset<uint32_t> out(held.begin(), held.end());
  out.insert(drained.begin(), drained.end());
  EXPECT_EQ(out, std::multiset<uint32_t>(accepted.begin(), accepted.end()));
  EXPECT_EQ(sys.mem.counters().full_rejections, 1u + 1u + retries);
}

TEST(StreamMemory, OneForOneReplacementNeverFailsOnAFullMemory) {
  REQUIRE_FRESH_SYSTEMC();
  constexpr uint32_t kThreads = 8;
  StreamSystem sys(tiny(10, 4, kThreads, 1), kThreads);
  sc_core::sc_event filled;
  uint32_t rejected = 0, rounds_done = 0;
  Script fill("fill", [&] {
    for (uint32_t id = 1; id <= 10; ++id) {
      const Ray ray = make_ray(id);
      EXPECT_EQ(sys.tp[0]->stream_push(0, ray.words).stream_status, StreamStatus::kOk);
    }
    sys.tp[0]->sync();
    filled.notify();
  });
  std::vector<std::unique_ptr<Script>> workers;
  for (uint32_t w = 0; w < kThreads; ++w) {
    workers.push_back(std::make_unique<Script>(("w" + std::to_string(w)).c_str(), [&, w] {
      sc_core::wait(filled);
      auto& tp = *sys.tp[w];
      std::mt19937 rng(w);
      Ray ray;
      for (int done = 0; done < 300;) {
        if (tp.stream_pop(kNoTreelet, ray.words).stream_status != StreamStatus::kOk) {
          tp.stream_assign();  // the TM's buffer ran dry: get another
          tp.advance(1);
          continue;
        }
        tp.advance(5 + rng() % 20);  // traverse the treelet
        if (tp.stream_push(rng() % 4, ray.words).stream_status != StreamStatus::kOk) ++rejected;
        ++done;
      }
      ++rounds_done;
    }));
  }
  sc_core::sc_start();
  EXPECT_EQ(rounds_done, kThreads);
  EXPECT_EQ(rejected, 0u);
  EXPECT_EQ(sys.mem.stored(), 10u);
  EXPECT_EQ(sys.mem.counters().full_rejections, 0u);
}

TEST(StreamScheduler, FullestFirstIsStickyWhileTheBufferHasRays) {
  StreamScheduler s(8, 100, 2, SchedulingPolicy::kFullestFirst, true);
  auto grow = [&](uint32_t t, uint32_t from, uint32_t to) {
    for (uint32_t i = from; i < to; ++i) s.resized(t, i, i + 1);
  };
  EXPECT_EQ(s.assign(0), StreamScheduler::kNone);
  grow(5, 0, 3);
  grow(2, 0, 1);
  grow(7, 0, 2);
  EXPECT_EQ(s.assign(0), 5u);
  s.resized(5, 3, 2);
  s.resized(5, 2, 1);  // 7 is fuller now, but TM 0 keeps 5 while it has rays
  EXPECT_EQ(s.assign(0), 5u);
  EXPECT_EQ(s.assign(1), 7u);  // a TM without a buffer gets the fullest
  s.resized(5, 1, 0);
  EXPECT_EQ(s.assign(0), 7u);
  StreamScheduler loose(8, 100, 1, SchedulingPolicy::kFullestFirst, false);
  for (uint32_t i = 0; i < 3; ++i) loose.resized(1, i, i + 1);
  for (uint32_t i = 0; i < 2; ++i) loose.resized(4, i, i + 1);
  EXPECT_EQ(loose.assign(0), 1u);
  loose.resized(1, 3, 2);
  loose.resized(1, 2, 1);
  EXPECT_EQ(loose.assign(0), 4u);  // not sticky: re-chosen at every assign
}

TEST(StreamScheduler, RoundRobinHandsOutNonEmptyBuffersInTurn) {
  StreamScheduler s(8, 100, 1, SchedulingPolicy::kRoundRobin, false);
  for (uint32_t t : {3u, 6u, 1u}) s.resized(t, 0, 1);
  EXPECT_EQ(s.assign(0), 3u);
  EXPECT_EQ(s.assign(0), 6u);
  EXPECT_EQ(s.assign(0), 1u);
  EXPECT_EQ(s.assign(0), 3u);
  s.resized(6, 1, 0);
  EXPECT_EQ(s.assign(0), 1u);
  EXPECT_EQ(s.assign(0), 3u);
  s.resized(1, 1, 0);
  s.resized(3, 1, 0);
  EXPECT_EQ(s.assign(0), StreamScheduler::kNone);
}

TEST(StreamScheduler, FullestFirstAlwaysPicksAFullestBufferUnderRandomTraffic) {
  constexpr uint32_t kTreelets = 50;
  StreamScheduler s(kTreelets, 1000, 1, SchedulingPolicy::kFullestFirst, false);
  std::vector<uint32_t> size(kTreelets, 0);
  std::mt19937 rng(7);
  uint32_t total = 0;
  for (int op = 0; op < 100000; ++op) {
    const auto t = static_cast<uint32_t>(rng() % kTreelets);
    if (rng() % 2 == 0 && total < 1000) {
      s.resized(t, size[t], size[t] + 1);
      ++size[t];
      ++total;
    } else if (size[t] > 0) {
      s.resized(t, size[t], size[t] - 1);
      --size[t];
      --total;
    }
    const uint32_t best = *std::max_element(size.begin(), size.end());
    const uint32_t chosen = s.assign(0);
    if (best == 0) ASSERT_EQ(chosen, StreamScheduler::kNone);
    else ASSERT_EQ(size[chosen], best) << "op " << op;
  }
}

}  // namespace
}  // namespace strata::memory::test
