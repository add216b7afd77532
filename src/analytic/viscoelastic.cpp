#include "bounce/analytic/viscoelastic.hpp"

#include <cmath>
#include <numbers>

#include <boost/math/tools/roots.hpp>

#include "bounce/contact/hertz.hpp"
#include "bounce/core/checks.hpp"
#include "master_curve_data.hpp"

namespace bounce::analytic {

namespace {
constexpr double pi = std::numbers::pi;
}

double b_constant() {  // BP04 (8.81)
  static const double b = std::sqrt(pi) * std::tgamma(0.6) / (5.0 * std::tgamma(2.1));
  return b;
}

double kappa(double a, double c0, double m, double g) {  // BP04 (8.70)
  return 1.5 * std::pow(1.25, 0.6) * a * std::pow(c0 / m, 0.4) * std::pow(g, 0.2);
}

double speed_for_kappa(double k, double a, double c0, double m) {  // (8.70) solved for g
  const double ratio = k / (1.5 * std::pow(1.25, 0.6) * a * std::pow(c0 / m, 0.4));
  return std::pow(ratio, 5.0);
}

double characteristic_velocity(double a, double c0, double m) {  // BP04 (8.88)
  const double inverse_fifth_root = std::sqrt(pi) / (std::pow(2.0, 0.2) * std::pow(5.0, 0.4)) *
                                    std::tgamma(0.6) / std::tgamma(2.1) * (1.5 * a) *
                                    std::pow(c0 / m, 0.4);
  return std::pow(inverse_fifth_root, -5.0);
}

double expansion_variable(double k) { return 2.0 * b_constant() * k; }  // BP04 (8.87)

double cor_implicit(double k) {  // BP04 (8.85): e + 2 kappa b e^{3/5} = 1
  require_non_negative("kappa", k, "kappa");
  if (k == 0.0) return 1.0;
  const double c = 2.0 * k * b_constant();
  auto f = [&](double e) { return e + c * std::pow(e, 0.6) - 1.0; };  // increasing, f(0) = -1, f(1) > 0
  std::uintmax_t iterations = 200;
  const auto r = boost::math::tools::toms748_solve(f, 0.0, 1.0, -1.0, c,
                                                   boost::math::tools::eps_tolerance<double>(52), iterations);
  return 0.5 * (r.first + r.second);
}

double cor_continued_fraction(double k, int depth) {  // BP04 (8.86)
  const double c = 2.0 * k * b_constant();
  double inner = 1.0;  // the innermost (1 + …) truncated to 1
  for (int i = 0; i < depth; ++i) inner = 1.0 + c * std::pow(inner, 0.4);
  return 1.0 / inner;
}

IntegerSeries bp04_simple_series() { return {{1.0, 0.6, 6.0 / 25.0, 7.0 / 125.0}, {0, 0, 0, 0}}; }

IntegerSeries bp04_rigorous_series() { return {{1.0, 0.6, 0.315, 0.161}, {0, 0, 0.0005, 0.0005}}; }

IntegerSeries master_series_overlap() {
  // The generator fits e = 1 + sum_n c_n kappa^n; in q = 2 b kappa, a_n = (-1)^n c_n / (2b)^n.
  IntegerSeries s;
  const double two_b = 2.0 * b_constant();
  for (int n = 0; n < detail::overlap_series_terms; ++n) {
    const double scale = std::pow(two_b, n + 1) * ((n + 1) % 2 ? -1.0 : 1.0);
    s.a.push_back(detail::overlap_series[n] / scale);
    s.uncertainty.push_back(std::abs(detail::overlap_series_uncertainty[n] / scale));
  }
  return s;
}

double cor_series(double q, const IntegerSeries& series) {  // BP04 (8.89)
  require_non_negative("q", q, "the expansion variable q = (g/g*)^(1/5) (BP04 (8.89))");
  double sum = 1.0, power = 1.0;
  for (std::size_t k = 0; k < series.a.size(); ++k) {
    power *= -q;
    sum += series.a[k] * power;
  }
  return sum;
}

ForceRuleCorrection master_series_force_correction() {
  ForceRuleCorrection c;
  for (int n = 0; n < detail::force_series_terms; ++n) {
    c.d.push_back(detail::force_series[n]);
    c.uncertainty.push_back(detail::force_series_uncertainty[n]);
  }
  return c;
}

double cor_series_force(double k, const IntegerSeries& overlap, const ForceRuleCorrection& correction) {
  double sum = 0.0, power = std::pow(k, 2.5);
  for (double d : correction.d) {
    sum += d * power;
    power *= k;
  }
  return cor_series(expansion_variable(k), overlap) + sum;
}

PadeCoefficients pade_coefficients(double a2, double a3, double a4) {  // BP04 (8.93)
  PadeCoefficients d{};
  d.d0 = a4 - 2.0 * a3 - a2 * a2 + 3.0 * a2 - 1.0;
  d.d1 = (1.0 - a2 + a3 - 2.0 * a4 + (a2 - 1.0) * (3.0 * a2 - 2.0 * a3)) / d.d0;
  d.d2 = ((a3 - a2) * (1.0 - 2.0 * a2) - a4) / d.d0;
  d.d3 = (a3 + a2 * a2 * (a2 - 1.0) - a4 * (a2 + 1.0)) / d.d0;
  d.d4 = (a4 * (a3 - 1.0) + (a3 - a2) * (a2 * a2 - 2.0 * a3)) / d.d0;
  d.d5 = (2.0 * (a3 - a2) * (a4 - a2 * a3) - (a4 - a2 * a2) * (a4 - a2 * a2) - a3 * (a3 - a2 * a2)) / d.d0;
  return d;
}

PadeCoefficients pade_coefficients(const IntegerSeries& s) {
  return pade_coefficients(s.a.at(1), s.a.at(2), s.a.at(3));
}

PadeCoefficients bp04_printed_pade() { return {-0.029, 2.583, 3.583, 2.983, 1.148, 0.326}; }  // BP04 (8.93)

double cor_pade(double q, const PadeCoefficients& d) {  // BP04 (8.92)
  require_non_negative("q", q, "the expansion variable q = (g/g*)^(1/5) (BP04 (8.92))");
  return (1.0 + d.d1 * q) / (1.0 + q * (d.d2 + q * (d.d3 + q * (d.d4 + q * d.d5))));
}

double c1_constant() {  // BP04 (8.91)
  return std::sqrt(pi) / (std::pow(2.0, 0.2) * std::pow(5.0, 0.4)) * std::tgamma(0.6) / std::tgamma(2.1);
}

double hertz_contact_time_bshp96(double c0, double m, double g) {  // BSHP96 (A13)
  const double k = 0.8 * c0;
  return 2.94 * std::pow(m / k, 0.4) * std::pow(g, -0.2);
}

double hertz_contact_time_k13(double m, double r, double e_star, double v) {  // K13 (22)
  return 2.87 * std::pow(m * m / (r * e_star * e_star * v), 0.2);
}

double hertz_contact_time_k13_constant() {
  return contact::hertz::scaled_collision_time() * std::pow(15.0 / 16.0, 0.4);
}

double power_law_kappa(double d1, double alpha, double d2, double beta, double gamma,
                       double speed) {  // BP04 (8.68)
  return d2 * std::pow((1.0 + alpha) / (2.0 * d1), (1.0 + gamma) / (1.0 + alpha)) *
         std::pow(speed, power_law_velocity_exponent(alpha, beta, gamma));
}

double power_law_velocity_exponent(double alpha, double beta, double gamma) {  // BP04 (8.69)
  return 2.0 * (gamma - alpha) / (1.0 + alpha) + beta;
}

}  // namespace bounce::analytic
