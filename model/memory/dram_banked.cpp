#include "model/memory/dram_banked.h"

#include "model/stats/stat_values.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace strata::memory {

namespace {
uint32_t log2_of(uint64_t pow2) {
  uint32_t n = 0;
  while ((uint64_t{1} << n) < pow2) ++n;
  return n;
}
using transport::Cycle;
Cycle later(Cycle a, Cycle b) { return a > b ? a : b; }
}  // namespace

BankedDram::Rank::Rank(uint32_t groups, uint32_t horizon)
    : acts(1, horizon), columns(1, horizon), window(4, horizon) {
  group_acts.reserve(groups);
  group_columns.reserve(groups);
  for (uint32_t g = 0; g < groups; ++g) {
    group_acts.emplace_back(1, horizon);
    group_columns.emplace_back(1, horizon);
  }
}

BankedDram::BankedDram(const DramConfig& config)
    : config_(config),
      timing_(DramTiming::at(config.banked, 1.0, config.channel_bytes_per_cycle())),
      stats_("banked", "Banked DRAM (memory.dram.model = banked): row buffers, commands and refresh.") {
  const DramTimingConfig& b = config_.banked;
  interleave_shift_ = log2_of(config_.interleave_bytes);
  column_shift_ = log2_of(b.row_bytes);
  bank_bits_ = log2_of(b.banks());
  channels_.resize(config_.channels);
  for (Channel& ch : channels_) {
    ch.banks.resize(b.banks());
    ch.ranks.reserve(b.ranks);
    for (uint32_t r = 0; r < b.ranks; ++r) ch.ranks.emplace_back(b.bank_groups, config_.calendar_horizon_cycles);
  }
  set_clock_ghz(1.0);
  counters_.resize(config_.channels);

  using stats::Unit;
  std::vector<const stats::Group*> each;
  for (uint32_t c = 0; c < config_.channels; ++c) {
    ChannelCounters& k = counters_[c];
    auto g = std::make_unique<stats::Group>("channel" + std::to_string(c), "The banked DRAM's channels.");
    g->count("row_hits", &k.row_hits, Unit::kCount, "Requests whose row was open in its bank.");
    g->count("row_misses", &k.row_misses, Unit::kCount, "Requests to a closed (precharged) bank: an ACT first.");
    g->count("row_conflicts", &k.row_conflicts, Unit::kCount,
             "Requests to a bank with another row open: a PRE and an ACT first.");
    g->count("activates", &k.activates, Unit::kCount, "ACT commands.");
    g->count("precharges", &k.precharges, Unit::kCount, "PRE commands (closed page: one per request).");
    g->count("read_commands", &k.reads, Unit::kCount, "RD commands, one per column (column_bytes).");
    g->count("write_commands", &k.writes, Unit::kCount, "WR commands, one per column (column_bytes).");
    g->count("refreshes", &k.refreshes, Unit::kCount, "All-bank refreshes, every tREFI per rank up to the last request.");
    g->count("refresh_cycles", &k.refresh_cycles, Unit::kCycles,
             "Cycles ranks spent refreshing (tRFC per refresh), summed over ranks.");
    g->count("read_requests", &k.read_requests, Unit::kCount, "Read requests.");
    g->count("read_latency_cycles", &k.read_latency_cycles, Unit::kCycles,
             "Cycles from each read request to its last data, summed.");
    g->ratio("mean_read_latency_cycles", "read_latency_cycles", {"read_requests"},
             "Mean cycles from a read request to its last data (cycles, though a ratio).");
    g->count("busy_bank_cycles", &k.busy_bank_cycles, Unit::kCycles,
             "Cycles from each request's first command (PRE, ACT or column) to its last data, summed.");
    // Over the frame's simulated time (Little's law): the mean number of requests being served
    // (banks busy at once) and of reads waiting or being served (the request queue's occupancy).
    const auto per_frame_cycle = [](const char* what) {
      return [what](const stats::Scope& sc) {
        const stats::Values& root = sc.root();
        const double cycles = root.has("frame.cycles") ? root.number("frame.cycles") : 0.0;
        return cycles > 0 ? sc.self().number(what) / cycles : std::nan("");
      };
    };
    g->derived("bank_level_parallelism", Unit::kRatio,
               "busy_bank_cycles / frame cycles: requests in service at once, on average (banks busy).",
               per_frame_cycle("busy_bank_cycles"));
    g->derived("mean_reads_in_flight", Unit::kRatio,
               "read_latency_cycles / frame cycles: reads queued or in service at once, on average (Little's law).",
               per_frame_cycle("read_latency_cycles"));
    auto h = std::make_unique<stats::Group>(
        "read_latency_histogram", "Read requests by latency (request to last data): below_16, then from_N holds N to "
                                  "2N - 1 cycles (N a power of two); the last bucket has no upper end. The buckets "
                                  "sum to read_requests.");
    for (unsigned bucket = 0; bucket < kLatencyBuckets; ++bucket) {
      const uint64_t from = kFirstLatencyBucket << (bucket > 0 ? bucket - 1 : 0);
      const std::string name = bucket == 0 ? "below_" + std::to_string(kFirstLatencyBucket) : "from_" + std::to_string(from);
      const std::string what = bucket == 0                       ? "Reads of fewer than " + std::to_string(from) + " cycles."
                               : bucket + 1 < kLatencyBuckets ? "Reads of " + std::to_string(from) + " to " +
                                                               std::to_string(2 * from - 1) + " cycles."
                                                         : "Reads of " + std::to_string(from) + " cycles or more.";
      h->count(name.c_str(), &k.read_latency_buckets[bucket], Unit::kCount, what.c_str());
    }
    g->child(h.get());
    owned_groups_.push_back(std::move(h));
    each.push_back(g.get());
    channel_stats_.push_back(std::move(g));
  }
  stats_.instances("channels", each, "channel", "Banked DRAM channel");
  auto by_data = std::make_unique<stats::Group>(
      "rows_by_data", "Row outcomes of the requests, by what the addressed bytes hold; the classes sum to the "
                      "channels' row_hits, row_misses and row_conflicts.");
  for (unsigned i = 0; i < transport::kDataClassCount; ++i) {
    const auto c = static_cast<transport::DataClass>(i);
    auto g = std::make_unique<stats::Group>(transport::data_class_name(c), "Requests for data of this class.");
    g->count("row_hits", &by_data_[i].hits, Unit::kCount, "Requests whose row was open.");
    g->count("row_misses", &by_data_[i].misses, Unit::kCount, "Requests to a closed bank.");
    g->count("row_conflicts", &by_data_[i].conflicts, Unit::kCount, "Requests to a bank with another row open.");
    g->derived("row_hit_rate", Unit::kRatio, "row_hits / (row_hits + row_misses + row_conflicts).",
               [](const stats::Scope& sc) {
                 const stats::Values& v = sc.self();
                 const double n = v.number("row_hits") + v.number("row_misses") + v.number("row_conflicts");
                 return n > 0 ? v.number("row_hits") / n : std::nan("");
               });
    by_data->child(g.get());
    owned_groups_.push_back(std::move(g));
  }
  stats_.child(by_data.get());
  owned_groups_.push_back(std::move(by_data));
}

