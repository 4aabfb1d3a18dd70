// The interconnect on its own: TMs as scripted initiators, the L2 and the stream memory as
// fixed-latency sinks (10 cycles). 4 TM ports, 16 L2 banks, 64 B links, 1-cycle hops.
#include "memory_test_support.h"

#include "model/memory/interconnect.h"

#include <memory>

namespace strata::memory::test {
namespace {

struct XbarBench {
  Interconnect xbar;
  std::vector<std::unique_ptr<RawInitiator>> tm;
  LatencySink l2{"l2", 10};
  LatencySink stream{"stream", 10};
  XbarBench() : xbar("xbar", config()) {
    for (uint32_t i = 0; i < 4; ++i) {
      tm.push_back(std::make_unique<RawInitiator>(("tm" + std::to_string(i)).c_str(), i * 32, i));
      tm.back()->socket.bind(xbar.tm_side);  // binding order = port index
    }
    xbar.l2_side.bind(l2.socket);
    xbar.stream_side.bind(stream.socket);
  }
  static InterconnectConfig config() {
    InterconnectConfig c;
    c.tm_ports = 4;
    return c;
  }
};

TEST(Interconnect, RoutesAndChargesHopsPortsAndLinks) {
  REQUIRE_FRESH_SYSTEMC();
  XbarBench b;
  std::vector<Sent> r;
  Script s("script", [&] {
    r.push_back(b.tm[0]->load(0, 0));           // port 0, hop, L2 10, link, hop: 13
    r.push_back(b.tm[0]->load(0, 100));         // port 0 at 100: 113
    r.push_back(b.tm[0]->load(64, 100));        // port 0 busy: granted 101, bank 1: 114
    r.push_back(b.tm[1]->load(3 * 64, 200));    // bank 3 from TM 1: 213
    r.push_back(b.tm[2]->load(3 * 64 + 8, 200));  // bank 3 from TM 2: return link busy: 214
    r.push_back(b.tm[3]->store(5 * 64, 300, 64));  // data in: link 301, L2 at 302, 312, hop: 313
    uint8_t ray[48] = {};
    r.push_back(b.tm[0]->send(AccessClass::kStreamPush, 0, ray, 48, 400, 7));  // to the stream memory: 413
  });
  sc_core::sc_start();
  const Cycle expected[] = {13, 113, 114, 213, 214, 313, 413};
  for (std::size_t i = 0; i < 7; ++i) EXPECT_EQ(r[i].done, expected[i]) << i;
  ASSERT_EQ(b.l2.seen.size(), 6u);
  EXPECT_EQ(b.l2.seen[5].cycle, 302u);
  EXPECT_EQ(b.l2.seen[5].command, tlm::TLM_WRITE_COMMAND);
  ASSERT_EQ(b.stream.seen.size(), 1u);
  EXPECT_EQ(b.stream.seen[0].access, AccessClass::kStreamPush);
  const auto& c = b.xbar.counters();
  EXPECT_EQ(c.transfers, 7u);
  EXPECT_EQ(c.l2_transfers, 6u);
  EXPECT_EQ(c.stream_transfers, 1u);
  EXPECT_EQ(c.port_conflicts, 1u);
  EXPECT_EQ(c.link_conflicts, 1u);
  EXPECT_EQ(c.bytes, 4u * 5 + 64 + 48);
}

TEST(Interconnect, BankOfMatchesTheL2LineInterleaving) {
  REQUIRE_FRESH_SYSTEMC();
  XbarBench b;
  EXPECT_EQ(b.xbar.bank_of(0), 0u);
  EXPECT_EQ(b.xbar.bank_of(63), 0u);
  EXPECT_EQ(b.xbar.bank_of(64), 1u);
  EXPECT_EQ(b.xbar.bank_of(16 * 64), 1u);  // hashed: line 16 folds to 1 ^ 0
  // The crossbar routes each line to the bank the L2 looks it up in.
  const BankInterleave l2_banks(16, true);
  for (uint64_t addr = 0; addr < (4u << 20); addr += 64 * 37) EXPECT_EQ(b.xbar.bank_of(addr), l2_banks.bank(addr / 64)) << addr;
  Script s("script", [] {});
  sc_core::sc_start();
}

TEST(Interconnect, LowBitBankOfWhenTheL2DoesNotHash) {
  REQUIRE_FRESH_SYSTEMC();
  InterconnectConfig c = XbarBench::config();
  c.l2_hash_banks = false;
  Interconnect xbar("xbar", c);
  EXPECT_EQ(xbar.bank_of(16 * 64), 0u);
  EXPECT_EQ(xbar.bank_of(17 * 64), 1u);
}

}  // namespace
}  // namespace strata::memory::test
