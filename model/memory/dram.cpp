#include "model/memory/dram.h"

#include <cmath>
#include <string>

#include "model/stats/stat_values.h"

namespace strata::memory {

using transport::Cycle;
using transport::MemoryExtension;

Dram::Dram(sc_core::sc_module_name name, const DramConfig& config, SparseMemory& backing)
    : sc_core::sc_module(name),
      config_((config.validate(), config)),
      backing_(backing),
      stats_("dram", "Off-chip DRAM: channels interleaved by address, behind the L2.", stats::Basis::kDataOps) {
  target.register_b_transport(this, &Dram::b_transport);
  while ((1u << interleave_shift_) != config_.interleave_bytes) ++interleave_shift_;
  channels_of_ = BankInterleave(config_.channels, config_.hash_channels);

  buses_.reserve(config_.channels);
  for (uint32_t c = 0; c < config_.channels; ++c)
    buses_.emplace_back(config_.channel_bytes_per_cycle(), config_.calendar_horizon_cycles);
  channels_.resize(config_.channels);  // never resized again: the stats point into it
  if (config_.model == DramModel::kBanked) banked_ = std::make_unique<BankedDram>(config_);

  using stats::Unit;
  const Counters& t = counters_;
  stats::Group& g = stats_;
  g.count("accesses", &t.accesses, Unit::kCount, "Bursts of up to burst_bytes; DRAM energy is per burst.");
  g.count("requests", &t.requests, Unit::kCount, "Requests from the L2 (line fills and write-backs).");
  g.count("bytes_read", &t.bytes_read, Unit::kBytes, "Bytes read.");
  g.count("bytes_written", &t.bytes_written, Unit::kBytes, "Bytes written.");
  g.count("energy_nj", &t.energy_nj, Unit::kNanojoules, "Energy of the bursts.");
  g.derived("bytes", Unit::kBytes, "bytes_read + bytes_written.",
            [](const stats::Scope& s) { return s.self().number("bytes_read") + s.self().number("bytes_written"); },
            true);
  g.derived("bandwidth_gb_per_s", Unit::kGigabytesPerSecond, "Bytes over the simulated frame time.",
            [](const stats::Scope& s) {
              const stats::Values& root = s.root();
              if (!root.has("frame.seconds") || root.number("frame.seconds") <= 0) return 0.0;
              return s.self().number("bytes") / root.number("frame.seconds") * 1e-9;
            });
  const double per_cycle = config_.bytes_per_cycle;
  g.derived("peak_gb_per_s", Unit::kGigabytesPerSecond, "The channels' peak: bytes_per_cycle at the chip clock.",
            [per_cycle](const stats::Scope& s) {
              const stats::Values& root = s.root();
              return root.has("chip.clock_ghz") ? per_cycle * root.number("chip.clock_ghz") : std::nan("");
            });
  g.level("calendar_overflow_bookings", [this] { return overflow_bookings(); }, Unit::kCount,
          "Fidelity: bus bookings beyond the calendar horizon, served late in arrival order; must be 0.");
  by_data_stats_ = std::make_unique<DataTrafficStats>(t.by_data, false, "Bursts of data of this class.",
                                                      "Bytes of this class moved.");
  g.child(&by_data_stats_->group());
  std::vector<const stats::Group*> each;
  for (uint32_t c = 0; c < config_.channels; ++c) {
    ChannelCounters& k = channels_[c];
    auto group = std::make_unique<stats::Group>("channel" + std::to_string(c), "The DRAM channels.");
    group->count("accesses", &k.accesses, Unit::kCount, "Bursts.");
    group->count("requests", &k.requests, Unit::kCount, "Requests.");
    group->count("bytes_read", &k.bytes_read, Unit::kBytes, "Bytes read.");
    group->count("bytes_written", &k.bytes_written, Unit::kBytes, "Bytes written.");
    group->count("queued_cycles", &k.queued_cycles, Unit::kCycles,
                 "Cycles requests waited for the data bus beyond the unloaded latency.");
    group->count("energy_nj", &k.energy_nj, Unit::kNanojoules, "Energy of the bursts.");
    each.push_back(group.get());
    channel_stats_.push_back(std::move(group));
    tr_bandwidth_.push_back(trace_.add_rate("channel" + std::to_string(c) + ".bytes_per_cycle"));
    tr_depth_.push_back(trace_.add_level("channel" + std::to_string(c) + ".queue_cycles"));
  }
  g.instances("channels", each, "channel", "DRAM channel", false);
  if (banked_) {
    g.child(&banked_->stats());
    // The banked model's row outcomes over the whole DRAM, per cycle of each window, and the
    // latest read's latency in it.
    for (const char* outcome : {"row_hits", "row_misses", "row_conflicts"})
      tr_rows_.push_back(trace_.add_rate(std::string(outcome) + "_per_cycle"));
    tr_latency_ = trace_.add_level("read_latency_cycles");
  }
}

void Dram::set_clock(const transport::Clock& clock) {
  clock_ = clock;
  if (banked_) banked_->set_clock_ghz(1e-9 / clock_.duration(1).to_seconds());
}

void Dram::trace(sc_core::sc_trace_file* file, const TraceWindow& window) { trace_.open(file, name(), window); }

uint64_t Dram::overflow_bookings() const {
  uint64_t n = 0;
  for (const auto& b : buses_) n += b.overflow_bookings();
  if (banked_) n += banked_->overflow_bookings();
  return n;
}

void Dram::b_transport(tlm::tlm_generic_payload& gp, sc_core::sc_time& delay) {
  MemoryExtension* ext = gp.get_extension<MemoryExtension>();
  const uint64_t addr = gp.get_address();
  const uint32_t bytes = gp.get_data_length();
  if (bytes == 0 || gp.get_command() == tlm::TLM_IGNORE_COMMAND ||
      (ext != nullptr && transport::is_stream_access(ext->access))) {
    gp.set_response_status(tlm::TLM_COMMAND_ERROR_RESPONSE);
    return;
  }
  const bool write = gp.is_write();
  if (ext == nullptr || !ext->timing_only) {
    if (write) backing_.write(addr, gp.get_data_ptr(), bytes);
    else backing_.read(addr, gp.get_data_ptr(), bytes);
  }

  // A request is served by the channel of its first byte; caches send aligned lines, which
  // never straddle an interleave block.
  const uint32_t ch = channel_of(addr);
  const uint64_t stamp = sc_core::sc_time_stamp().value();
  const Cycle now = clock_.now_at(stamp);
  const Cycle t = clock_.request_cycle_at(stamp, delay);
  transport::ReservationCalendar& bus = buses_[ch];
  bus.retire_before(now);
  const bool counted = transport::counts(ext);  // sampled timing measures part of each detailed window only
  Cycle end = 0, queued = 0;
  BankedDram::RowOutcome row = BankedDram::RowOutcome::kMiss;
  if (banked_) {
    const BankedDram::Result r =
        banked_->access(ch, addr, bytes, write, t, now, bus, counted, transport::data_class_of(ext));
    end = r.end;
    queued = r.queued;
    row = r.row;
  } else {
    const Cycle data_from = t + config_.latency_cycles;
    const transport::Booking b = bus.book(data_from, bytes);
    const Cycle unloaded =
        data_from + (bytes + config_.channel_bytes_per_cycle() - 1) / config_.channel_bytes_per_cycle();
    end = b.end();
    queued = end > unloaded ? end - unloaded : 0;
  }

  const uint64_t bursts = (bytes + config_.burst_bytes - 1) / config_.burst_bytes;
  const double energy = static_cast<double>(bursts) * config_.access_energy_nj;
  if (counted) {
    ChannelCounters& k = channels_[ch];
    k.accesses += bursts;
    ++k.requests;
    (write ? k.bytes_written : k.bytes_read) += bytes;
    k.queued_cycles += queued;
    k.energy_nj += energy;
    counters_.accesses += bursts;
    ++counters_.requests;
    (write ? counters_.bytes_written : counters_.bytes_read) += bytes;
    counters_.energy_nj += energy;
    ClassTraffic& d = traffic(counters_.by_data, transport::data_class_of(ext));
    d.accesses += bursts;
    d.bytes += bytes;
  }

  if (trace_.enabled()) {
    trace_.count(tr_bandwidth_[ch], bytes, now);
    trace_.level(tr_depth_[ch], static_cast<double>(bus.backlog_end() > now ? bus.backlog_end() - now : 0), now);
    if (banked_) {
      trace_.count(tr_rows_[static_cast<unsigned>(row)], 1, now);
      if (!write) trace_.level(tr_latency_, static_cast<double>(end - t), now);
    }
  }
  if (ext != nullptr) ext->served_by = transport::ServedBy::kDram;
  gp.set_response_status(tlm::TLM_OK_RESPONSE);
  delay = clock_.delay_until_at(stamp, end);
}

}  // namespace strata::memory
