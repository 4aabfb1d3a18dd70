#include "model/chip/sampling_factors.h"

#include "model/iss/counters.h"

namespace strata::chip {

stats::Factors extrapolation_factors(const stats::Values& root) {
  stats::Factors f;
  if (!root.has("sampling")) return f;
  const auto factor = [](double all, double part) { return part > 0 ? all / part : 1.0; };
  const stats::Values& s = root.group("sampling");
  const stats::Values& mix = root.group("instructions.mix");
  const double retired = root.number("instructions.retired");
  const double data = mix.number(iss::class_name(iss::InstrClass::kLoad)) +
                      mix.number(iss::class_name(iss::InstrClass::kStore)) +
                      mix.number(iss::class_name(iss::InstrClass::kStrataPipeLoad));
  f[stats::Basis::kTimedInstructions] = factor(retired, s.number("timed_instructions"));
  f[stats::Basis::kMeasuredInstructions] = factor(retired, s.number("measured_instructions"));
  f[stats::Basis::kDataOps] = factor(data, s.number("measured_data_ops"));
  f[stats::Basis::kStreamOps] =
      factor(mix.number(iss::class_name(iss::InstrClass::kStrataStream)), s.number("measured_stream_ops"));
  // Pushes and pops apart from the other stream operations: those are mostly idle TPs polling
  // stream_assign, whose number depends on the run's own timing, while the moves are set by
  // the rays. Scaling the moves by all stream operations over-counted them by 6-74%.
  f[stats::Basis::kStreamMoves] = factor(root.number("instructions.stream_moves"), s.number("measured_stream_moves"));
  return f;
}

}  // namespace strata::chip
