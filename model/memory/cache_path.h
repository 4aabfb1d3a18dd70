// What the L1 data cache, the L1 instruction cache and the L2 do around their own lookup
// policy, written once: refuse what the cache does not serve, move the data through the
// backing store (caches hold no data to go stale), book the bank, count the access; then
// count what went below, update the VCD and answer with the completion time. The read path
// with allocation (an L1 load or fetch) is shared too; the L2's write-back policy is its own.
#pragma once

#include "model/memory/cache_core.h"
#include "model/memory/data_traffic.h"
#include "model/memory/downstream_port.h"
#include "model/memory/sparse_memory.h"
#include "model/memory/window_trace.h"
#include "model/stats/stat_group.h"
#include "tlm/clock.h"
#include "tlm/memory_extension.h"

#include <tlm>

#include <cstdint>

namespace strata::memory {

struct CacheCounters {
  uint64_t accesses = 0, loads = 0, stores = 0;
  uint64_t hits = 0, misses = 0, merged_misses = 0;  // loads only (an L1 store neither hits nor misses)
  uint64_t bank_conflicts = 0, conflict_cycles = 0;
  uint64_t fills = 0, writebacks = 0, bytes_read = 0, bytes_written = 0;
  // Lookups answered as the precise order would although they arrived out of order (LT
  // only; always 0 in precise mode): see CacheCore.
  uint64_t reordered = 0;
  double energy_nj = 0.0;
  DataTraffic by_data{};
};

class CachePath {
 public:
  using Cycle = transport::Cycle;

  struct Request {
    transport::MemoryExtension* ext = nullptr;
    uint64_t addr = 0;
    uint32_t bytes = 0;
    bool store = false;
    transport::DataClass data = transport::DataClass::kOther;
    uint64_t stamp = 0;  // global time when the request arrived (it does not move during it)
    Cycle now = 0, t = 0, slot = 0, answer = 0;
    uint64_t line = 0;
    uint32_t set = 0, bank = 0;
    CacheCounters* c = nullptr;  // the reported counters, or the uncounted copy
  };
  struct Result {
    Cycle done = 0;
    transport::ServedBy served = transport::ServedBy::kNone;
    bool ok = true;
    bool missed = false;  // went to the level below for this line
  };

  // `accesses_trace`: the VCD name of the access rate ("accesses_per_cycle").
  CachePath(const CacheGeometry& geometry, uint32_t hit_latency_cycles, double access_energy_nj,
            SparseMemory& backing, tlm::tlm_initiator_socket<>& downstream, const char* accesses_trace);

  // Checks, data path, bank slot and the access's own counts. `accepted`: the cache serves
  // this kind of request. False when refused (the response is set; nothing was counted).
  // `ext`: the payload's extension (the caller looked it up already), or null.
  bool begin(tlm::tlm_generic_payload& gp, transport::MemoryExtension* ext, sc_core::sc_time& delay, bool accepted,
             Request& r);
  // A read that allocates on a miss (L1 loads and fetches). `model_misses` false: always a hit.
  Result read_allocate(Request& r, bool model_misses, transport::ServedBy hit_level,
                       transport::ServedBy merged_level);
  // Functional warming of a cache that allocates on reads and sends stores on (the L1 data
  // cache): the tags change as the access would change them, a miss or a store goes on to the
  // level below as a warming request too.
  void warm_read_allocate(tlm::tlm_generic_payload& gp, const transport::MemoryExtension* ext);

  // Counts a lookup outcome of a read (hits, merged, reordered).
  void count_read_outcome(const Request& r, CacheCore::Outcome o);
  // What went below, the VCD, the response and the delay.
  void finish(tlm::tlm_generic_payload& gp, sc_core::sc_time& delay, const Request& r, const Result& res);

  // Registers the counters every cache has; `below` names the level it misses to.
  void register_stats(stats::Group& g, const char* below, bool stores, bool writebacks, const char* requests_name,
                      const char* bytes_name);

  void set_clock(const transport::Clock& clock) {
    clock_ = clock;
    below_.set_clock(clock);
  }

  CacheCore& core() { return core_; }
  const CacheCore& core() const { return core_; }
  DownstreamPort& below() { return below_; }
  const CacheCounters& counters() const { return counters_.counted; }
  double access_energy_nj() const { return energy_; }
  WindowTrace& trace() { return trace_; }

