#include "model/memory/stream_memory.h"

#include "model/stats/stat_values.h"

#include <algorithm>
#include <string>

namespace strata::memory {

using transport::AccessClass;
using transport::Cycle;
using transport::kNoTreelet;
using transport::MemoryExtension;
using transport::StreamStatus;

StreamMemory::StreamMemory(sc_core::sc_module_name name, const StreamMemoryConfig& config)
    : sc_core::sc_module(name),
      config_((config.validate(), config)),
      energy_per_access_(config.energy_per_access_nj()),
      sram_(make_stream_layout(config)),
      scheduler_(config.treelets, sram_.capacity(), config.tms, config.policy, config.sticky),

      stats_("stream", "The ray stream memory: treelet buffers of rays (STRaTA designs).", stats::Basis::kStreamOps) {
  target.register_b_transport(this, &StreamMemory::b_transport);
  using stats::Unit;
  const Counters& c = counters_.counted;
  stats::Group& g = stats_;
  // A push or pop that moved a ray is counted whole (sampled timing's fast-forward moves the
  // same rays), and only the failed ones, whose number depends on timing, are scaled: scaling
  // every push and pop by the frame's stream moves over the measured ones carried the idle
  // TPs' empty pops into the ray counts (-52% pushes on Hairball 128x128).
  g.count("rays_pushed", &rays_pushed_, Unit::kCount, "Pushes that stored a ray (the whole frame; exact).",
          stats::Basis::kExact);
  g.count("rays_popped", &rays_popped_, Unit::kCount, "Pops that took a ray (the whole frame; exact).",
          stats::Basis::kExact);
  g.derived("pushes", Unit::kCount, "Ray pushes, refused ones included: rays_pushed + full_rejections.",
            [](const stats::Scope& s) { return s.self().number("rays_pushed") + s.self().number("full_rejections"); },
            true);
  g.derived("pops", Unit::kCount, "Ray pops, empty ones included: rays_popped + empty_pops.",
            [](const stats::Scope& s) { return s.self().number("rays_popped") + s.self().number("empty_pops"); },
            true);
  g.count("queries", &c.queries, Unit::kCount, "Size, assign and capacity queries (head/count region only).");
  g.level("schedule_ops_out_of_order", [this] { return schedule_ops_out_of_order_; }, Unit::kCount,
          "Fidelity: pushes, pops, size queries and assignments dated before one already served, over the "
          "whole frame: the ray schedule changed out of time order. About 1 in 1,000 stream accesses in precise "
          "mode, in LT with timing.sync_shared_ops and in sampled timing with timing.fast_forward_time_order; "
          "45% on the test frame sampled with timing.fast_forward_time_order=false.");
  g.count("full_rejections", &c.full_rejections, Unit::kCount, "Pushes refused because the memory was full (retried).",
          stats::Basis::kStreamMoves);
  g.count("empty_pops", &c.empty_pops, Unit::kCount, "Pops that found the buffer empty.", stats::Basis::kStreamMoves);
  g.count("assignments", &c.assignments, Unit::kCount, "Treelet buffers handed to TMs.");
  g.count("port_conflicts", &c.port_conflicts, Unit::kCount, "Pushes and pops that found every port busy.");
  g.count("conflict_cycles", &c.conflict_cycles, Unit::kCycles, "Cycles pushes and pops waited for a port.");
  g.count("path_reads", &c.path_reads, Unit::kCount,
          "Loads from the path records kept on chip (design.path_state = on-chip).", stats::Basis::kDataOps);
  g.count("path_writes", &c.path_writes, Unit::kCount, "Stores to the path records kept on chip.",
          stats::Basis::kDataOps);
  // A sum rather than a count of its own, so that sampled timing scales each part by its
  // basis (moves, polls, data operations).
  g.derived("accesses", Unit::kCount, "Operations: pushes + pops + queries + path_reads + path_writes.",
            [](const stats::Scope& s) {
              const stats::Values& v = s.self();
              return v.number("pushes") + v.number("pops") + v.number("queries") + v.number("path_reads") +
                     v.number("path_writes");
            },
            true);
  g.count("bytes_read", &c.bytes_read, Unit::kBytes, "Bytes read: rays popped and path state loaded.");
  g.count("bytes_written", &c.bytes_written, Unit::kBytes, "Bytes written: rays pushed and path state stored.");
  g.level("stored", [this] { return uint64_t{sram_.stored()}; }, Unit::kCount, "Rays stored when the frame ended.");
  g.level("capacity", [this] { return uint64_t{sram_.capacity()}; }, Unit::kCount,
          "Rays the memory holds (its size less the heads, links, thread bits and on-chip path records).");
  g.level("path_record_bytes", [this] { return uint64_t{layout().path_record_bytes}; }, Unit::kBytes,
          "Bytes of path state beside each ray slot (0: path state is not kept here).");
  g.level("ray_bytes", [this] { return uint64_t{layout().ray_bytes}; }, Unit::kBytes,
          "Bytes of one entry's ray: 48, or 64 when the ray carries its path's state (design.path_state = compact).");
  g.level("sram_bytes_per_ray", [this] { return uint64_t{layout().entry_bytes()} + layout().path_record_bytes; },
          Unit::kBytes, "SRAM each ray slot takes: the ray, its link word and any path record beside it.");
  g.count("link_conflicts", &c.link_conflicts, Unit::kCount,
          "Transfers that found their bank's link from the crossbar busy (links modelled here, as on the chip).");
  g.count("link_conflict_cycles", &c.link_conflict_cycles, Unit::kCycles, "Cycles transfers waited for those links.");
  g.level("banks", [this] { return uint64_t{config_.banks}; }, Unit::kCount, "SRAM banks, each with its own ports and link.");
  g.level("calendar_overflow_bookings", [this] { return overflow_bookings(); }, Unit::kCount,
          "Fidelity: port and link bookings beyond the calendar horizon, served late in arrival order; must be 0.");
  g.count("energy_nj", &c.energy_nj, Unit::kNanojoules, "Energy of the operations.");
  by_data_stats_ = std::make_unique<DataTrafficStats>(c.by_data, false, "Operations on data of this class.",
                                                      "Bytes of this class moved.");
  g.child(&by_data_stats_->group());
  banks_.reserve(config_.banks);
  std::vector<const stats::Group*> each;
  for (uint32_t b = 0; b < config_.banks; ++b) {
    banks_.push_back(Bank{transport::ReservationCalendar(config_.ports, config_.calendar_horizon_cycles),
                          transport::ReservationCalendar(1, config_.calendar_horizon_cycles), 0, 0});
    auto bank = std::make_unique<stats::Group>("bank" + std::to_string(b), "The stream memory's banks.");
    bank->count("accesses", &banks_.back().accesses, Unit::kCount, "Operations this bank served.");
    bank->count("conflict_cycles", &banks_.back().conflict_cycles, Unit::kCycles,
                "Cycles they waited for this bank's ports and link.");
    each.push_back(bank.get());
    bank_stats_.push_back(std::move(bank));
  }
  g.instances("bank_detail", each, "stream-bank", "stream-memory bank", false);
  tr_stored_ = trace_.add_level("stored_rays");
  tr_pushes_ = trace_.add_rate("pushes_per_cycle");
  tr_pops_ = trace_.add_rate("pops_per_cycle");
  tr_full_ = trace_.add_rate("full_rejections_per_cycle");
}

uint64_t StreamMemory::overflow_bookings() const {
  uint64_t n = 0;
  for (const Bank& b : banks_) n += b.ports.overflow_bookings() + b.link.overflow_bookings();
  return n;
}

void StreamMemory::trace(sc_core::sc_trace_file* file, const TraceWindow& window) { trace_.open(file, name(), window); }

void StreamMemory::b_transport(tlm::tlm_generic_payload& gp, sc_core::sc_time& delay) {
  MemoryExtension* ext = gp.get_extension<MemoryExtension>();
  if (ext == nullptr || !transport::is_stream_access(ext->access)) {
    gp.set_response_status(tlm::TLM_COMMAND_ERROR_RESPONSE);
    return;
  }
  const AccessClass access = ext->access;
  const bool moves_ray = access == AccessClass::kStreamPush || access == AccessClass::kStreamPop;
  const bool path = access == AccessClass::kStreamPathRead || access == AccessClass::kStreamPathWrite;
  if (moves_ray && (gp.get_data_length() != layout().ray_bytes || gp.get_data_ptr() == nullptr)) {
    gp.set_response_status(tlm::TLM_BURST_ERROR_RESPONSE);
    return;
  }
  // Path state rides in the SRAM beside the rays: one port access moves up to a ray's width.
  if (path && (layout().path_record_bytes == 0 || gp.get_data_length() == 0 ||
               gp.get_data_length() > layout().ray_bytes)) {
    gp.set_response_status(path && layout().path_record_bytes == 0 ? tlm::TLM_COMMAND_ERROR_RESPONSE
                                                                   : tlm::TLM_BURST_ERROR_RESPONSE);
    return;
  }
  if (ext->tm_id >= scheduler_.tms()) {
    ext->stream_status = StreamStatus::kBadRequest;
    gp.set_response_status(tlm::TLM_GENERIC_ERROR_RESPONSE);
    return;
  }

  const uint64_t stamp = sc_core::sc_time_stamp().value();
  const Cycle now = clock_.now_at(stamp);
  const Cycle t = clock_.request_cycle_at(stamp, delay);
  if (moves_ray || access == AccessClass::kStreamSize || access == AccessClass::kStreamAssign) {
    if (t < latest_schedule_op_) ++schedule_ops_out_of_order_;
    else latest_schedule_op_ = t;
  }
  // A functional access (sampled timing's fast-forward) moves rays like any other but books
  // no port; neither it nor a warm-up access is counted: the statistics hold the measured
  // parts of the detailed windows only.
  Counters& c = counters_.of(ext);
  ++c.accesses;
  c.energy_nj += energy_per_access_;

  // The function first: it decides which bank serves the access (the entry a push is given
  // or a pop finds, the path-state row, the treelet's head).
  StreamStatus status = StreamStatus::kOk;
  uint32_t result = 0;
  uint32_t bank = 0;
  switch (access) {
    case AccessClass::kStreamPush: {
      const uint32_t before = ext->treelet < layout().treelets ? sram_.size(ext->treelet) : 0;
      uint32_t entry = StreamSram::kNil;
      status = sram_.push(ext->initiator_id, ext->treelet, gp.get_data_ptr(), &entry);
      ++c.pushes;
      bank = entry != StreamSram::kNil ? bank_of_entry(entry) : ext->initiator_id % config_.banks;
      if (status == StreamStatus::kOk) {
        ++rays_pushed_;
        scheduler_.resized(ext->treelet, before, before + 1);
        c.bytes_written += layout().ray_bytes;
        result = 1;
      } else if (status == StreamStatus::kFull) {
        ++c.full_rejections;
      }
      break;
    }
    case AccessClass::kStreamPop: {
      const uint32_t treelet = ext->treelet == kNoTreelet ? scheduler_.assigned(ext->tm_id) : ext->treelet;
      ++c.pops;
      if (treelet == kNoTreelet) {
        status = StreamStatus::kEmpty;
        bank = ext->tm_id % config_.banks;
      } else {
        const uint32_t before = treelet < layout().treelets ? sram_.size(treelet) : 0;
        uint32_t entry = StreamSram::kNil;
        status = sram_.pop(ext->initiator_id, treelet, gp.get_data_ptr(), &entry);
        bank = entry != StreamSram::kNil ? bank_of_entry(entry) : treelet % config_.banks;
        if (status == StreamStatus::kOk) {
          ++rays_popped_;
          scheduler_.resized(treelet, before, before - 1);
          c.bytes_read += layout().ray_bytes;
          result = 1;
        }
      }
      if (status == StreamStatus::kEmpty) ++c.empty_pops;
      break;
    }
    case AccessClass::kStreamPathRead:
    case AccessClass::kStreamPathWrite: {
      // The data moved through the chip's backing store (the TP executed the load or store);
      // the SRAM books the port and the energy. Records are interleaved over the banks by row.
      const bool write = access == AccessClass::kStreamPathWrite;
      ++(write ? c.path_writes : c.path_reads);
      (write ? c.bytes_written : c.bytes_read) += gp.get_data_length();
      bank = static_cast<uint32_t>((gp.get_address() / 64) % config_.banks);
      result = 1;
      break;
    }
    case AccessClass::kStreamSize:
      ++c.queries;
      if (ext->treelet < layout().treelets) result = sram_.size(ext->treelet);
      else status = StreamStatus::kBadRequest;
      bank = (ext->treelet < layout().treelets ? ext->treelet : 0) % config_.banks;
      break;
    case AccessClass::kStreamAssign:
      ++c.queries;
      ++c.assignments;
      result = scheduler_.assign(ext->tm_id);
      bank = ext->tm_id % config_.banks;
      break;
    default:  // kStreamCapacity
      ++c.queries;
      result = sram_.capacity();
      break;
  }

  if (moves_ray) occupancy_.record(t, sram_.stored() + sram_.credits(), sram_.stored(), scheduler_.nonempty());

  // Then the time: the data crosses the bank's link (a store's on the way in, a load's on
  // the way out), and a ray or path-state access takes one of the bank's ports.
  Bank& k_bank = banks_[bank];
  Cycle at = t;
  const bool links = config_.link_bytes_per_cycle > 0 && !ext->functional;
  const uint32_t flits = links ? std::max<uint32_t>(1, (gp.get_data_length() + config_.link_bytes_per_cycle - 1) /
                                                           config_.link_bytes_per_cycle)
                               : 0;
  auto cross_link = [&](Cycle from) {
    k_bank.link.retire_before(now);
    const transport::Booking bk = k_bank.link.book(from, flits);
    if (bk.first > from) {
      ++c.link_conflicts;
      c.link_conflict_cycles += bk.first - from;
      if (transport::counts(ext)) k_bank.conflict_cycles += bk.first - from;
    }
    return bk.end();
  };
  if (links && gp.is_write()) at = cross_link(at);
  Cycle done = at + config_.query_latency_cycles;
  if ((moves_ray || path) && !ext->functional) {
    k_bank.ports.retire_before(now);
    const Cycle slot = k_bank.ports.book(at, 1).first;
    if (slot > at) {
      ++c.port_conflicts;
      c.conflict_cycles += slot - at;
      if (transport::counts(ext)) k_bank.conflict_cycles += slot - at;
    }
    done = slot + config_.access_latency_cycles;
  }
  if (links && !gp.is_write()) done = cross_link(done);
  if (transport::counts(ext)) ++k_bank.accesses;

  ClassTraffic& k = traffic(c.by_data, ext->data);
  ++k.accesses;
  if (result == 1 && moves_ray) k.bytes += layout().ray_bytes;
  if (path) k.bytes += gp.get_data_length();

  if (trace_.enabled()) {
    trace_.level(tr_stored_, static_cast<double>(sram_.stored()), now);
    trace_.count(tr_pushes_, access == AccessClass::kStreamPush && status == StreamStatus::kOk ? 1 : 0, now);
    trace_.count(tr_pops_, access == AccessClass::kStreamPop && status == StreamStatus::kOk ? 1 : 0, now);
    trace_.count(tr_full_, status == StreamStatus::kFull ? 1 : 0, now);
  }
  ext->stream_status = status;
  ext->result = result;
  ext->served_by = transport::ServedBy::kStream;
  gp.set_response_status(status == StreamStatus::kBadRequest ? tlm::TLM_GENERIC_ERROR_RESPONSE : tlm::TLM_OK_RESPONSE);
  delay = clock_.delay_until_at(stamp, done);
}

}  // namespace strata::memory
