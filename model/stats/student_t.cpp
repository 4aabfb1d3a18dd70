#include "model/stats/student_t.h"

#include <cmath>
#include <stdexcept>

namespace strata::stats {
namespace {

// The continued fraction of the regularized incomplete beta function I_x(a, b), evaluated by
// the modified Lentz method; converges quickly for x < (a + 1) / (a + b + 2).
double beta_fraction(double a, double b, double x) {
  const double tiny = 1e-300;
  double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
  if (std::fabs(d) < tiny) d = tiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m <= 400; ++m) {
    const double m2 = 2.0 * m;
    double num = m * (b - m) * x / ((a + m2 - 1.0) * (a + m2));
    for (int step = 0; step < 2; ++step) {
      d = 1.0 + num * d;
      if (std::fabs(d) < tiny) d = tiny;
      c = 1.0 + num / c;
      if (std::fabs(c) < tiny) c = tiny;
      d = 1.0 / d;
      const double delta = d * c;
      h *= delta;
      if (step == 1 && std::fabs(delta - 1.0) < 1e-15) return h;
      num = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1.0));
    }
  }
  return h;
}

double incomplete_beta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) +
                                b * std::log1p(-x));
  if (x < (a + 1.0) / (a + b + 2.0)) return front * beta_fraction(a, b, x) / a;
  return 1.0 - front * beta_fraction(b, a, 1.0 - x) / b;
}

double student_t_cdf(double t, unsigned dof) {
  const double n = double(dof);
  const double tail = 0.5 * incomplete_beta(0.5 * n, 0.5, n / (n + t * t));
  return t >= 0 ? 1.0 - tail : tail;
}

// The x in [lo, hi] where the increasing `cdf` reaches p.
template <class F>
double invert(F cdf, double p, double lo, double hi) {
  for (int i = 0; i < 400 && hi - lo > 1e-12 * (1.0 + std::fabs(lo)); ++i) {
    const double mid = 0.5 * (lo + hi);
    if (cdf(mid) < p) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

// Both by bisection on the exact distribution function: slower than a rational fit, but they
// are called a few times per frame, and cannot be off by more than the bisection's tolerance.
double normal_quantile(double p) {
  if (!(p > 0.0 && p < 1.0)) throw std::domain_error("normal_quantile: p must lie in (0, 1)");
  return invert([](double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }, p, -40.0, 40.0);
}

double student_t_quantile(double p, unsigned dof) {
  if (dof == 0) throw std::domain_error("student_t_quantile: at least one degree of freedom");
  if (!(p > 0.0 && p < 1.0)) throw std::domain_error("student_t_quantile: p must lie in (0, 1)");
  double hi = 1.0;
  while (student_t_cdf(hi, dof) < p && hi < 1e12) hi *= 2.0;
  double lo = -1.0;
  while (student_t_cdf(lo, dof) > p && lo > -1e12) lo *= 2.0;
  return invert([dof](double t) { return student_t_cdf(t, dof); }, p, lo, hi);
}

}  // namespace strata::stats