 private:
  CacheCore core_;
  uint32_t hit_latency_;
  double energy_;
  SparseMemory& backing_;
  transport::Clock clock_;
  DownstreamPort below_;
  transport::CountedPair<CacheCounters> counters_;
  std::unique_ptr<DataTrafficStats> by_data_stats_;
  WindowTrace trace_;
  std::size_t tr_accesses_, tr_misses_, tr_conflicts_;
};

// The per-access steps are inline: every cache's b_transport is one hot function.
inline bool CachePath::begin(tlm::tlm_generic_payload& gp, transport::MemoryExtension* ext, sc_core::sc_time& delay,
                             bool accepted, Request& r) {
  r.ext = ext;
  r.addr = gp.get_address();
  r.bytes = gp.get_data_length();
  if (!accepted) {
    gp.set_response_status(tlm::TLM_COMMAND_ERROR_RESPONSE);
    return false;
  }
  if (core_.crosses_line(r.addr, r.bytes)) {
    gp.set_response_status(tlm::TLM_BURST_ERROR_RESPONSE);
    return false;
  }
  r.store = gp.is_write();
  r.data = transport::data_class_of(r.ext);
  // Data path: the one backing store, in arrival order.
  if (r.ext == nullptr || !r.ext->timing_only) {
    if (r.store) backing_.write(r.addr, gp.get_data_ptr(), r.bytes);
    else backing_.read(r.addr, gp.get_data_ptr(), r.bytes);
  }

  r.stamp = sc_core::sc_time_stamp().value();
  r.now = clock_.now_at(r.stamp);
  r.t = clock_.request_cycle_at(r.stamp, delay);
  r.line = core_.line_of(r.addr);
  r.set = core_.set_of(r.line);
  r.bank = core_.bank_of(r.line);
  r.slot = core_.book_bank(r.bank, r.t, r.now);
  r.answer = r.slot + hit_latency_;
  CacheCounters& c = counters_.of(r.ext);  // sampled timing: warm-up and fast-forward go apart
  r.c = &c;
  ++c.accesses;
  c.energy_nj += energy_;
  if (r.slot > r.t) {
    ++c.bank_conflicts;
    c.conflict_cycles += r.slot - r.t;
  }
  if (r.store) {
    ++c.stores;
    c.bytes_written += r.bytes;
  } else {
    ++c.loads;
    c.bytes_read += r.bytes;
  }
  ClassTraffic& k = traffic(c.by_data, r.data);
  ++k.accesses;
  k.bytes += r.bytes;
  return true;
}

inline void CachePath::count_read_outcome(const Request& r, CacheCore::Outcome o) {
  CacheCounters& c = *r.c;
  switch (o) {
    case CacheCore::Outcome::kShadowHit: ++c.reordered; [[fallthrough]];
    case CacheCore::Outcome::kHit: ++c.hits; break;
    case CacheCore::Outcome::kTimeShifted: ++c.reordered; [[fallthrough]];
    case CacheCore::Outcome::kMerged: ++c.merged_misses; break;
    case CacheCore::Outcome::kMiss:
      ++c.misses;
      ++traffic(c.by_data, r.data).misses;
      break;
  }
}

inline CachePath::Result CachePath::read_allocate(Request& r, bool model_misses, transport::ServedBy hit_level, transport::ServedBy merged_level) {
  Result res{r.answer, hit_level, true, false};
  const CacheCore::Lookup look = model_misses ? core_.classify(r.set, r.line, r.slot, r.answer)
                                              : CacheCore::Lookup{CacheCore::Outcome::kHit, 0, r.answer};
  count_read_outcome(r, look.outcome);
  switch (look.outcome) {
    case CacheCore::Outcome::kShadowHit:
    case CacheCore::Outcome::kHit: break;
    case CacheCore::Outcome::kTimeShifted:
    case CacheCore::Outcome::kMerged:  // the line is on its way: wait for that fill
      res.done = look.done;
      res.served = merged_level;
      break;
    case CacheCore::Outcome::kMiss: {
      const DownstreamResult d =
          below_.send(tlm::TLM_READ_COMMAND, core_.line_base(r.line), core_.line_bytes(), r.answer, r.ext, r.data);
      res.ok = d.ok;
      res.done = d.done;
      res.served = d.served_by;
      res.missed = true;
      core_.install(r.set, 0, r.line, r.slot, d.done, false, r.data);
      core_.book_bank(r.bank, d.done, r.now);  // writing the fill takes the bank for a cycle
      ++r.c->fills;
      r.c->energy_nj += energy_;
      break;
    }
  }
  return res;
}

inline void CachePath::finish(tlm::tlm_generic_payload& gp, sc_core::sc_time& delay, const Request& r, const Result& res) {
  if (trace_.enabled()) {
    trace_.count(tr_accesses_, 1, r.now);
    trace_.count(tr_misses_, res.missed ? 1 : 0, r.now);
    trace_.count(tr_conflicts_, r.slot > r.t ? 1 : 0, r.now);
  }
  if (r.ext != nullptr) r.ext->served_by = res.served;
  gp.set_response_status(res.ok ? tlm::TLM_OK_RESPONSE : tlm::TLM_GENERIC_ERROR_RESPONSE);
  delay = clock_.delay_until_at(r.stamp, res.done);
}

}  // namespace strata::memory
