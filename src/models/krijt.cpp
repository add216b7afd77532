#include "bounce/models/krijt.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <numbers>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/roots.hpp>
#include <fmt/format.h>

#include "bounce/contact/independent.hpp"
#include "bounce/contact/jkr.hpp"
#include "bounce/models/contact_law.hpp"
#include "bounce/core/error.hpp"
#include "bounce/models/crack.hpp"
#include "factories.hpp"
#include "hertz_type.hpp"

namespace bounce::models {

namespace {
constexpr double pi = std::numbers::pi;
}

double KrijtParameters::crack_speed_scale() const {  // K13 (16): E* gamma / (sigma0^2 T_vis)
  return effective_modulus * z0 * z0 / (surface_energy * relaxation_time);
}

double krijt_dissipative_constant(double relaxation_time, const Pair& pair) {  // K13 after (18)
  const Material& m1 = pair.body1().material;
  const Material& m2 = pair.body2().material;
  double nu = m1.poisson_ratio;
  if (!pair.body2().rigid) {
    const double c1 = (1.0 - m1.poisson_ratio * m1.poisson_ratio) / m1.youngs_modulus;
    const double c2 = (1.0 - m2.poisson_ratio * m2.poisson_ratio) / m2.youngs_modulus;
    if (c2 > c1) nu = m2.poisson_ratio;
  }
  return relaxation_time / (nu * nu);
}

double effective_surface_energy_ratio(const KrijtParameters& p, double a, double delta) {  // K13 (14)
  const contact::independent::Geometry g{p.effective_radius, p.effective_modulus};
  return contact::independent::effective_surface_energy(g, a, delta) / p.surface_energy;
}

double elastic_force(const KrijtParameters& p, double a, double delta) {  // K13 (2)
  return contact::independent::elastic_force({p.effective_radius, p.effective_modulus}, a, delta);
}

double bulk_dissipative_force(const KrijtParameters& p, double a, double rate) {  // K13 (19)
  return 2.0 * p.dissipative_constant * p.effective_modulus * a * rate;
}

double contact_energy(const KrijtParameters& p, double a, double delta) {  // K13 (3) + (6)
  return contact::independent::elastic_energy({p.effective_radius, p.effective_modulus}, a, delta) +
         contact::independent::surface_energy(a, p.surface_energy);
}

double krijt_hysteresis_estimate(const KrijtParameters& p, double speed) {
  const double rho = 4.0 / 3.0 * p.effective_modulus * std::sqrt(p.effective_radius);  // BP04 (8.24)
  const double xi0 = std::pow(1.25 * p.effective_mass * speed * speed / rho, 0.4);    // BP04 (8.65)
  const double a_eq = std::cbrt(9.0 * pi * p.surface_energy * p.effective_radius * p.effective_radius /
                                (2.0 * p.effective_modulus));                         // K13 (10)
  const double a = std::max(std::sqrt(p.effective_radius * xi0), a_eq);
  const double t_c = 2.943275184 * std::pow(1.25 * p.effective_mass / rho, 0.4) * std::pow(speed, -0.2);
  const double phi = a / (p.crack_speed_scale() * t_c);
  const double energy = 0.5 * p.effective_mass * speed * speed;
  return 2.0 * pi * a * a * p.surface_energy / energy * std::pow(phi / 0.39, 1.0 / 1.14);
}

CrackStep krijt_crack_step(const KrijtParameters& p, double a_old, double delta, double dt) {  // K13 (14)-(17)
  const double c = p.crack_speed_scale(), top = (1.0 - 1e-6) / p.k, bottom = p.k * (1.0 + 1e-12);
  auto beta = [&](double a) { return effective_surface_energy_ratio(p, a, delta); };
  auto h = [&](double a) {
    return a - a_old - dt * c * crack_speed_function(std::clamp(beta(a), bottom, top), p.k).value;
  };
  const auto tolerance = boost::math::tools::eps_tolerance<double>(50);
  std::uintmax_t iterations = 200;
  if (beta(a_old) >= top) return {0.0, true};
  if (h(a_old) <= 0.0) {  // the contact grows: h increases above a_old (beta grows with a there)
    double hi = 2.0 * a_old;
    while (h(hi) <= 0.0) hi *= 2.0;
    const auto [x0, x1] = boost::math::tools::toms748_solve(h, a_old, hi, tolerance, iterations);
    return {0.5 * (x0 + x1), false};
  }
  // It shrinks: march down from a_old to the first sign change, unless beta reaches 1/k first
  // (below the minimum of beta(a) the opening crack accelerates: K13's run-away).
  double above = a_old;
  for (double s = 1e-12; s < 1.0; s *= 1.5) {
    const double a = a_old * (1.0 - s);
    if (beta(a) >= top) return {0.0, true};
    if (h(a) <= 0.0) {
      const auto [x0, x1] = boost::math::tools::toms748_solve(h, a, above, tolerance, iterations);
      return {0.5 * (x0 + x1), false};
    }
    above = a;
  }
  return {0.0, true};
}

InitialContact krijt_initial_contact(const KrijtParameters& p) {  // K13 appendix B
  const double r2 = p.effective_radius * p.effective_radius;
  // (B.1): at delta = 0, beta = E* a^3 / (2 pi R^2 gamma), so a = (2 pi R^2 beta gamma / E*)^{1/3}.
  auto radius = [&](double beta) { return std::cbrt(2.0 * pi * r2 * beta * p.surface_energy / p.effective_modulus); };
  InitialContact c;
  const double beta0 = 1.01 * p.k;  // "1.01 k beta" of K13 read as G_eff = 1.01 k gamma (docs/decisions.md D8)
  c.contact_radius = radius(beta0);
  // t = int da / a' with da = a dbeta / (3 beta) and a' = c f(beta): substitute beta = k + (beta0 - k) s^2
  // so that the integrand (which vanishes like f^-1 at beta = k) is smooth.
  const double speed = p.crack_speed_scale();
  auto integrand = [&](double s) {
    const double beta = p.k + (beta0 - p.k) * s * s;
    const double f = crack_speed_function(beta, p.k).value;
    return radius(beta) / (3.0 * beta) / (speed * f) * 2.0 * (beta0 - p.k) * s;
  };
  c.time = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(integrand, 0.0, 1.0, 10, 1e-12);
  c.crack_dissipated = -contact_energy(p, c.contact_radius, 0.0);
  return c;
}

// --- the registry's factories: krijt and its fast-crack limit jkr-viscoelastic -------

namespace {

// K13's parameters for the pair: gamma of the pair, T_vis, A (given, or T_vis / nu^2 by
// K13 after (18)), z0 and k. krijt needs T_vis (its crack law); jkr-viscoelastic A or T_vis.
Model dynamic_contact(const Pair& pair, const Parameters& p, std::string_view name, bool instantaneous) {
  KrijtParameters k;
  k.effective_radius = pair.effective_radius();
  k.effective_modulus = pair.effective_modulus();
  k.effective_mass = pair.effective_mass();
  k.surface_energy = detail::adhesive_surface_energy(pair, name);
  if (p.given("tvis")) {
    k.relaxation_time = *p.real("tvis");
  } else if (!instantaneous || !p.given("A")) {
    throw InvalidArgument("tvis", "(not given)", fmt::format("a viscous relaxation time T_vis > 0 s (model {})", name));
  }
  k.dissipative_constant = p.given("A") ? *p.real("A") : krijt_dissipative_constant(k.relaxation_time, pair);
  k.z0 = *p.real("z0");
  if (!instantaneous) k.k = *p.real("k");
  Model m;
  m.dynamic_contact = DynamicContact{k, instantaneous};
  m.dissipative_constant = k.dissipative_constant;
  m.viscous_time = p.given("tvis") ? k.relaxation_time : k.dissipative_constant;
  m.z0 = k.z0;
  m.adhesion = Adhesion::modelled;
  return m;
}

// jkr-viscoelastic per DEM contact: K13 (2) + (19) with a on the JKR branch a(delta) of K13 (8)
// for the contact's R_eff; it holds down to the fold delta_c or the pull-off point.
class JkrViscoelasticContact final : public ContactLaw {
 public:
  JkrViscoelasticContact(const KrijtParameters& p, bool pull_off) : p_(p), pull_off_(pull_off) {}
  double force(const ContactGeometry& g, double delta, double rate) const override {
    const KrijtParameters p = at(g);
    const double a = contact::jkr::DisplacementBranch(jkr(p)).radius(delta);
    return elastic_force(p, a, delta) + bulk_dissipative_force(p, a, rate);
  }
  double energy(const ContactGeometry& g, double delta) const override {
    const KrijtParameters p = at(g);
    return contact_energy(p, contact::jkr::DisplacementBranch(jkr(p)).radius(delta), delta);
  }
  double release_overlap(const ContactGeometry& g) const override {
    const contact::jkr::Parameters j = jkr(at(g));
    return pull_off_ ? contact::jkr::pull_off_overlap(j) : contact::jkr::separation_overlap(j);
  }

 private:
  KrijtParameters at(const ContactGeometry& g) const {
    KrijtParameters p = p_;
    p.effective_radius = g.effective_radius;
    p.effective_mass = g.effective_mass;
    return p;
  }
  static contact::jkr::Parameters jkr(const KrijtParameters& p) {
    return {p.effective_radius, p.effective_modulus, p.surface_energy};
  }
  KrijtParameters p_;
  bool pull_off_;
};

}  // namespace

Model make_krijt(const Pair& pair, const Parameters& p) { return dynamic_contact(pair, p, "krijt", false); }

std::shared_ptr<const ContactLaw> jkr_viscoelastic_contact(const Pair& pair, const Parameters& p) {
  const Model m = dynamic_contact(pair, p, "jkr-viscoelastic", true);
  return std::make_shared<JkrViscoelasticContact>(m.dynamic_contact->parameters,
                                                  parse_end_rule(p.text("contact_end")) == EndRule::pull_off);
}

Model make_jkr_viscoelastic(const Pair& pair, const Parameters& p) {
  return dynamic_contact(pair, p, "jkr-viscoelastic", true);
}

}  // namespace bounce::models
