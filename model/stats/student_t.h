// Quantiles of the standard normal and Student t distributions, for the confidence intervals of
// sampled timing (batch_means.h), from the exact distribution functions (the t's through the
// regularized incomplete beta function), to about 1e-12.
#pragma once

namespace strata::stats {

// z with P(Z <= z) = p, 0 < p < 1.
double normal_quantile(double p);
// t with P(T <= t) = p for T ~ Student t with `dof` >= 1 degrees of freedom.
double student_t_quantile(double p, unsigned dof);

}  // namespace strata::stats
