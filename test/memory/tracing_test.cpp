// VCD tracing: key state per time window lands in the trace file when tracing is on.
#include "memory_test_support.h"

#include "model/memory/dram.h"
#include "model/memory/interconnect.h"
#include "model/memory/l1_data_cache.h"
#include "model/memory/l1_instruction_cache.h"
#include "model/memory/l2_cache.h"
#include "model/memory/stream_memory.h"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace strata::memory::test {
namespace {

TEST(Tracing, DramWritesBandwidthAndQueueDepthPerWindowToVcd) {
  REQUIRE_FRESH_SYSTEMC();
  const std::string base = ::testing::TempDir() + "strata_dram_trace";
  SparseMemory backing;
  Dram dram("dram", DramConfig{}, backing);
  RawInitiator port("port");
  port.socket.bind(dram.target);
  sc_core::sc_trace_file* vcd = sc_core::sc_create_vcd_trace_file(base.c_str());
  dram.trace(vcd, 100);
  Script s("script", [&] {
    uint8_t line[64];
    for (Cycle k = 0; k < 5000; ++k) {  // saturating bursts into channel 0 for 5000 cycles
      port.send(AccessClass::kDataLoad, (k % 4) * 64, line, 64, k, transport::kNoTreelet, true);
      if (k % 10 == 9) sc_core::wait(port.clock.duration(10));
    }
  });
  sc_core::sc_start();
  sc_core::sc_close_vcd_trace_file(vcd);
  std::ifstream in(base + ".vcd");
  ASSERT_TRUE(in.good());
  std::stringstream text;
  text << in.rdbuf();
  const std::string vcd_text = text.str();
  // SystemC turns the dotted names into VCD scopes: dram / channel0 / bytes_per_cycle.
  EXPECT_NE(vcd_text.find("channel0"), std::string::npos);
  EXPECT_NE(vcd_text.find("bytes_per_cycle"), std::string::npos);
  EXPECT_NE(vcd_text.find("queue_cycles"), std::string::npos);
  // One 64 B line per cycle into one channel: 64 B/cycle offered, 32 served, the rest queues.
  EXPECT_NE(vcd_text.find("r64 "), std::string::npos) << "bandwidth sample of 64 B/cycle expected";
  if (!HasFailure()) std::remove((base + ".vcd").c_str());
}

TEST(Tracing, EveryModuleTracesItsKeyStateWhenAsked) {
  REQUIRE_FRESH_SYSTEMC();
  const std::string base = ::testing::TempDir() + "strata_memory_trace";
  SparseMemory backing;
  L1DataCache l1d("l1d", L1DataCacheConfig{}, backing);
  L1InstructionCache l1i("l1i", L1InstructionCacheConfig{}, backing);
  InterconnectConfig xc;
  xc.tm_ports = 2;
  Interconnect xbar("xbar", xc);
  L2Cache l2("l2", L2Config{}, backing);
  Dram dram("dram", DramConfig{}, backing);
  StreamMemory stream("stream", StreamMemoryConfig{});
  RawInitiator data("data"), code("code"), rays("rays");
  Fanin to_stream("to_stream");
  data.socket.bind(l1d.target);
  code.socket.bind(l1i.target);
  l1d.downstream.bind(xbar.tm_side);
  l1i.downstream.bind(xbar.tm_side);
  xbar.l2_side.bind(l2.target);
  xbar.stream_side.bind(to_stream.in);
  rays.socket.bind(to_stream.in);
  to_stream.out.bind(stream.target);
  l2.downstream.bind(dram.target);
  sc_core::sc_trace_file* vcd = sc_core::sc_create_vcd_trace_file(base.c_str());
  l1d.trace(vcd, 50);
  l1i.trace(vcd, 50);
  xbar.trace(vcd, 50);
  l2.trace(vcd, 50);
  dram.trace(vcd, 50);
  stream.trace(vcd, 50);
  Script s("script", [&] {
    uint32_t ray[12] = {};
    for (Cycle k = 0; k < 400; ++k) {
      data.load(k * 64, k);
      code.fetch(k * 4, k);
      rays.send(AccessClass::kStreamPush, 0, ray, 48, k, static_cast<uint32_t>(k % 8));
      sc_core::wait(data.clock.duration(1));
    }
  });
  sc_core::sc_start();
  sc_core::sc_close_vcd_trace_file(vcd);
  std::ifstream in(base + ".vcd");
  std::stringstream text;
  text << in.rdbuf();
  const std::string v = text.str();
  for (const char* name : {"l1d", "l1i", "xbar", "l2", "dram", "stream", "accesses_per_cycle", "misses_per_cycle",
                           "bank_conflicts_per_cycle", "fetches_per_cycle", "bytes_per_cycle", "conflicts_per_cycle",
                           "queue_cycles", "stored_rays", "pushes_per_cycle", "full_rejections_per_cycle"})
    EXPECT_NE(v.find(name), std::string::npos) << name;
  EXPECT_EQ(stream.stored(), 400u);
  if (!HasFailure()) std::remove((base + ".vcd").c_str());
}

}  // namespace
}  // namespace strata::memory::test
