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
  // A middle that ran instructions but measured none has no frame time of its own.
  middle_measured_ = weighted_raw.number("sampling.measured_instructions") > 0 ||
                     weighted_raw.number("instructions.retired") == 0;
}

stats::Values SampledEstimate::scaled(stats::Values raw) const {
  // The frame time is the samples' (measured cycles per instruction times the instructions
  // retired, per stratum), not the simulated clock: that also ran the windows' warm-ups, which
  // start from a fast-forwarded state and ran 8% above the steady rate on Sibenik 256x256,
  // and it came out 1.2-1.7% short of LT (docs/sampled-timing.md, "The frame time").
  // Without a measured middle, the simulated clock is all there is.
  const double model = sampled_model_cycles(raw) + strata_model_cycles_;
  if (full_model_cycles_ > 0)
    raw.set("frame.cycles", middle_measured_ ? model : simulated_cycles_ * model / full_model_cycles_);
  raw.scale(extrapolation_factors(raw));
  for (const stats::Values& s : strata_) raw.combine(s, +1, [](const std::string&, const stats::Values::Stat&) { return true; });
  return raw;
}

}  // namespace strata::chip
