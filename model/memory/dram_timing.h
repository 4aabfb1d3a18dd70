// The banked DRAM's organisation and command timing (memory.dram.banked.*), typed as the
// datasheets give them: times in nanoseconds, converted once to chip cycles (rounded up, as
// a controller rounds a minimum time to whole clocks) by DramTiming::at(). The defaults are the
// GDDR5 preset: 8 Gbit/s per pin, x32 devices, one device per channel, so 8 channels give
// 8 x 32 GB/s = 256 GB/s, the STRaTA paper's DRAM bandwidth. docs/memory-system.md ("Banked
// DRAM") gives where each value comes from. validate() checks the rules the standard sets between them
// (tRC >= tRAS + tRP, ...) and names the field that breaks one.
#pragma once

#include <cstdint>

namespace strata::memory {

enum class RowPolicy : uint8_t {
  kOpen,    // a row stays open after an access: the next access to it is a row hit
  kClosed,  // every access precharges its bank after its last column command (auto-precharge)
};

struct DramTimingConfig {
  // Organisation of one channel. A channel is one x32 GDDR5 device here: 16 banks in 4 bank
  // groups, 2 KB rows (JESD212, 8 Gb x32 organisation).
  uint32_t ranks = 1;
  uint32_t bank_groups = 4;
  uint32_t banks_per_group = 4;
  uint32_t row_bytes = 2048;
  // Bytes one column command (RD or WR) moves: the device width x burst length (x32 x BL8).
  uint32_t column_bytes = 32;
  // true: the bank index is XOR-folded with the low row bits, so rows that differ only above
  // the bank bits (a power-of-two stride) spread over banks instead of conflicting in one.
  bool hash_banks = true;
  RowPolicy row_policy = RowPolicy::kOpen;
  // true: an ACT that had to wait (its bank or its rank busy when it was ready) and comes less
  // than tRC after its rank's previous ACT is placed so that the gap between them (where tFAW
  // allows an ACT) is a whole number of tRRD_S slots, as a controller with requests queued
  // issues activates back to back (dram_banked.cpp, packed_act); it moves by under tRRD_S.
  // An ACT issued the moment its request was ready does not move.
  // false: each ACT at the first cycle it fits, which wastes the odd cycles of every gap.
  bool pack_activates = true;

  // Minimum times, ns. GDDR5 at 8 Gbit/s: CK 2 GHz, tCK 0.5 ns. The array timings are SK
  // hynix's H5GQ1H24AFR datasheet (as gem5's GDDR5_4000_2x32 transcribes it; Ramulator's
  // GDDR5 speed table keeps the same ns from 4 to 7 Gbit/s, so they are taken at 8 as well);
  // tCK multiples and refresh from Micron's 8 Gb MT51J256M32 brief. docs/memory-system.md,
  // "Banked DRAM", gives each source.
  double t_rcd_ns = 12.0;   // ACT to RD/WR, same bank
  double t_rp_ns = 12.0;    // PRE to ACT, same bank
  double t_cl_ns = 12.0;    // RD to first data (CL 24 tCK)
  double t_cwl_ns = 3.5;    // WR to first data (WL 7 tCK)
  double t_ras_ns = 28.0;   // ACT to PRE, same bank
  double t_rc_ns = 40.0;    // ACT to ACT, same bank (tRAS + tRP)
  double t_rrd_s_ns = 5.5;  // ACT to ACT, other bank group of the rank
  double t_rrd_l_ns = 5.5;  // ACT to ACT, same bank group
  double t_faw_ns = 23.0;   // at most four ACTs per rank in any window this long
  double t_ccd_s_ns = 1.0;  // RD to RD (WR to WR), other bank group (2 tCK)
  double t_ccd_l_ns = 1.5;  // ... same bank group (3 tCK)
  double t_wr_ns = 12.0;    // end of write data to PRE
  double t_wtr_ns = 5.0;    // end of write data to RD, same rank
  double t_rtp_ns = 1.0;    // RD to PRE (2 tCK)
  double t_refi_ns = 1953.125;  // average interval between all-bank refreshes: 32 ms / 16,384
  double t_rfc_ns = 184.0;      // REF to the next command: the whole rank is busy (Ramulator's)
  // Added to every request before its first command: the controller's queues and PHY, and
  // the wires to the device. 0: the request reaches the device's command bus at once.
  double controller_ns = 0.0;

  uint32_t banks() const { return ranks * bank_groups * banks_per_group; }
  // Throws std::invalid_argument naming the field ("dram.banked.t_rc_ns: ...").
  // channel_bytes_per_cycle: the data bus width; a column's burst must fit whole cycles.
  void validate(uint32_t channel_bytes_per_cycle) const;
};

// The same times in chip cycles, as the model uses them.
struct DramTiming {
  uint32_t rcd = 0, rp = 0, cl = 0, cwl = 0, ras = 0, rc = 0, rrd_s = 0, rrd_l = 0, faw = 0;
  uint32_t ccd_s = 0, ccd_l = 0, wr = 0, wtr = 0, rtp = 0, refi = 0, rfc = 0, controller = 0;
  uint32_t burst = 1;  // cycles one column's data holds the channel's data bus
  static DramTiming at(const DramTimingConfig& c, double clock_ghz, uint32_t channel_bytes_per_cycle);
};

}  // namespace strata::memory
