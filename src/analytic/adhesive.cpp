#include "bounce/analytic/adhesive.hpp"

#include <cmath>
#include <numbers>

#include "bounce/analytic/viscoelastic.hpp"
#include "bounce/contact/hertz.hpp"
#include "bounce/contact/independent.hpp"
#include "bounce/contact/jkr.hpp"

namespace bounce::analytic {

namespace {
constexpr double pi = std::numbers::pi;

// U_E + U_S on the JKR curve at contact radius a (K13 (3), (6), (8)).
double jkr_curve_energy(const contact::jkr::Parameters& p, double a) {
  const double delta = contact::jkr::overlap(p, a);
  return contact::independent::elastic_energy({p.effective_radius, p.effective_modulus}, a, delta) +
         contact::independent::surface_energy(a, p.surface_energy);
}
}  // namespace

double jkr_collision_loss(double r, double e_star, double gamma) {
  const contact::jkr::Parameters p{r, e_star, gamma};
  return jkr_curve_energy(p, contact::jkr::separation_contact_radius(p)) - jkr_curve_energy(p, contact::jkr::snap_on_contact_radius(p));
}

double jkr_collision_loss_constant() {
  static const double c = jkr_collision_loss(1.0, 1.0, 1.0);
  return c;
}

double sticking_velocity_k13(double m, double r, double e_star, double gamma) {  // K13 (25)
  return std::sqrt(14.18 / m) * std::pow(std::pow(gamma, 5) * std::pow(r, 4) / (e_star * e_star), 1.0 / 6.0);
}

double sticking_velocity_jkr(double m, double r, double e_star, double gamma) {
  return std::sqrt(2.0 * jkr_collision_loss(r, e_star, gamma) / m);
}

double cor_jkr(double v, double v_c) {  // K13 (24)
  return v > v_c ? std::sqrt(1.0 - (v_c / v) * (v_c / v)) : 0.0;
}

double cor_viscous_k13(double a, double t_h) { return 1.0 - 5.57 * a / t_h; }  // K13 (26)

double cor_viscous_constant() { return 2.0 * b_constant() * 15.0 / 8.0 * contact::hertz::scaled_collision_time(); }

double cor_independent(double e_jkr, double e_d) {  // K13 (27)
  const double radicand = e_jkr * e_jkr + e_d * e_d - 1.0;
  return radicand > 0.0 ? std::sqrt(radicand) : 0.0;
}

double yield_velocity(double r, double m, double e_star, double y) {  // K13 (28)
  const double p_y = 1.6 * y;
  return std::sqrt(10.2 * r * r * r * std::pow(p_y, 5) / (m * std::pow(e_star, 4)));
}

double yield_velocity_constant() { return std::pow(pi, 5) / 30.0; }

double cor_thornton_ning(double v, double v_y) {  // K13 (29)
  const double vhat = v_y / v;
  if (vhat > 1.0) return 1.0;
  const double vhat2 = vhat * vhat;
  return std::sqrt(6.0 * std::sqrt(3.0) / 5.0) * std::sqrt(1.0 - vhat2 / 6.0) *
         std::pow(vhat / (vhat + 2.0 * std::sqrt(6.0 / 5.0 - vhat2 / 5.0)), 0.25);
}

double cor_with_plastic(double e_a, double e_p) {  // K13 (30)
  const double radicand = e_a * e_a + e_p * e_p - 1.0;
  return radicand > 0.0 ? std::sqrt(radicand) : 0.0;
}

double plastic_length_scale(double m, double v, double r, double e_star) {  // K13 (33)
  return std::pow(15.0 * m * v * v * r * r / (16.0 * e_star), 0.2);
}

double hall_petch_yield(double y0, double k, double l, double n) { return y0 + k * std::pow(l, -n); }  // K13 (32)

double bulk_quasi_static_limit(double nu, double t_c) { return 1e-2 * nu * nu * t_c; }  // K13 (A.2)

double crack_quasi_static_limit(double z0, double a, double e_star, double gamma, double t_c) {  // K13 (A.4)
  return 1e-3 * (z0 / a) * (2.0 * e_star * z0 / gamma) * t_c;
}

double tensile_work_constant() {  // BP04 (8.96)
  return 0.1 * (3.0 * std::cbrt(2.0) - 1.0) * std::cbrt(9.0);
}

double tensile_work(double r_eff, double e_star, double gamma) {  // BP04 (8.95), R = 2 R_eff
  const double d = 3.0 / (4.0 * e_star);
  const double r = 2.0 * r_eff;
  return tensile_work_constant() * std::cbrt(std::pow(pi, 5) * std::pow(gamma, 5) * d * d * std::pow(r, 4));
}

double cor_adhesive_bp04(double e, double g, double w0, double m) {  // BP04 (8.98)
  const double radicand = e * e * g * g - 2.0 * w0 / m;
  return radicand > 0.0 ? std::sqrt(radicand) / g : 0.0;
}

double sticking_velocity_bp04_leading(double w0, double m, double a, double c0) {  // BP04 (8.101)
  const double g0 = std::sqrt(2.0 * w0 / m);
  const double kappa_bp04 = std::pow(1.5, 2.5) * c0 / m;  // (8.73)
  return g0 * (1.0 + c1_constant() * a * std::pow(kappa_bp04, 0.4) * std::pow(g0, 0.2));
}

}  // namespace bounce::analytic
