// The order in which the chip's TMs (and the window sampler) run against global time.
//
// Every TM is one SC_THREAD that runs ahead of global time and waits when it must not run
// further (thread_multiprocessor.cpp, sync_to). Shared state (the L2 and stream memory
// calendars, the stream scheduler, the global registers) is first come, first served, so
// when two TMs resume at the same cycle, the one that runs first can take the other's bank
// slot or ray. With a plain sc_core::wait(delay) per TM that order is the SystemC kernel's: it
// pops equal-time events from a binary heap, whose order among equal times depends on every
// event inserted before, so any other process with timed waits (the progress monitor, at
// --progress-cycles) changed the frame's cycle counts (issue 39, F2).
//
// Here the participants take turns instead: one runs at a time, and the next is always the
// one waiting for the earliest cycle. Ties go round robin, as an arbiter would grant them: at
// cycle c the TM with id c mod tms goes first, then the ids after it (TM i has id i), so no
// TM is always first to the shared memories; the window sampler (the id after the last TM)
// goes after every TM. A participant that must wait names its cycle and hands the turn over;
// the kernel sees at most one pending timed notification from all of them, so no other
// process can reorder them. Nothing here allocates once constructed.
#pragma once

#include <cstdint>
#include <memory>
#include <queue>
#include <utility>
#include <vector>

#include <systemc>

#include "tlm/clock.h"

namespace strata::transport {

class TurnOrder {
 public:
  using Cycle = transport::Cycle;

  // `participants`: how many threads take turns, of which the first `rotating` (the TMs) share
  // the first place at a cycle in turn; each must call wait_turn() before any runs.
  TurnOrder(uint32_t participants, uint32_t rotating, const transport::Clock& clock)
      : clock_(clock),
        events_(new sc_core::sc_event[participants]),
        participants_(participants),
        rotating_(rotating) {
    std::vector<Entry> storage;
    storage.reserve(participants);
    waiting_ = Queue(std::greater<Entry>(), std::move(storage));
  }

  // From participant `id`'s thread: returns when it is its turn, with global time at `cycle`
  // (or later, if it was there already) and no other participant running. The first call of
  // each participant registers it; none runs until all have registered.
  void wait_turn(uint32_t id, Cycle cycle) {
    waiting_.push({cycle, rank(id, cycle)});
    if (registered_ < participants_ && ++registered_ < participants_) {
      sc_core::wait(events_[id]);
      return;
    }
    const Entry next = waiting_.top();
    waiting_.pop();
    if (id_of(next) == id) {
      if (next.first > clock_.now()) sc_core::wait(clock_.delay_until(next.first));
      return;
    }
    wake(next);
    sc_core::wait(events_[id]);
  }

  // From the running participant's thread (after its first wait_turn), when it has finished
  // for good: the next one runs.
  void leave() {
    if (waiting_.empty()) return;
    const Entry next = waiting_.top();
    waiting_.pop();
    wake(next);
  }

 private:
  // (cycle, place at that cycle << 32 | id): earliest first, then by place.
  using Entry = std::pair<Cycle, uint64_t>;
  using Queue = std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>>;

  uint64_t rank(uint32_t id, Cycle cycle) const {
    const uint64_t place =
        id < rotating_ ? (id + rotating_ - static_cast<uint32_t>(cycle % rotating_)) % rotating_ : id;
    return place << 32 | id;
  }
  static uint32_t id_of(const Entry& e) { return static_cast<uint32_t>(e.second); }

  void wake(const Entry& next) {
    const sc_core::sc_time delay = clock_.delay_until(next.first);
    // Immediate at the same time: it runs in this evaluation phase, right after this one waits.
    if (delay == sc_core::SC_ZERO_TIME) events_[id_of(next)].notify();
    else events_[id_of(next)].notify(delay);
  }

  transport::Clock clock_;
  std::unique_ptr<sc_core::sc_event[]> events_;
  uint32_t participants_;
  uint32_t rotating_;
  uint32_t registered_ = 0;
  Queue waiting_;
};

}  // namespace strata::transport
