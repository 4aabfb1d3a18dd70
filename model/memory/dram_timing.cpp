#include "model/memory/dram_timing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace strata::memory {

namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}
[[noreturn]] void bad(const std::string& field, const std::string& why, double got) {
  throw std::invalid_argument("dram.banked." + field + ": " + why + " (got " + num(got) + ")");
}
bool pow2(uint64_t v) { return v != 0 && (v & (v - 1)) == 0; }
void need_pow2(const char* field, uint64_t v) {
  if (!pow2(v)) bad(field, "must be a power of two", static_cast<double>(v));
}
// A time: finite, >= 0, and at most 1 ms (a longer one would stall the model for ever).
void need_time(const char* field, double ns, bool positive) {
  if (!(ns >= 0.0 && ns <= 1e6)) bad(field, "must be 0..1e6 ns", ns);
  if (positive && ns <= 0.0) bad(field, "must be > 0 ns", ns);
}
// A rule of the standard between two times: `field` >= `what` (= `sum`).
void need_at_least(const char* field, double v, const std::string& what, double sum) {
  if (v + 1e-9 < sum) bad(field, "must be at least " + what + " (" + num(sum) + " ns)", v);
}

uint32_t cycles(double ns, double ghz) {
  // Rounded up: a minimum time never shrinks. The epsilon keeps 14.0 ns at 1 GHz at 14.
  return static_cast<uint32_t>(std::ceil(ns * ghz - 1e-9));
}

}  // namespace

void DramTimingConfig::validate(uint32_t channel_bytes_per_cycle) const {
  need_pow2("ranks", ranks);
  need_pow2("bank_groups", bank_groups);
  need_pow2("banks_per_group", banks_per_group);
  // Each rank keeps calendars per bank group (dram_banked.h): bounded, as devices are (DDR5:
  // 2 ranks x 8 groups), so a hostile config cannot make thousands of them per channel.
  if (ranks > 8) bad("ranks", "must be at most 8", ranks);
  if (bank_groups > 16) bad("bank_groups", "must be at most 16", bank_groups);
  // In 64 bits: three large powers of two would wrap a 32-bit product to 0 and pass.
  const uint64_t banks = uint64_t{ranks} * bank_groups * banks_per_group;
  if (banks > 1024)
    bad("banks_per_group", "ranks x bank_groups x banks_per_group must be at most 1024", static_cast<double>(banks));
  need_pow2("column_bytes", column_bytes);
  need_pow2("row_bytes", row_bytes);
  if (row_bytes < column_bytes) bad("row_bytes", "must hold at least one column (column_bytes)", row_bytes);
  if (channel_bytes_per_cycle == 0 || column_bytes % channel_bytes_per_cycle != 0)
    bad("column_bytes", "must be a whole number of cycles of the channel's bus (dram.bytes_per_cycle / dram.channels = " +
                            std::to_string(channel_bytes_per_cycle) + ")",
        column_bytes);
  need_time("t_rcd_ns", t_rcd_ns, true);
  need_time("t_rp_ns", t_rp_ns, true);
  need_time("t_cl_ns", t_cl_ns, true);
  need_time("t_cwl_ns", t_cwl_ns, false);
  need_time("t_ras_ns", t_ras_ns, true);
  need_time("t_rc_ns", t_rc_ns, true);
  need_time("t_rrd_s_ns", t_rrd_s_ns, true);
  need_time("t_rrd_l_ns", t_rrd_l_ns, true);
  need_time("t_faw_ns", t_faw_ns, false);
  need_time("t_ccd_s_ns", t_ccd_s_ns, true);
  need_time("t_ccd_l_ns", t_ccd_l_ns, true);
  need_time("t_wr_ns", t_wr_ns, false);
  need_time("t_wtr_ns", t_wtr_ns, false);
  need_time("t_rtp_ns", t_rtp_ns, false);
  need_time("t_refi_ns", t_refi_ns, true);
  need_time("t_rfc_ns", t_rfc_ns, true);
  need_time("controller_ns", controller_ns, false);
  // The rules between them (JESD212 and every SDRAM standard before it): a bank's row cycle
  // covers its active and precharge times; a row stays open at least until its columns can
  // be read; the same bank group is never faster than another group; a refresh fits its
  // interval.
  need_at_least("t_rc_ns", t_rc_ns, "t_ras_ns + t_rp_ns", t_ras_ns + t_rp_ns);
  need_at_least("t_ras_ns", t_ras_ns, "t_rcd_ns", t_rcd_ns);
  need_at_least("t_rrd_l_ns", t_rrd_l_ns, "t_rrd_s_ns", t_rrd_s_ns);
  need_at_least("t_ccd_l_ns", t_ccd_l_ns, "t_ccd_s_ns", t_ccd_s_ns);
  need_at_least("t_faw_ns", t_faw_ns, "t_rrd_s_ns", t_rrd_s_ns);
  if (!(t_refi_ns > t_rfc_ns)) bad("t_refi_ns", "must be longer than t_rfc_ns (" + num(t_rfc_ns) + " ns)", t_refi_ns);
}

DramTiming DramTiming::at(const DramTimingConfig& c, double clock_ghz, uint32_t channel_bytes_per_cycle) {
  DramTiming t;
  t.rcd = cycles(c.t_rcd_ns, clock_ghz);
  t.rp = cycles(c.t_rp_ns, clock_ghz);
  t.cl = cycles(c.t_cl_ns, clock_ghz);
  t.cwl = cycles(c.t_cwl_ns, clock_ghz);
  t.ras = cycles(c.t_ras_ns, clock_ghz);
  t.rc = cycles(c.t_rc_ns, clock_ghz);
  t.rrd_s = cycles(c.t_rrd_s_ns, clock_ghz);
  t.rrd_l = cycles(c.t_rrd_l_ns, clock_ghz);
  t.faw = cycles(c.t_faw_ns, clock_ghz);
  t.ccd_s = cycles(c.t_ccd_s_ns, clock_ghz);
  t.ccd_l = cycles(c.t_ccd_l_ns, clock_ghz);
  t.wr = cycles(c.t_wr_ns, clock_ghz);
  t.wtr = cycles(c.t_wtr_ns, clock_ghz);
  t.rtp = cycles(c.t_rtp_ns, clock_ghz);
  t.refi = cycles(c.t_refi_ns, clock_ghz);
  t.rfc = cycles(c.t_rfc_ns, clock_ghz);
  t.controller = cycles(c.controller_ns, clock_ghz);
  // Rounding can make tREFI 0 cycles or no longer than tRFC at a slow clock: refreshes would
  // then never end (BankedDram would loop). One cycle of each interval stays usable.
  t.refi = std::max(t.refi, t.rfc + 1);
  t.burst = channel_bytes_per_cycle == 0 ? 1 : (c.column_bytes + channel_bytes_per_cycle - 1) / channel_bytes_per_cycle;
  return t;
}

}  // namespace strata::memory