void BankedDram::set_clock_ghz(double ghz) {
  timing_ = DramTiming::at(config_.banked, ghz, config_.channel_bytes_per_cycle());
  // Ranks refresh in turn, spread over the interval, so the channel is never blocked whole.
  for (Channel& ch : channels_)
    for (uint32_t r = 0; r < ch.ranks.size(); ++r)
      ch.ranks[r].next_refresh = timing_.refi + uint64_t{r} * timing_.refi / ch.ranks.size();
}

BankedDram::Location BankedDram::locate(uint64_t addr) const {
  // Take the channel's bits out (channel is the lowest field above the interleave block), so
  // consecutive blocks of one channel are consecutive in its rows.
  const uint64_t block = addr >> interleave_shift_;
  const uint64_t local =
      ((block / config_.channels) << interleave_shift_) | (addr & ((uint64_t{1} << interleave_shift_) - 1));
  const uint64_t bank_mask = (uint64_t{1} << bank_bits_) - 1;
  Location at;
  at.row = local >> (column_shift_ + bank_bits_);
  uint64_t bank = (local >> column_shift_) & bank_mask;
  if (config_.banked.hash_banks) bank ^= at.row & bank_mask;  // rows a power of two apart differ in bank
  at.bank = static_cast<uint32_t>(bank);
  const DramTimingConfig& b = config_.banked;
  // Bank groups take the lowest bits, so neighbouring rows alternate groups (tCCD_S, tRRD_S).
  at.group = at.bank % b.bank_groups;
  at.rank = at.bank / (b.bank_groups * b.banks_per_group);
  return at;
}

