// TurnOrder (tlm/turn_order.h): participants resuming at one cycle run in a fixed
// round-robin order, the window sampler's id last, whatever other processes with timed waits
// the kernel has (issue 39, F2: the progress monitor's wake-ups reordered the TMs).
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include <systemc>

#include "tlm/turn_order.h"

namespace strata::transport {
namespace {

using Log = std::vector<std::pair<uint32_t, uint64_t>>;  // (id, global cycle when it ran)

struct Participant : sc_core::sc_module {
  SC_HAS_PROCESS(Participant);
  Participant(sc_core::sc_module_name name, TurnOrder& turns, uint32_t id, std::vector<uint64_t> cycles, Log& log,
              const transport::Clock& clock)
      : sc_core::sc_module(name), turns_(turns), id_(id), cycles_(std::move(cycles)), log_(log), clock_(clock) {
    SC_THREAD(run);
  }
  void run() {
    for (uint64_t c : cycles_) {
      turns_.wait_turn(id_, c);
      log_.push_back({id_, clock_.now()});
    }
    turns_.leave();
  }
  TurnOrder& turns_;
  uint32_t id_;
  std::vector<uint64_t> cycles_;
  Log& log_;
  transport::Clock clock_;
};

// Wakes at every cycle from 1 to 10, as the progress monitor at --progress-cycles 1 would.
struct Disturber : sc_core::sc_module {
  SC_HAS_PROCESS(Disturber);
  Disturber(sc_core::sc_module_name name, const transport::Clock& clock) : sc_core::sc_module(name), clock_(clock) {
    SC_THREAD(run);
  }
  void run() {
    for (int i = 0; i < 10; ++i) sc_core::wait(clock_.duration(1));
  }
  transport::Clock clock_;
};

TEST(TurnOrder, TiesGoRoundRobinAmongTheTmsAndTheSamplerLastWhateverElseWakes) {
  const transport::Clock clock(sc_core::sc_time(2, sc_core::SC_NS));
  TurnOrder turns(3, 2, clock);  // two TMs (ids 0 and 1) and the sampler (id 2)
  Log log;
  // Declared sampler first and TM 1 before TM 0, so the kernel's own start order disagrees.
  Disturber disturber("disturber", clock);
  Participant sampler("sampler", turns, 2, {0, 5}, log, clock);
  Participant tm1("tm1", turns, 1, {0, 5, 6}, log, clock);
  Participant tm0("tm0", turns, 0, {0, 5, 6, 9}, log, clock);
  sc_core::sc_start();
  // Cycle 0: TM 0 first; cycle 5 (odd): TM 1 first; the sampler after both; cycle 6: TM 0.
  const Log expected = {{0, 0}, {1, 0}, {2, 0}, {1, 5}, {0, 5}, {2, 5}, {0, 6}, {1, 6}, {0, 9}};
  EXPECT_EQ(log, expected);
  EXPECT_EQ(clock.now(), 10u);  // the disturber's last wake-up; the participants ended at 9
}

}  // namespace
}  // namespace strata::transport
