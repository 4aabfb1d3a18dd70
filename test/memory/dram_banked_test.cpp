// The banked DRAM model (memory.dram.model = banked) on one channel, against command timings
// worked out by hand at 1 GHz (1 ns = 1 cycle) from a set of timings of the tests' own
// (hand_timing(), apart from the preset so that the preset can follow its datasheet): tRCD 14,
// tRP 14, tCL 12, tRAS 32, tRC 46, tRRD_S 6 (5.5 ns rounded up), tRRD_L 6, tCCD_S 1, tCCD_L 2,
// tRTP 2, tREFI 1900, tRFC 110; a 32-byte column holds the 32 B/cycle bus for 1 cycle.
// One channel and no bank hash, so an address reads directly as row:bank:column: a 2 KB row,
// bank = (addr >> 11) & 15 (bank group = bank % 4), row = addr >> 15.
#include "memory_test_support.h"
#include "model/stats/stat_values.h"

#include "model/memory/dram.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace strata::memory::test {
namespace {

constexpr uint64_t kBank = 1u << 11, kRow = 1u << 15;
constexpr Cycle kRcd = 14, kCl = 12, kBurst = 1, kRc = 46, kRefi = 1900, kRfc = 110;

DramTimingConfig hand_timing() {
  DramTimingConfig t;
  t.t_rcd_ns = 14.0;
  t.t_rp_ns = 14.0;
  t.t_cl_ns = 12.0;
  t.t_cwl_ns = 3.5;
  t.t_ras_ns = 32.0;
  t.t_rc_ns = 46.0;
  t.t_rrd_s_ns = 5.5;
  t.t_rrd_l_ns = 6.0;
  t.t_faw_ns = 23.0;
  t.t_ccd_s_ns = 1.0;
  t.t_ccd_l_ns = 1.5;
  t.t_wr_ns = 12.0;
  t.t_wtr_ns = 5.0;
  t.t_rtp_ns = 2.0;
  t.t_refi_ns = 1900.0;
  t.t_rfc_ns = 110.0;
  return t;
}

DramConfig one_channel() {
  DramConfig c;
  c.model = DramModel::kBanked;
  c.banked = hand_timing();
  c.channels = 1;
  c.bytes_per_cycle = 32;
  c.hash_channels = false;
  c.banked.hash_banks = false;
  return c;
}

struct Rig {
  SparseMemory backing;
  Dram dram;
  RawInitiator port{"port"};
  explicit Rig(const DramConfig& c) : dram("dram", c, backing) { port.socket.bind(dram.target); }
  const BankedDram::ChannelCounters& k() const { return dram.banked()->channel(0); }
};

Sent read32(RawInitiator& p, uint64_t addr, Cycle at) {
  uint8_t buf[32] = {};
  return p.send(AccessClass::kDataLoad, addr, buf, 32, at, transport::kNoTreelet, true);
}

TEST(DramBanked, ReadToAClosedBankTakesRcdPlusClPlusBurst) {
  REQUIRE_FRESH_SYSTEMC();
  Rig rig(one_channel());
  Sent r;
  Script s("script", [&] { r = read32(rig.port, 0, 0); });
  sc_core::sc_start();
  EXPECT_EQ(r.done, kRcd + kCl + kBurst);  // ACT 0, RD 14, data 26
  EXPECT_EQ(r.served_by, ServedBy::kDram);
  EXPECT_EQ(rig.k().row_misses, 1u);
  EXPECT_EQ(rig.k().activates, 1u);
  EXPECT_EQ(rig.k().read_latency_cycles, 27u);
  // 27 cycles: the from_16 bucket (16-31); the bank was busy from the ACT (0) to the data's end.
  EXPECT_EQ(rig.k().read_latency_buckets[BankedDram::latency_bucket(27)], 1u);
  EXPECT_EQ(BankedDram::latency_bucket(27), 1u);
  EXPECT_EQ(rig.k().busy_bank_cycles, 27u);
  // An unclassified payload (no data class) counts as "other".
  EXPECT_EQ(rig.dram.banked()->by_data(transport::DataClass::kOther).misses, 1u);
  stats::Values v = stats::Values::snapshot(rig.dram.stats());
  v.derive();
  EXPECT_EQ(v.count("banked.channels.read_latency_histogram.from_16"), 1u);
  EXPECT_EQ(v.count("banked.rows_by_data.other.row_misses"), 1u);
  EXPECT_DOUBLE_EQ(v.number("banked.rows_by_data.other.row_hit_rate"), 0.0);
}

TEST(DramBanked, LatencyBucketsArePowersOfTwoFromSixteen) {
  EXPECT_EQ(BankedDram::latency_bucket(0), 0u);
  EXPECT_EQ(BankedDram::latency_bucket(15), 0u);
  EXPECT_EQ(BankedDram::latency_bucket(16), 1u);
  EXPECT_EQ(BankedDram::latency_bucket(31), 1u);
  EXPECT_EQ(BankedDram::latency_bucket(32), 2u);
  EXPECT_EQ(BankedDram::latency_bucket(2047), 7u);
  EXPECT_EQ(BankedDram::latency_bucket(2048), 8u);  // the last bucket: 2048 and more
  EXPECT_EQ(BankedDram::latency_bucket(1u << 30), BankedDram::kLatencyBuckets - 1);
}

TEST(DramBanked, RowHitTakesClPlusBurst) {
  REQUIRE_FRESH_SYSTEMC();
  Rig rig(one_channel());
  Sent first, hit;
  Script s("script", [&] {
    first = read32(rig.port, 0, 0);
    hit = read32(rig.port, 32, 100);  // the next column of the open row
  });
  sc_core::sc_start();
  EXPECT_EQ(first.done, 27u);
  EXPECT_EQ(hit.done, 100 + kCl + kBurst);
  EXPECT_EQ(rig.k().row_hits, 1u);
  EXPECT_EQ(rig.k().row_misses, 1u);
  stats::Values v = stats::Values::snapshot(rig.dram.stats());
  v.derive();
  EXPECT_EQ(v.count("banked.channels.row_hits"), 1u);
  EXPECT_DOUBLE_EQ(v.number("banked.channels.mean_read_latency_cycles"), (27.0 + 13.0) / 2);
}

TEST(DramBanked, ClosedPagePolicyMakesTheSecondAccessAMiss) {
  REQUIRE_FRESH_SYSTEMC();
  DramConfig c = one_channel();
  c.banked.row_policy = RowPolicy::kClosed;
  Rig rig(c);
  Sent second;
  Script s("script", [&] {
    read32(rig.port, 0, 0);
    second = read32(rig.port, 32, 100);  // precharged at 32 (tRAS), ready again at 46
  });
  sc_core::sc_start();
  EXPECT_EQ(second.done, 100 + kRcd + kCl + kBurst);
  EXPECT_EQ(rig.k().row_hits, 0u);
  EXPECT_EQ(rig.k().row_misses, 2u);
  EXPECT_EQ(rig.k().precharges, 2u);
}

TEST(DramBanked, BackToBackRowConflictsInOneBankAreSpacedByTrc) {
  REQUIRE_FRESH_SYSTEMC();
  Rig rig(one_channel());
  Sent r[3];
  Script s("script", [&] {
    for (int i = 0; i < 3; ++i) r[i] = read32(rig.port, i * kRow, 0);  // bank 0, rows 0, 1, 2
  });
  sc_core::sc_start();
  // PRE at ACT + tRAS (32), ACT at PRE + tRP = ACT + tRC (46): ACTs at 0, 46, 92.
  for (int i = 0; i < 3; ++i) EXPECT_EQ(r[i].done, i * kRc + kRcd + kCl + kBurst) << i;
  EXPECT_EQ(rig.k().row_conflicts, 2u);
  EXPECT_EQ(rig.k().precharges, 2u);
}

TEST(DramBanked, FawAllowsFourActivatesPerWindow) {
  REQUIRE_FRESH_SYSTEMC();
  DramConfig c = one_channel();
  c.banked.t_faw_ns = 40;  // longer than 4 x tRRD, so the window, not tRRD, holds the fifth
  Rig rig(c);
  Sent r[5];
  Script s("script", [&] {
    for (int i = 0; i < 5; ++i) r[i] = read32(rig.port, i * kBank, 0);  // banks 0..4, groups 0,1,2,3,0
  });
  sc_core::sc_start();
  // ACTs 6 apart (tRRD_S): 0, 6, 12, 18; the fifth waits for the first + tFAW = 40.
  const Cycle act[] = {0, 6, 12, 18, 40};
  for (int i = 0; i < 5; ++i) EXPECT_EQ(r[i].done, act[i] + kRcd + kCl + kBurst) << i;
}

// Activates booked in arrival order leave gaps a controller with a queue would fill. Bank 1's
// second request (another row) waits for its bank: PRE at tRAS 32, ACT at tRC 46, 34 cycles
// after the end of bank 2's tRRD slot [6, 12), 4 cycles more than five whole slots. Packed
// (it had to wait), it moves to 48, and a request that arrives last but is ready at 42 takes
// the slot [42, 48) left before it. Unpacked, that request finds [42, 48) cut by [46, 52)
// and waits until 52. Returns the four requests' ACT cycles.
std::vector<Cycle> queued_activates(bool pack) {
  DramConfig c = one_channel();
  c.banked.pack_activates = pack;
  Rig rig(c);
  Sent r[4];
  Script s("script", [&] {
    r[0] = read32(rig.port, 1 * kBank, 0);         // bank 1, row 0: ACT at 0, its slot [0, 6)
    r[1] = read32(rig.port, 2 * kBank, 4);         // bank 2: waits for the slot, ACT at 6
    r[2] = read32(rig.port, kRow + 1 * kBank, 0);  // bank 1, row 1: waits for its bank
    r[3] = read32(rig.port, 3 * kBank, 42);        // bank 3, ready at 42 but sent last
  });
  sc_core::sc_start();
  std::vector<Cycle> acts;
  for (const Sent& x : r) acts.push_back(x.done - (kRcd + kCl + kBurst));
  return acts;
}

TEST(DramBanked, ActivatesThatWaitedLeaveWholeTrrdSlotsBetweenThem) {
  REQUIRE_FRESH_SYSTEMC();
  EXPECT_EQ(queued_activates(true), (std::vector<Cycle>{0, 6, 48, 42}));  // no cycle lost
}

TEST(DramBanked, UnpackedActivatesWasteTheOddCyclesOfAGap) {
  REQUIRE_FRESH_SYSTEMC();
  EXPECT_EQ(queued_activates(false), (std::vector<Cycle>{0, 6, 46, 52}));  // [42, 46) unused
}

// With nothing queued, packing changes nothing: an ACT issued the moment its request arrives
// (its bank idle, its rank's tRRD slot free) stays there, 10 cycles after the previous one,
// although that gap is not a whole number of tRRD slots. Nothing else would use [6, 10).
TEST(DramBanked, ActivatesThatDidNotWaitAreNotMoved) {
  REQUIRE_FRESH_SYSTEMC();
  Rig rig(one_channel());  // packing on, the default
  Sent r[2];
  Script s("script", [&] {
    r[0] = read32(rig.port, 0 * kBank, 0);
    r[1] = read32(rig.port, 1 * kBank, 10);
  });
  sc_core::sc_start();
  EXPECT_EQ(r[0].done, 0 + kRcd + kCl + kBurst);
  EXPECT_EQ(r[1].done, 10 + kRcd + kCl + kBurst);
}

TEST(DramBanked, RefreshBlocksTheRankForTrfcAndClosesRows) {
  REQUIRE_FRESH_SYSTEMC();
  Rig rig(one_channel());
  Sent at_refresh, after;
  Script s("script", [&] {
    at_refresh = read32(rig.port, kBank, kRefi);  // closed bank, the refresh falls due now
    after = read32(rig.port, kBank + 32, 2 * kRefi + 50);  // its row was open; the 2nd refresh closed it
  });
  sc_core::sc_start();
  EXPECT_EQ(at_refresh.done, kRefi + kRfc + kRcd + kCl + kBurst);
  // Refresh 2 falls due at 3800 with bank 1's row open (PRE allowed since 2010 + tRAS): it
  // precharges at 3800 and refreshes at 3800 + tRP = 3814, until 3924.
  EXPECT_EQ(after.done, 2 * kRefi + 14 + kRfc + kRcd + kCl + kBurst);
  EXPECT_EQ(rig.k().refreshes, 2u);
  EXPECT_EQ(rig.k().refresh_cycles, 2 * kRfc);
  EXPECT_EQ(rig.k().row_misses, 2u);
}

TEST(DramBanked, WritesUseTcwlAndDelayAFollowingReadByTwtr) {
  REQUIRE_FRESH_SYSTEMC();
  Rig rig(one_channel());
  Sent w, r;
  Script s("script", [&] {
    uint8_t buf[32] = {};
    w = rig.port.send(AccessClass::kDataStore, 0, buf, 32, 0, transport::kNoTreelet, true);
    r = read32(rig.port, 32, 0);  // a row hit, but tWTR after the write's data
  });
  sc_core::sc_start();
  // WR at 14, data at 14 + tCWL (3.5 ns -> 4) = 18, ends 19; RD at 19 + tWTR 5 = 24, data 36.
  EXPECT_EQ(w.done, 19u);
  EXPECT_EQ(r.done, 24 + kCl + kBurst);
}

// Row hits that alternate bank groups issue a column per cycle (tCCD_S = 1): the bus's peak.
TEST(DramBanked, HitsAcrossBankGroupsStreamAtTheBusRate) {
  REQUIRE_FRESH_SYSTEMC();
  Rig rig(one_channel());
  std::vector<Sent> r;
  Script s("script", [&] {
    for (uint64_t b = 0; b < 4; ++b) read32(rig.port, b * kBank, 0);  // open a row in each group
    for (uint64_t i = 0; i < 64; ++i) r.push_back(read32(rig.port, (i % 4) * kBank + 32 * (1 + i / 4), 200));
  });
  sc_core::sc_start();
  for (uint64_t i = 0; i < 64; ++i) EXPECT_EQ(r[i].done, 200 + i + kCl + kBurst) << i;
  EXPECT_EQ(rig.k().row_hits, 64u);
}

// Random traffic over 8 channels: every request is exactly one of hit, miss or conflict, and
// each channel has refreshed once per tREFI up to its last request.
TEST(DramBanked, RandomTrafficCountsAddUpAndRefreshKeepsPace) {
  REQUIRE_FRESH_SYSTEMC();
  DramConfig c;
  c.model = DramModel::kBanked;
  c.banked = hand_timing();
  SparseMemory backing;
  Dram dram("dram", c, backing);
  RawInitiator port("port");
  port.socket.bind(dram.target);
  // Kept inside the bus calendars' horizon (16384 cycles; the script never advances time):
  // random rows are bound by tFAW, about 6 cycles per ACT per channel.
  constexpr uint64_t kRequests = 8000;
  Cycle last = 0;
  Script s("script", [&] {
    uint64_t x = 12345;
    uint8_t line[64];
    for (uint64_t k = 0; k < kRequests; ++k) {
      x = x * 6364136223846793005ull + 1442695040888963407ull;
      const uint64_t addr = ((x >> 20) % (256ull << 20)) & ~uint64_t{63};
      const AccessClass a = (x >> 60) == 0 ? AccessClass::kDataStore : AccessClass::kDataLoad;
      const Sent r = port.send(a, addr, line, 64, k / 2, transport::kNoTreelet, true);  // half the peak
      last = std::max(last, r.done);
    }
  });
  sc_core::sc_start();
  uint64_t requests = 0;
  for (uint32_t ch = 0; ch < c.channels; ++ch) {
    const BankedDram::ChannelCounters& k = dram.banked()->channel(ch);
    EXPECT_EQ(k.row_hits + k.row_misses + k.row_conflicts, dram.channel(ch).requests) << ch;
    EXPECT_EQ(k.reads + k.writes, 2 * dram.channel(ch).requests) << ch;  // 64 B = 2 columns
    EXPECT_LE(k.refreshes, last / kRefi) << ch;
    EXPECT_GE(k.refreshes + 1, (kRequests / 2) / kRefi) << ch;
    requests += dram.channel(ch).requests;
  }
  EXPECT_EQ(requests, kRequests);
  EXPECT_EQ(dram.overflow_bookings(), 0u);
  // The histogram's buckets sum to the reads, the data classes' outcomes to the requests, and
  // every request kept a bank busy for at least its own column and burst.
  uint64_t by_class = 0;
  for (unsigned i = 0; i < transport::kDataClassCount; ++i) {
    const BankedDram::RowOutcomes& o = dram.banked()->by_data(static_cast<transport::DataClass>(i));
    by_class += o.hits + o.misses + o.conflicts;
  }
  EXPECT_EQ(by_class, kRequests);
  for (uint32_t ch = 0; ch < c.channels; ++ch) {
    const BankedDram::ChannelCounters& k = dram.banked()->channel(ch);
    uint64_t bucketed = 0;
    for (const uint64_t n : k.read_latency_buckets) bucketed += n;
    EXPECT_EQ(bucketed, k.read_requests) << ch;
    EXPECT_GE(k.busy_bank_cycles, dram.channel(ch).requests * 2 * kBurst) << ch;  // two columns each
  }
}

// Temporal decoupling: a TM that ran ahead sends its request first. A request that arrives
// later in call order but is earlier in time takes the earlier gap in the rank's calendars and
// goes before a refresh that its predecessor triggered, instead of queueing behind both.
TEST(DramBanked, AnEarlierRequestArrivingLaterIsNotQueuedBehindLaterOnes) {
  REQUIRE_FRESH_SYSTEMC();
  Rig rig(one_channel());
  Sent late, early, before_refresh;
  Script s("script", [&] {
    late = read32(rig.port, 1 * kBank, kRefi + 50);  // refresh at 1900..2010, then ACT 2010
    early = read32(rig.port, 2 * kBank, 500);        // another bank: ACT at 500
    before_refresh = read32(rig.port, 3 * kBank, kRefi - 100);  // ACT at 1800, before the refresh
  });
  sc_core::sc_start();
  EXPECT_EQ(late.done, kRefi + kRfc + kRcd + kCl + kBurst);
  EXPECT_EQ(early.done, 500 + kRcd + kCl + kBurst);
  EXPECT_EQ(before_refresh.done, kRefi - 100 + kRcd + kCl + kBurst);
}

// The same within one bank: a request whose whole row cycle (tRC) fits before the bank's
// later ACT is served there, as a miss, and the bank's later state (its open row) stays.
TEST(DramBanked, AnEarlierRequestToABankUsedLaterIsServedBeforeIt) {
  REQUIRE_FRESH_SYSTEMC();
  Rig rig(one_channel());
  Sent later_one, earlier, too_close, hit;
  Script s("script", [&] {
    later_one = read32(rig.port, 0, 500);      // bank 0, row 0: ACT 500
    earlier = read32(rig.port, kRow, 100);     // bank 0, row 1, at 100: ACT 100, done by 146 < 500
    too_close = read32(rig.port, 2 * kRow, 480);  // 480 + tRC > 500: queues behind (a conflict)
    hit = read32(rig.port, 2 * kRow + 32, 700);   // row 2 is open now
  });
  sc_core::sc_start();
  EXPECT_EQ(later_one.done, 500 + kRcd + kCl + kBurst);
  EXPECT_EQ(earlier.done, 100 + kRcd + kCl + kBurst);
  // PRE at 500 + tRAS = 532, ACT at 546 (= 500 + tRC).
  EXPECT_EQ(too_close.done, 500 + kRc + kRcd + kCl + kBurst);
  EXPECT_EQ(hit.done, 700 + kCl + kBurst);
  EXPECT_EQ(rig.k().row_misses, 2u);
  EXPECT_EQ(rig.k().row_conflicts, 1u);
  EXPECT_EQ(rig.k().row_hits, 1u);
}

TEST(DramBanked, AddressMapHashesBanksAndSpreadsTreeletAlignedRows) {
  REQUIRE_FRESH_SYSTEMC();
  DramConfig c = one_channel();
  c.banked.hash_banks = true;
  SparseMemory backing;
  Dram dram("dram", c, backing);
  const BankedDram& b = *dram.banked();
  EXPECT_EQ(b.locate(5 * kBank + 3 * kRow).bank, 5u ^ 3u);
  EXPECT_EQ(b.locate(5 * kBank + 3 * kRow).row, 3u);
  EXPECT_EQ(b.locate(5 * kBank + 3 * kRow).group, (5u ^ 3u) % 4);
  // 32 KB-aligned treelets (one row apart here) no longer all open rows in bank 0.
  EXPECT_NE(b.locate(0).bank, b.locate(kRow).bank);
}

TEST(DramBanked, ThePresetPassesTheRulesAndGives256GBPerSecond) {
  DramConfig c;
  c.model = DramModel::kBanked;
  EXPECT_NO_THROW(c.validate());
  // 8 channels x one 32-byte column per cycle (tCCD_S = 1 ns) at 1 GHz.
  EXPECT_EQ(c.channels * c.banked.column_bytes, 256u);
  EXPECT_EQ(DramTiming::at(c.banked, 1.0, c.channel_bytes_per_cycle()).burst, 1u);
  EXPECT_EQ(c.bytes_per_cycle, 256u);
}

// The preset is the cited part (docs/memory-system.md, "Banked DRAM"): the array timings of
// SK hynix's H5GQ1H24AFR GDDR5 datasheet (as gem5's GDDR5_4000_2x32 transcribes it; Ramulator's
// GDDR5 speed table keeps the same nanoseconds from 4 to 7 Gbit/s), the 8 Gbit part's
// organisation and refresh from Micron's MT51J256M32 brief, and the standard's rules between
// them hold exactly where the standard fixes them.
TEST(DramBanked, ThePresetIsTheCitedGddr5Part) {
  const DramTimingConfig t;
  const double tck = 0.5;  // CK 2 GHz at 8 Gbit/s per pin (data at 4x CK)
  EXPECT_EQ(t.banks(), 16u);
  EXPECT_EQ(t.bank_groups, 4u);
  EXPECT_DOUBLE_EQ(t.t_rcd_ns, 12.0);
  EXPECT_DOUBLE_EQ(t.t_rp_ns, 12.0);
  EXPECT_DOUBLE_EQ(t.t_ras_ns, 28.0);
  EXPECT_DOUBLE_EQ(t.t_rc_ns, t.t_ras_ns + t.t_rp_ns);  // 40 ns, the datasheet's minimum row cycle
  EXPECT_DOUBLE_EQ(t.t_rrd_s_ns, 5.5);
  EXPECT_DOUBLE_EQ(t.t_rrd_l_ns, 5.5);
  EXPECT_DOUBLE_EQ(t.t_faw_ns, 23.0);
  EXPECT_DOUBLE_EQ(t.t_wr_ns, 12.0);
  EXPECT_DOUBLE_EQ(t.t_wtr_ns, 5.0);
  EXPECT_DOUBLE_EQ(t.t_rtp_ns, 2 * tck);
  EXPECT_DOUBLE_EQ(t.t_ccd_s_ns, 2 * tck);  // BL8 at four beats per CK
  EXPECT_DOUBLE_EQ(t.t_ccd_l_ns, 3 * tck);  // Micron: tCCDL = 3 tCK
  EXPECT_DOUBLE_EQ(t.t_cl_ns, 24 * tck);    // Micron: CL up to 24
  EXPECT_DOUBLE_EQ(t.t_cwl_ns, 7 * tck);    // Micron: WL up to 7
  EXPECT_DOUBLE_EQ(t.t_refi_ns, 32e6 / 16384);  // Micron: 16,384 refreshes per 32 ms
  EXPECT_DOUBLE_EQ(t.t_rfc_ns, 184.0);
  DramConfig c;
  c.model = DramModel::kBanked;
  EXPECT_NO_THROW(c.validate());
}

// At a slow clock both round up to one cycle; a refresh must still leave time between them.
TEST(DramBanked, RoundingKeepsTheRefreshIntervalLongerThanTheRefresh) {
  DramTimingConfig t;
  t.t_rfc_ns = 110.0;
  t.t_refi_ns = 110.5;
  const DramTiming slow = DramTiming::at(t, 0.001, 32);
  EXPECT_EQ(slow.rfc, 1u);
  EXPECT_EQ(slow.refi, 2u);
  const DramTiming fast = DramTiming::at(hand_timing(), 1.0, 32);
  EXPECT_EQ(fast.refi, 1900u);
  EXPECT_EQ(fast.rrd_s, 6u);  // 5.5 ns rounds up
}

TEST(DramBanked, InconsistentTimingsAreRefusedNamingTheField) {
  const struct {
    void (*change)(DramTimingConfig&);
    const char* expected;
  } cases[] = {
      {[](DramTimingConfig& t) { t.t_rc_ns = 40; }, "dram.banked.t_rc_ns: must be at least t_ras_ns + t_rp_ns (46 ns)"},
      {[](DramTimingConfig& t) { t.t_ras_ns = 10; }, "dram.banked.t_ras_ns: must be at least t_rcd_ns"},
      {[](DramTimingConfig& t) { t.t_rrd_l_ns = 5; }, "dram.banked.t_rrd_l_ns: must be at least t_rrd_s_ns"},
      {[](DramTimingConfig& t) { t.t_ccd_l_ns = 0.5; }, "dram.banked.t_ccd_l_ns: must be at least t_ccd_s_ns"},
      {[](DramTimingConfig& t) { t.t_rfc_ns = 5000; }, "dram.banked.t_refi_ns: must be longer than t_rfc_ns"},
      {[](DramTimingConfig& t) { t.t_cl_ns = -1; }, "dram.banked.t_cl_ns: must be 0..1e6 ns"},
      {[](DramTimingConfig& t) { t.bank_groups = 3; }, "dram.banked.bank_groups: must be a power of two"},
      {[](DramTimingConfig& t) { t.column_bytes = 16; }, "dram.banked.column_bytes: must be a whole number of cycles"},
      {[](DramTimingConfig& t) { t.row_bytes = 16; }, "dram.banked.row_bytes: must hold at least one column"},
      {[](DramTimingConfig& t) { t.ranks = 16; }, "dram.banked.ranks: must be at most 8"},
      {[](DramTimingConfig& t) { t.bank_groups = 32; }, "dram.banked.bank_groups: must be at most 16"},
      // 8 x 16 x 2^28 banks: a 32-bit product wraps to 0.
      {[](DramTimingConfig& t) {
         t.ranks = 8;
         t.bank_groups = 16;
         t.banks_per_group = 1u << 28;
       },
       "dram.banked.banks_per_group: ranks x bank_groups x banks_per_group"},
  };
  for (const auto& c : cases) {
    DramConfig config;
    config.model = DramModel::kBanked;
    config.banked = hand_timing();
    c.change(config.banked);
    std::string e;
    try {
      config.validate();
    } catch (const std::invalid_argument& x) {
      e = x.what();
    }
    EXPECT_NE(e.find(c.expected), std::string::npos) << e;
  }
  // The channel model ignores the banked fields.
  DramConfig channel;
  channel.banked.t_rc_ns = 1;
  EXPECT_NO_THROW(channel.validate());
}

}  // namespace
}  // namespace strata::memory::test
