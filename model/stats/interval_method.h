// The ways sampled timing turns its replicates into an interval (batch_means.h), apart so the
// chip's configuration can name one without the statistics machinery.
#pragma once

namespace strata::stats {

// How the replicates' spread becomes a standard error (docs/sampled-timing.md, "Confidence
// intervals").
enum class IntervalMethod {
  // sqrt((n - 1) / n x the sum of squares about their mean), Student's t with n - 1 degrees
  // of freedom: for exchangeable batches.
  kJackknife,
  // The same with the sum of squares replaced by half the sum of squared differences between
  // neighbouring batches' replicates (von Neumann's successive differences, the usual variance
  // estimator for a systematic sample), and about 2(n - 1)/3 degrees of freedom (their
  // estimate of a variance is 1.5 times less precise than the sum of squares'). A smooth trend
  // adds only its slope squared.
  kSuccessiveDifferences,
};
const char* interval_method_name(IntervalMethod m);

}  // namespace strata::stats
