// `power-law`: F = m_eff (D1 xi^alpha + D2 xi^gamma sgn(xi') |xi'|^beta), BP04 (8.63)-(8.69).
#include <cmath>

#include "bounce/contact/hertz.hpp"
#include "bounce/models/normal_force.hpp"
#include "factories.hpp"

namespace bounce::models {

namespace {

class PowerLawForce final : public NormalForceModel {
 public:
  PowerLawForce(const PowerLawParameters& p, double m, double radius) : p_(p), m_(m), radius_(radius) {}
  std::string_view name() const override { return "power-law"; }
  double force(double xi, double rate) const override {  // BP04 (8.63)
    if (xi <= 0.0) return 0.0;
    const double rate_term = std::copysign(std::pow(std::abs(rate), p_.beta), rate);
    return m_ * (p_.d1 * std::pow(xi, p_.alpha) + p_.d2 * std::pow(xi, p_.gamma) * rate_term);
  }
  double force_sign(double xi, double rate) const override {
    // The force law with xi clamped at 0: continuous through the end of contact.
    const double x = std::max(xi, 0.0);
    const double rate_term = std::copysign(std::pow(std::abs(rate), p_.beta), rate);
    return p_.d1 * std::pow(x, p_.alpha) + p_.d2 * std::pow(x, p_.gamma) * rate_term;
  }
  double elastic_force(double xi) const override { return xi <= 0.0 ? 0.0 : m_ * p_.d1 * std::pow(xi, p_.alpha); }
  double elastic_energy(double xi) const override {
    return xi <= 0.0 ? 0.0 : m_ * p_.d1 * std::pow(xi, p_.alpha + 1.0) / (p_.alpha + 1.0);
  }
  double contact_radius(double xi) const override { return contact::hertz::contact_radius(radius_, xi); }
  double reference_overlap(double speed) const override {  // BP04 (8.65)
    return power_law_reference_overlap(p_.d1, p_.alpha, speed);
  }

 private:
  PowerLawParameters p_;
  double m_;
  double radius_;
};

}  // namespace

std::unique_ptr<NormalForceModel> make_power_law_force(const PowerLawParameters& parameters, double effective_mass,
                                                       double equivalent_radius) {
  return std::make_unique<PowerLawForce>(parameters, effective_mass, equivalent_radius);
}

Model make_power_law(const Pair& pair, const Parameters& p) {
  PowerLawParameters law;
  law.d1 = p.require_real("power_d1", "D1 > 0 for the power-law model");
  law.d2 = p.require_real("power_d2", "D2 >= 0 for the power-law model");
  law.alpha = *p.real("power_alpha");
  law.beta = *p.real("power_beta");
  law.gamma = *p.real("power_gamma");
  Model m;
  m.force = make_power_law_force(law, pair.effective_mass(), pair.effective_radius());
  m.adhesion = Adhesion::unchecked;
  return m;
}

}  // namespace bounce::models
