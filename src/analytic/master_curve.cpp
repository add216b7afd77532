#include "bounce/analytic/master_curve.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "bounce/core/checks.hpp"
#include "master_curve_data.hpp"

namespace bounce::analytic {

namespace {

using namespace detail;

// Chebyshev series sum c_k T_k(x) by Clenshaw's recurrence.
inline double clenshaw(const double* c, int n, double x) {
  double b1 = 0.0, b2 = 0.0;
  const double two_x = 2.0 * x;
  for (int k = n - 1; k >= 1; --k) {
    const double b0 = c[k] + two_x * b1 - b2;
    b2 = b1;
    b1 = b0;
  }
  return c[0] + x * b1 - b2;
}

constexpr double octave_limit = 134217728.0;  // 2^27

// Leading asymptotes for kappa -> inf (derived in docs/viscoelastic.md): with
// X = (3/2)^{2/3}, the overdamped compression stops at X kappa^{-2/3}; under the
// force rule the contact ends when the fast transient has decayed to the slow
// creep, giving e = (5/4) X kappa^{-5/3} and
// t_c = kappa^{-2/3} [(10/3)(2/3)^{1/3} ln kappa + d].
const double plateau = std::cbrt(1.5 * 1.5);                           // X
const double force_cor_constant = 1.25 * plateau;                      // (5/4) X
const double force_time_log = 10.0 / 3.0 * std::cbrt(2.0 / 3.0);       // (10/3)(2/3)^{1/3}
const double force_time_constant =                                     // d
    std::cbrt(2.0 / 3.0) * (13.0 / 3.0 * std::log(2.0) + 7.0 / 6.0 * std::log(3.0) -
                            2.0 * std::log(5.0) - std::sqrt(3.0) * std::numbers::pi / 6.0);

struct Octave {
  int index;
  double x;
};
inline Octave octave_of(double kappa) {
  int exponent = 0;
  const double mantissa = std::frexp(kappa, &exponent);  // kappa = mantissa 2^exponent, mantissa in [0.5, 1)
  return {exponent - 1, 4.0 * mantissa - 3.0};
}

double check_kappa(double kappa) {
  return require_non_negative("kappa", kappa, "the dimensionless damping kappa (BP04 (8.70))");
}

}  // namespace

double master_cor(double kappa, models::EndRule rule) {
  check_kappa(kappa);
  if (kappa < 1.0) {
    const int q = rule == models::EndRule::overlap ? cor_overlap_scaled : cor_force;
    // A passive force gives e <= 1, and e = 1 at kappa = 0 (Hertz); the fit's own error
    // (a few 1e-15 at kappa = 0) must not carry it past that bound.
    return std::min(1.0, clenshaw(small_coefficients[q], small_nodes, 2.0 * std::sqrt(kappa) - 1.0));
  }
  if (rule == models::EndRule::overlap) {
    const double k2 = kappa * kappa;
    if (kappa >= overlap_tail_start) return tail_cor_constant / (k2 * k2 * kappa);
    const Octave o = octave_of(kappa);
    return clenshaw(octave_coefficients[o.index][cor_overlap_scaled], octave_nodes[o.index], o.x) /
           (k2 * k2 * kappa);
  }
  if (kappa >= octave_limit) return force_cor_constant / (kappa * std::cbrt(kappa * kappa));
  const Octave o = octave_of(kappa);
  return clenshaw(octave_coefficients[o.index][cor_force], octave_nodes[o.index], o.x);
}

MasterValues viscoelastic_master(double kappa, models::EndRule rule) {
  check_kappa(kappa);
  MasterValues v;
  v.cor = master_cor(kappa, rule);
  const bool overlap = rule == models::EndRule::overlap;
  if (kappa < 1.0) {
    const double x = 2.0 * std::sqrt(kappa) - 1.0;
    v.contact_time = clenshaw(small_coefficients[overlap ? time_overlap : time_force], small_nodes, x);
    v.max_overlap = clenshaw(small_coefficients[max_overlap], small_nodes, x);
    return v;
  }
  if (kappa >= octave_limit) {
    const double k23 = std::cbrt(kappa * kappa);
    v.max_overlap = plateau / k23;
    v.contact_time = (force_time_log * std::log(kappa) + force_time_constant) / k23;
  } else {
    const Octave o = octave_of(kappa);
    v.max_overlap = clenshaw(octave_coefficients[o.index][max_overlap], octave_nodes[o.index], o.x);
    v.contact_time = clenshaw(octave_coefficients[o.index][time_force], octave_nodes[o.index], o.x);
    if (overlap && kappa < overlap_tail_start) {
      v.contact_time = clenshaw(octave_coefficients[o.index][time_overlap], octave_nodes[o.index], o.x);
    }
  }
  if (overlap && kappa >= overlap_tail_start) {
    const double z = std::pow(kappa / overlap_tail_start, -5.0 / 3.0);
    v.contact_time =
        kappa * (8.0 / 3.0 * std::log(kappa) + clenshaw(tail_time_coefficients, tail_nodes, 2.0 * z - 1.0));
  }
  return v;
}

double overlap_tail_constant() { return tail_cor_constant; }

double master_curve_fit_error() { return fit_error_estimate; }

}  // namespace bounce::analytic