// A rank refreshes all its banks at once: every open row is precharged first (as soon as
// each bank allows), then REF holds the rank for tRFC (no ACT in it). Applied when a request
// reaches a time at or past the refresh that was due.
void BankedDram::refresh_until(Channel& ch, uint32_t rank, Cycle until, ChannelCounters& k) {
  Rank& r = ch.ranks[rank];
  const uint32_t per_rank = config_.banked.bank_groups * config_.banked.banks_per_group;
  while (r.next_refresh <= until) {
    Cycle start = r.next_refresh;
    for (uint32_t i = 0; i < per_rank; ++i) {
      const Bank& b = ch.banks[rank * per_rank + i];
      start = later(start, b.open ? later(r.next_refresh, b.next_pre) + timing_.rp : b.next_act);
    }
    for (uint32_t i = 0; i < per_rank; ++i) {
      Bank& b = ch.banks[rank * per_rank + i];
      if (b.open) ++k.precharges;
      b.open = false;
    }
    r.refresh_from = start;
    r.refresh_to = start + timing_.rfc;
    ++k.refreshes;
    k.refresh_cycles += timing_.rfc;
    r.next_refresh += timing_.refi;
  }
}

namespace {
// The first cycle >= from where `length` cycles of `c` are free (from itself if length is 0:
// no constraint); kNone beyond the horizon.
Cycle gap(const transport::ReservationCalendar& c, Cycle from, uint32_t length) {
  return length == 0 ? from : c.first_gap(from, length);
}
constexpr Cycle kNone = transport::ReservationCalendar::kNone;
}  // namespace

// A controller with requests queued issues its next ACT as soon as tRRD allows, so under load
// activates follow each other at exactly tRRD. Booked one request at a time (each answered as
// it arrives, in arrival order, not time order), ACTs land where their banks allow, and the
// gaps between them are rarely whole multiples of tRRD: a gap of 10 cycles holds one more ACT
// and wastes 4. At saturation on random reads that cost 10% of the activate rate
// (docs/memory-system.md, "Banked DRAM"). So an ACT that follows its rank's previous ACT by
// less than a row cycle (tRC: how far past the others a request waiting for its own bank can
// land) is placed so that the part of the gap where tFAW would allow an ACT is a whole number
// of tRRD slots, each usable by another bank's request, as the controller would have issued
// those first. It moves by less than tRRD. A gap the tFAW window closes is no loss, and an ACT
// a whole row cycle after the previous one (its own bank's next) moves not at all. Only an
// ACT that waited is packed (access(), place_act): with nothing queued, nothing would take the
// cycles it leaves, and a lightly loaded DRAM is timed as if packing were off.
Cycle BankedDram::packed_act(const Rank& r, Cycle b) const {
  const uint32_t spacing = timing_.rrd_s;
  if (spacing < 2 || timing_.rc <= spacing) return b;
  // Look back for the previous ACT's slot: its last cycle b - k, so the ACT itself at
  // b - k - spacing + 1, which must be less than tRC before b.
  const Cycle reach = std::min<Cycle>(b, timing_.rc - spacing);
  for (Cycle k = 1; k <= reach; ++k) {
    if (r.acts.used(b - k) == 0) continue;
    // The previous ACT's tRRD slot ends at b - k + 1; from where tFAW allows one, the gap.
    const Cycle open = gap(r.window, b - k + 1, timing_.faw);
    if (open == kNone || open >= b) return b;
    return b + (spacing - (b - open) % spacing) % spacing;
  }
  return b;
}

Cycle BankedDram::act_slot(const Rank& r, uint32_t group, Cycle from, bool pack) const {
  // Each calendar can only move the cycle later; stop when all three agree.
  for (Cycle a = from;;) {
    Cycle b = gap(r.acts, a, timing_.rrd_s);
    if (b != kNone && pack) b = packed_act(r, b);
    if (b != kNone) b = gap(r.group_acts[group], b, timing_.rrd_l);
    if (b != kNone) b = gap(r.window, b, timing_.faw);
    if (b == kNone || b == a) return b == kNone ? kNever : b;
    a = b;
  }
}

void BankedDram::book_act(Rank& r, uint32_t group, Cycle at) {
  if (timing_.rrd_s > 0) r.acts.book(at, timing_.rrd_s);
  if (timing_.rrd_l > 0) r.group_acts[group].book(at, timing_.rrd_l);
  for (Cycle c = at; c < at + timing_.faw; ++c) r.window.book_below(c, 4);
}

