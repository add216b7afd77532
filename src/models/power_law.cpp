// `power-law`: F = m_eff (D1 xi^alpha + D2 xi^gamma sgn(xi') |xi'|^beta), BP04 (8.63)-(8.69).
#include <cmath>

#include <fmt/format.h>

#include "bounce/contact/hertz.hpp"
#include "bounce/core/error.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/models/dem_law.hpp"
#include "bounce/models/normal_force.hpp"
#include "factories.hpp"

namespace bounce::models {

namespace {

// BP04 (8.63): F = m_eff (D1 xi^alpha + D2 xi^gamma sgn(xi') |xi'|^beta); 0 out of contact.
double power_law_force(const PowerLawParameters& p, double m, double xi, double rate) {
  if (xi <= 0.0) return 0.0;
  const double rate_term = std::copysign(std::pow(std::abs(rate), p.beta), rate);
  return m * (p.d1 * std::pow(xi, p.alpha) + p.d2 * std::pow(xi, p.gamma) * rate_term);
}

// Its potential, integral of m D1 xi^alpha.
double power_law_energy(const PowerLawParameters& p, double m, double xi) {
  return xi <= 0.0 ? 0.0 : m * p.d1 * std::pow(xi, p.alpha + 1.0) / (p.alpha + 1.0);
}

constexpr double max_kappa = 1e2;

class PowerLawForce final : public NormalForceModel {
 public:
  PowerLawForce(const PowerLawParameters& p, double m, double radius) : p_(p), m_(m), radius_(radius) {}
  std::string_view name() const override { return "power-law"; }
  double force(double xi, double rate) const override { return power_law_force(p_, m_, xi, rate); }
  double force_sign(double xi, double rate) const override {
    // The force law with xi clamped at 0: continuous through the end of contact.
    const double x = std::max(xi, 0.0);
    const double rate_term = std::copysign(std::pow(std::abs(rate), p_.beta), rate);
    return p_.d1 * std::pow(x, p_.alpha) + p_.d2 * std::pow(x, p_.gamma) * rate_term;
  }
  double elastic_force(double xi) const override { return xi <= 0.0 ? 0.0 : m_ * p_.d1 * std::pow(xi, p_.alpha); }
  double elastic_energy(double xi) const override { return power_law_energy(p_, m_, xi); }
  double contact_radius(double xi) const override { return contact::hertz::contact_radius(radius_, xi); }
  double reference_overlap(double speed) const override {  // BP04 (8.65)
    return power_law_reference_overlap(p_.d1, p_.alpha, speed);
  }
  // BP04 (8.68): kappa = D2 xi0^(1+gamma) g^(beta-2) (its (8.67) swaps the two exponents). Far above
  // 1 the contact creeps apart beyond the step budget (docs/hardening.md, round 3, gives the bound's measurements).
  void check_speed(double speed) const override {
    const double xi0 = reference_overlap(speed);
    const double kappa = p_.d2 * std::pow(xi0, 1.0 + p_.gamma) * std::pow(speed, p_.beta - 2.0);
    if (!(kappa > max_kappa)) return;
    throw InvalidArgument(
        "power_d2", format_value(p_.d2),
        fmt::format("a damping under which the grains part: kappa = D2 xi0^(1+gamma) g^(beta-2) (BP04 (8.68)) <= {:g} at this "
                    "impact speed g = {:g} m/s, where it is {:.3g} (xi0 = {:.3g} m, BP04 (8.65), with --power-d1 = {:g}): "
                    "an overdamped contact creeps apart for about kappa contact times",
                    max_kappa, speed, kappa, xi0, p_.d1));
  }

 private:
  PowerLawParameters p_;
  double m_;
  double radius_;
};

// The same law per DEM contact, with the contact's m_eff.
class PowerLawContact final : public DemLaw {
 public:
  explicit PowerLawContact(const PowerLawParameters& p) : p_(p) {}
  double force(const ContactGeometry& g, double xi, double rate) const override {
    return power_law_force(p_, g.effective_mass, xi, rate);
  }
  double energy(const ContactGeometry& g, double xi) const override { return power_law_energy(p_, g.effective_mass, xi); }

 private:
  PowerLawParameters p_;
};

}  // namespace

std::unique_ptr<NormalForceModel> make_power_law_force(const PowerLawParameters& parameters, double effective_mass,
                                                       double equivalent_radius) {
  return std::make_unique<PowerLawForce>(parameters, effective_mass, equivalent_radius);
}

Made<ForceLaw> make_power_law(const Pair& pair, const PowerLawParameters& p, const Context&) {
  Made<ForceLaw> m;
  m.normal = ForceLaw{make_power_law_force(p, pair.effective_mass(), pair.effective_radius()),
                      std::make_shared<PowerLawContact>(p)};
  return m;
}

}  // namespace bounce::models
