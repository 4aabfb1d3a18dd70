// The chip's `treelets` group: the treelet mechanism in numbers, so that a design's DRAM
// traffic reads as sessions x lines per session, and its ray supply as rays in flight
// against the stream memory's capacity.
//
//   sessions        each TM's treelet sessions (treelet_sessions.h), summed; per TM with
//                   --stats-detail tm
//   buffers         how many treelet buffers held rays, and how full they were
//   rays_in_flight  rays stored + held by threads: mean, peak and steady state
//
// The levels are time-weighted over the frame (cycle 0 to frame.cycles) from the stream
// memory's own record of every push and pop (stream_occupancy.h), fast-forward included, so
// they mean the same in every timing mode and are never extrapolated.
#include "model/chip/chip.h"
#include "model/stats/stat_values.h"

namespace strata::chip {

using stats::Unit;

void Chip::register_treelet_stats(stats::Group& g) {
  g.before_snapshot([this] { snapshot_.occupancy = stream_->occupancy().summary(snapshot_.report_cycle); });
  std::vector<const stats::Group*> sessions;
  for (const auto& tm : tms_) sessions.push_back(&tm->session_stats());
  g.instances("sessions", sessions, "tm", "TM's treelet sessions");

  auto own = [this](const char* name, const char* description) -> stats::Group& {
    stat_groups_.push_back(std::make_unique<stats::Group>(name, description, stats::Basis::kExact));
    return *stat_groups_.back();
  };
  const memory::StreamOccupancy::Summary& o = snapshot_.occupancy;
  stats::Group& buffers = own("buffers",
                              "The treelet buffers of the stream memory: how many held rays, and how many rays each "
                              "held, time-weighted over the frame.");
  buffers.level("treelets", [this] { return uint64_t{stream_->layout().treelets}; }, Unit::kCount,
                "Treelet buffers: one per treelet of the scene (memory.stream's; unused on TRaX).");
  buffers.level("node_treelets", [this] { return uint64_t{frame_.node_treelets}; }, Unit::kCount,
                "Of the scene's treelets, node treelets (the scene header's count); the rest hold triangles.");
  buffers.level("nonempty_mean", [&o] { return o.nonempty_mean; }, Unit::kCount,
                "Buffers holding at least one ray: time-weighted mean over the frame.");
  buffers.level("stored_mean", [&o] { return o.stored_mean; }, Unit::kCount,
                "Rays stored in the buffers: time-weighted mean over the frame.");
  buffers.level("rays_per_nonempty_mean", [&o] { return o.rays_per_nonempty; }, Unit::kCount,
                "Rays per non-empty buffer: stored_mean / nonempty_mean (so a stretch with more buffers in use weighs "
                "more); 0 when no buffer held a ray.");
  g.child(&buffers);

  stats::Group& flight = own("rays_in_flight",
                             "Rays in flight: stored in the stream memory plus held by threads that popped one (a "
                             "popped ray's slot stays reserved for its successor), against the capacity.");
  flight.level("capacity", [this] { return uint64_t{stream_->capacity()}; }, Unit::kCount,
               "Rays the stream memory holds (memory.stream.capacity).");
  flight.level("mean", [&o] { return o.in_flight_mean; }, Unit::kCount,
               "Time-weighted mean over the frame, from cycle 0 to its end.");
  flight.level("peak", [&o] { return uint64_t{o.peak}; }, Unit::kCount, "The highest level held for a cycle or more.");
  flight.level("steady_state", [&o] { return o.steady_mean; }, Unit::kCount,
               "Time-weighted mean over the steady span: from the first moment the level reaches 90% of peak to the "
               "last moment it is at or above 90% of peak (after which it stays below: the drain). The fill before "
               "and the drain after are left out, dips inside kept. The span's ends are known to a history bin "
               "(frame cycles / 2048 or finer; model/memory/stream_occupancy.h).");
  flight.level("steady_begin_cycle", [&o] { return uint64_t{o.steady_begin}; }, Unit::kCycles,
               "Where the steady span begins.");
  flight.level("steady_end_cycle", [&o] { return uint64_t{o.steady_end}; }, Unit::kCycles,
               "Where it ends: the drain begins.");
  flight.derived("mean_share_of_capacity", Unit::kRatio, "mean / capacity.", [](const stats::Scope& s) {
    const double c = s.self().number("capacity");
    return c > 0 ? s.self().number("mean") / c : 0.0;
  });
  flight.derived("steady_share_of_capacity", Unit::kRatio, "steady_state / capacity.", [](const stats::Scope& s) {
    const double c = s.self().number("capacity");
    return c > 0 ? s.self().number("steady_state") / c : 0.0;
  });
  g.child(&flight);
}

}  // namespace strata::chip