Cycle BankedDram::column_slot(const Rank& r, uint32_t group, Cycle from, Cycle lead, const Calendar& bus) const {
  for (Cycle a = from;;) {
    Cycle b = gap(r.columns, a, timing_.ccd_s);
    if (b != kNone) b = gap(r.group_columns[group], b, timing_.ccd_l);
    if (b != kNone) {  // the data's cycles on the bus, whole (every booking fills whole cycles)
      b = bus.first_gap(b + lead, timing_.burst);
      if (b != kNone) b -= lead;
    }
    if (b == kNone || b == a) return b == kNone ? kNever : b;
    a = b;
  }
}

void BankedDram::book_column(Rank& r, uint32_t group, Cycle at) {
  if (timing_.ccd_s > 0) r.columns.book(at, timing_.ccd_s);
  if (timing_.ccd_l > 0) r.group_columns[group].book(at, timing_.ccd_l);
}

uint64_t BankedDram::overflow_bookings() const {
  uint64_t n = overflows_;
  for (const Channel& ch : channels_)
    for (const Rank& r : ch.ranks) {
      n += r.acts.overflow_bookings() + r.columns.overflow_bookings() + r.window.overflow_bookings();
      for (const Calendar& c : r.group_acts) n += c.overflow_bookings();
      for (const Calendar& c : r.group_columns) n += c.overflow_bookings();
    }
  return n;
}

BankedDram::Result BankedDram::access(uint32_t channel, uint64_t addr, uint32_t bytes, bool write, Cycle t,
                                      Cycle now, transport::ReservationCalendar& bus, bool count,
                                      transport::DataClass data) {
  Channel& ch = channels_[channel];
  ChannelCounters scratch;
  ChannelCounters& k = count ? counters_[channel] : scratch;
  const Location at = locate(addr);
  Bank& bank = ch.banks[at.bank];
  Rank& rank = ch.ranks[at.rank];
  const Cycle arrive = t + timing_.controller;
  rank.acts.retire_before(now);
  rank.columns.retire_before(now);
  rank.window.retire_before(now);
  rank.group_acts[at.group].retire_before(now);
  rank.group_columns[at.group].retire_before(now);

  // An ACT at or after `from`, by the rank's calendars, outside the latest refresh. `ready`:
  // where it would go if the DRAM served nothing else (the request's arrival, or its own PRE's
  // end). Only an ACT that waited past it (its bank or its rank busy: a controller would have
  // held it in its queue) is packed; one issued the moment it could be is not, since with
  // nothing queued no other request would take the cycles packing leaves.
  auto place_act = [&](Cycle from, Cycle ready) {
    const bool pack = config_.banked.pack_activates;
    Cycle a = act_slot(rank, at.group, from, false);
    if (pack && a != kNever && a > ready) a = act_slot(rank, at.group, a, true);
    if (a != kNever && a >= rank.refresh_from && a < rank.refresh_to)
      a = act_slot(rank, at.group, rank.refresh_to, pack);
    if (a == kNever) {  // beyond the horizon: without the rank's constraints
      a = from < rank.refresh_from || from >= rank.refresh_to ? from : rank.refresh_to;
      ++overflows_;
    }
    return a;
  };

  // A request earlier in time than its bank's latest ACT arrived late in call order (its TM
  // ran behind). If a whole row cycle of its own (ACT, columns, PRE) fits before that ACT, it
  // is served there as a miss and leaves the bank's state, which is later, alone; else it
  // queues behind, first come, first served.
  if (bank.last_act != kNever && arrive + timing_.rc <= bank.last_act) {
    const Cycle act = place_act(arrive, arrive);
    if (act + timing_.rc <= bank.last_act) {
      ++k.activates;
      ++k.precharges;
      book_act(rank, at.group, act);
      Result r = issue_columns(rank, nullptr, at.group, act + timing_.rcd, bytes, write, bus, k);
      r.row = RowOutcome::kMiss;
      count_request(k, count, data, r.row, write, t, act, r.end);
      return r;
    }
  }

  // The request's first command (PRE, ACT, or its first column command on a row hit) must
  // come before the rank's next refresh; else the refresh goes first and the plan is redone.
  bool hit = false, conflict = false;
  Cycle pre = 0, act = 0, col_ready = 0, first = 0;
  for (;;) {
    refresh_until(ch, at.rank, arrive, k);
    hit = bank.open && bank.row == at.row;
    conflict = bank.open && !hit;
    if (hit) {
      col_ready = later(arrive, bank.next_col);
      first = col_ready;
    } else {
      pre = conflict ? later(arrive, bank.next_pre) : 0;
      Cycle from = later(conflict ? pre + timing_.rp : arrive, bank.next_act);
      if (bank.last_act != kNever) from = later(from, bank.last_act + timing_.rc);
      act = place_act(from, conflict ? arrive + timing_.rp : arrive);
      col_ready = act + timing_.rcd;
      first = conflict ? pre : act;
    }
    if (first < rank.next_refresh) break;
    refresh_until(ch, at.rank, first, k);
  }

  if (!hit) {
    if (conflict) ++k.precharges;
    ++k.activates;
    bank.open = true;
    bank.row = at.row;
    bank.last_act = act;
    bank.next_act = later(bank.next_act, act + timing_.rc);
    bank.next_pre = later(bank.next_pre, act + timing_.ras);
    bank.next_col = act + timing_.rcd;
    book_act(rank, at.group, act);
  }

  Result result = issue_columns(rank, &bank, at.group, col_ready, bytes, write, bus, k);
  result.row = hit ? RowOutcome::kHit : conflict ? RowOutcome::kConflict : RowOutcome::kMiss;

  if (config_.banked.row_policy == RowPolicy::kClosed) {  // auto-precharge after the last column
    ++k.precharges;
    bank.open = false;
    bank.next_act = later(bank.next_act, bank.next_pre + timing_.rp);
  }
  count_request(k, count, data, result.row, write, t, first, result.end);
  return result;
}

