#include "model/memory/interconnect.h"

#include <algorithm>

namespace strata::memory {

using transport::Cycle;
using transport::MemoryExtension;

Interconnect::Interconnect(sc_core::sc_module_name name, const InterconnectConfig& config)
    : sc_core::sc_module(name),
      config_((config.validate(), config)),
      interleave_(config_.l2_banks, config_.l2_hash_banks),
      stats_("interconnect", "The crossbar between the TMs and the L2 banks and stream memory.", stats::Basis::kDataOps) {
  tm_side.register_b_transport(this, &Interconnect::b_transport);
  while ((1u << line_shift_) != config_.l2_line_bytes) ++line_shift_;
  tm_ports_.reserve(config_.tm_ports);
  for (uint32_t p = 0; p < config_.tm_ports; ++p) tm_ports_.emplace_back(1, config_.calendar_horizon_cycles);
  links_.reserve(config_.l2_banks + 1);
  for (uint32_t l = 0; l <= config_.l2_banks; ++l) links_.emplace_back(1, config_.calendar_horizon_cycles);
  using stats::Unit;
  const Counters& c = counters_.counted;
  stats::Group& g = stats_;
  g.count("transfers", &c.transfers, Unit::kCount, "Requests carried between the TMs and the L2 banks or stream memory.");
  g.count("bytes", &c.bytes, Unit::kBytes, "Bytes those requests carried (data of loads, stores, fills, rays).");
  g.count("l2_transfers", &c.l2_transfers, Unit::kCount, "Transfers to and from the L2.");
  g.count("stream_transfers", &c.stream_transfers, Unit::kCount, "Transfers to and from the stream memory.");
  g.count("port_conflicts", &c.port_conflicts, Unit::kCount, "Requests that found their TM port busy.");
  g.count("link_conflicts", &c.link_conflicts, Unit::kCount, "Requests that found their bank's or the stream memory's link busy.");
  g.count("conflict_cycles", &c.conflict_cycles, Unit::kCycles, "Cycles requests waited for ports and links.");
  g.level("calendar_overflow_bookings", [this] { return overflow_bookings(); }, Unit::kCount,
          "Fidelity: port and link bookings beyond the calendar horizon, served late; must be 0.");
  g.count("energy_nj", &c.energy_nj, Unit::kNanojoules, "Energy of the transfers (0 unless transfer_energy_nj is set).");
  by_data_stats_ = std::make_unique<DataTrafficStats>(c.by_data, false, "Transfers of data of this class.",
                                                      "Bytes of this class carried.");
  g.child(&by_data_stats_->group());
  tr_bytes_ = trace_.add_rate("bytes_per_cycle");
  tr_conflicts_ = trace_.add_rate("conflicts_per_cycle");
}

uint64_t Interconnect::overflow_bookings() const {
  uint64_t n = 0;
  for (const auto& p : tm_ports_) n += p.overflow_bookings();
  for (const auto& l : links_) n += l.overflow_bookings();
  return n;
}

void Interconnect::trace(sc_core::sc_trace_file* file, const TraceWindow& window) { trace_.open(file, name(), window); }

void Interconnect::b_transport(int port, tlm::tlm_generic_payload& gp, sc_core::sc_time& delay) {
  if (port < 0 || static_cast<uint32_t>(port) >= config_.tm_ports) {
    gp.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
    return;
  }
  const MemoryExtension* ext = gp.get_extension<MemoryExtension>();
  const bool stream = ext != nullptr && transport::is_stream_access(ext->access);
  if (ext != nullptr && ext->functional) {
    // Fast-forward (sampled timing): pass it on, book nothing, count nothing.
    (stream ? stream_side : l2_side)->b_transport(gp, delay);
    return;
  }
  const uint32_t bytes = gp.get_data_length();
  const uint32_t flits = std::max<uint32_t>(1, (bytes + config_.link_bytes_per_cycle - 1) / config_.link_bytes_per_cycle);
  const bool data_in = gp.is_write();  // a store or push carries its data toward the target

  const uint64_t stamp = sc_core::sc_time_stamp().value();  // global time stands still during the call
  const Cycle now = clock_.now_at(stamp);
  const Cycle t = clock_.request_cycle_at(stamp, delay);
  transport::ReservationCalendar& in = tm_ports_[static_cast<uint32_t>(port)];
  transport::ReservationCalendar& link = links_[stream ? config_.l2_banks : bank_of(gp.get_address())];
  in.retire_before(now);
  link.retire_before(now);
  Counters& c = counters_.of(ext);  // sampled: warm-up and fast-forward go apart
  const Cycle granted = in.book(t, 1).first;
  if (granted > t) {
    ++c.port_conflicts;
    c.conflict_cycles += granted - t;
  }
  Cycle arrive = granted + config_.hop_latency_cycles;
  const bool book_link = !stream || config_.stream_link;  // else the stream memory books its bank's
  if (data_in && book_link) {
    const transport::Booking b = link.book(arrive, flits);
    if (b.first > arrive) {
      ++c.link_conflicts;
      c.conflict_cycles += b.first - arrive;
    }
    arrive = b.end();
  }

  sc_core::sc_time d = clock_.delay_until_at(stamp, arrive);
  (stream ? stream_side : l2_side)->b_transport(gp, d);
  Cycle done = clock_.request_cycle_at(stamp, d);
  if (!data_in && book_link) {
    const transport::Booking b = link.book(done, flits);
    if (b.first > done) {
      ++c.link_conflicts;
      c.conflict_cycles += b.first - done;
    }
    done = b.end();
  }
  done += config_.hop_latency_cycles;

  ++c.transfers;
  c.bytes += bytes;
  ++(stream ? c.stream_transfers : c.l2_transfers);
  c.energy_nj += config_.transfer_energy_nj * flits;
  ClassTraffic& k = traffic(c.by_data, transport::data_class_of(ext));
  ++k.accesses;
  k.bytes += bytes;
  if (trace_.enabled()) {
    trace_.count(tr_bytes_, bytes, now);
    trace_.count(tr_conflicts_, granted > t ? 1 : 0, now);
  }
  delay = clock_.delay_until_at(stamp, done);
}

}  // namespace strata::memory
