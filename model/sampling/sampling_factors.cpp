#include "model/sampling/sampling_factors.h"

#include "model/iss/counters.h"

namespace strata::sampling {

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

double sampled_model_cycles(const stats::Values& raw) {
  const double measured = raw.number("sampling.measured_instructions");
  return measured > 0 ? raw.number("instructions.retired") * raw.number("sampling.measured_cycles") / measured : 0.0;
}

SampledEstimate::SampledEstimate(const stats::Values& weighted_raw, const std::vector<stats::Values>& strata,
                                 double simulated_cycles)
    : simulated_cycles_(simulated_cycles) {
  for (const stats::Values& s : strata) {
    strata_model_cycles_ += sampled_model_cycles(s);
    stats::Values scaled = s;
    scaled.scale(extrapolation_factors(s));  // by the stratum's own ratios
    strata_.push_back(std::move(scaled));
  }
  full_model_cycles_ = sampled_model_cycles(weighted_raw) + strata_model_cycles_;
}

stats::Values SampledEstimate::scaled(stats::Values raw) const {
  // The frame time is the simulated clock, scaled in a replicate by the change in the samples'
  // estimate. The estimate itself (instructions x measured cycles per instruction) was the
  // frame time for a day and came out 35% long on Sibenik 128x128 strata-pipelines, whose
  // middle held 2 windows (docs/sampled-timing.md, "The frame time"); the clock is back until
  // that is understood.
  const double model = sampled_model_cycles(raw) + strata_model_cycles_;
  if (full_model_cycles_ > 0) raw.set("frame.cycles", simulated_cycles_ * model / full_model_cycles_);
  raw.scale(extrapolation_factors(raw));
  for (const stats::Values& s : strata_) raw.combine(s, +1, [](const std::string&, const stats::Values::Stat&) { return true; });
  return raw;
}

}  // namespace strata::sampling