void BankedDram::count_request(ChannelCounters& k, bool count, transport::DataClass data, RowOutcome row, bool write,
                               Cycle t, Cycle first, Cycle end) {
  const bool hit = row == RowOutcome::kHit, conflict = row == RowOutcome::kConflict;
  (hit ? k.row_hits : conflict ? k.row_conflicts : k.row_misses) += 1;
  k.busy_bank_cycles += end > first ? end - first : 0;
  if (!write) {
    ++k.read_requests;
    k.read_latency_cycles += end - t;
    ++k.read_latency_buckets[latency_bucket(end - t)];
  }
  if (count) {
    RowOutcomes& d = by_data_[static_cast<unsigned>(data)];
    (hit ? d.hits : conflict ? d.conflicts : d.misses) += 1;
  }
}

// Column commands, one per column_bytes, each as early as tCCD (and tWTR for a read after a
// write) allow, then as early as the data bus has room: a busy bus delays the command. `bank`
// (null: a request served before the bank's later state) learns its tRTP and tWR limits.
BankedDram::Result BankedDram::issue_columns(Rank& rank, Bank* bank, uint32_t group, Cycle col_ready, uint32_t bytes,
                                             bool write, transport::ReservationCalendar& bus, ChannelCounters& k) {
  const uint32_t column = config_.banked.column_bytes;
  const uint32_t columns = std::max<uint32_t>(1, (bytes + column - 1) / column);
  const Cycle latency = write ? timing_.cwl : timing_.cl;
  Result result;
  for (uint32_t i = 0; i < columns; ++i) {
    Cycle want = col_ready;
    // tWTR: a read after (in call order) a write whose command it would follow.
    if (!write && rank.last_write != kNever && want >= rank.last_write)
      want = later(want, rank.write_data_end + timing_.wtr);
    Cycle c = column_slot(rank, group, want, latency, bus);
    if (c == kNever) {  // beyond the horizon: the bus's overflow tail serves it in arrival order
      c = want;
      ++overflows_;
    } else {
      book_column(rank, group, c);
    }
    const transport::Booking data = bus.book(c + latency, column);
    result.queued += data.first - (want + latency);
    c = data.first - latency;
    if (write) {
      ++k.writes;
      rank.last_write = c;
      rank.write_data_end = data.end();
      if (bank != nullptr) bank->next_pre = later(bank->next_pre, data.end() + timing_.wr);
    } else {
      ++k.reads;
      if (bank != nullptr) bank->next_pre = later(bank->next_pre, c + timing_.rtp);
    }
    col_ready = c;
    result.end = later(result.end, data.end());
  }
  return result;
}

}  // namespace strata::memory
