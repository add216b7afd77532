// `adhesive-viscoelastic`: BP04's quasi-static estimate for adhesive viscoelastic spheres
// (§8.2.3), the forces (8.56)-(8.57) with B of (8.58) as corrected (docs/adhesive.md).
#include <cmath>
#include <numbers>

#include "bounce/contact/hertz.hpp"
#include "bounce/models/dem_law.hpp"
#include "bounce/models/normal_force.hpp"
#include "bounce/pair/mixing.hpp"
#include "factories.hpp"
#include "hertz_type.hpp"

namespace bounce::models {

namespace {

// BP04 (8.56) + (8.57); 0 out of contact.
double adhesive_viscoelastic_force(const AdhesiveViscoelasticParameters& p, double xi, double rate) {
  if (xi <= 0.0) return 0.0;
  const double q = std::sqrt(std::sqrt(xi));  // xi^{1/4}
  return p.rho * xi * q * q + p.rho * 1.5 * p.a * q * q * rate - p.adhesion * xi / q + 0.75 * p.b * p.adhesion * rate / q;
}

// The integral of (8.56).
double adhesive_viscoelastic_energy(const AdhesiveViscoelasticParameters& p, double xi) {
  if (xi <= 0.0) return 0.0;
  return 0.4 * p.rho * xi * xi * std::sqrt(xi) - 4.0 / 7.0 * p.adhesion * std::pow(xi, 1.75);
}

// The constants of (8.56)-(8.57) for a pair of effective modulus E*, surface energy gamma and
// effective radius and mass R, m.
AdhesiveViscoelasticParameters adhesive_parameters(double modulus, double gamma, double r, double m, double a, double b) {
  AdhesiveViscoelasticParameters out;
  out.rho = hertz_constant(modulus, r);  // BP04 (8.24)
  // BP04 (8.56): C = sqrt(6 pi gamma / D) R_eff^{3/4}
  out.adhesion = std::sqrt(6.0 * std::numbers::pi * gamma / hertz_compliance_d(modulus)) * std::pow(r, 0.75);
  out.a = a;
  out.b = b;
  out.effective_mass = m;
  out.effective_radius = r;
  return out;
}

class AdhesiveViscoelasticForce final : public NormalForceModel {
 public:
  explicit AdhesiveViscoelasticForce(const AdhesiveViscoelasticParameters& p) : p_(p) {}
  std::string_view name() const override { return "adhesive-viscoelastic"; }
  double force(double xi, double rate) const override { return adhesive_viscoelastic_force(p_, xi, rate); }
  double force_sign(double xi, double rate) const override { return force(xi, rate); }
  double elastic_force(double xi) const override {  // (8.56)
    if (xi <= 0.0) return 0.0;
    return p_.rho * xi * std::sqrt(xi) - p_.adhesion * std::pow(xi, 0.75);
  }
  double elastic_energy(double xi) const override { return adhesive_viscoelastic_energy(p_, xi); }
  double adhesive_energy(double xi) const override {  // the integral of -C xi^{3/4}, (8.56)
    return xi <= 0.0 ? 0.0 : -4.0 / 7.0 * p_.adhesion * std::pow(xi, 1.75);
  }
  double contact_radius(double xi) const override { return contact::hertz::contact_radius(p_.effective_radius, xi); }
  double reference_overlap(double speed) const override {
    return power_law_reference_overlap(p_.rho / p_.effective_mass, 1.5, speed);
  }
  bool adhesive() const override { return true; }
  double cutoff_overlap(double speed) const override { return p_.cutoff_fraction * reference_overlap(speed); }

 private:
  AdhesiveViscoelasticParameters p_;
};

// B of BP04 (8.57): given, from eta1, eta2 ((8.58) corrected: B = alpha beta =
// (3 eta2 - eta1)(1 + nu)(1 - 2 nu) / (3 E nu), docs/adhesive.md), or A.
double dissipative_constant_b(const Pair& pair, const AdhesiveViscousParameters& p, double a) {
  if (p.dissipative_constant_b) {  // bounded as A is (docs/models.md): B = 1e300 s made the state inf
    return detail::require_short_viscous_time(pair, *p.dissipative_constant_b, "B", "a dissipative constant B [s]");
  }
  if (p.shear_viscosity && p.bulk_viscosity) {
    const Material& m = pair.body1().material;
    const double nu = m.poisson_ratio;
    return (3.0 * *p.bulk_viscosity - *p.shear_viscosity) * (1.0 + nu) * (1.0 - 2.0 * nu) / (3.0 * m.youngs_modulus * nu);
  }
  // With equal relaxation times of shear and dilatation (eta_i = E_i tau) both A and
  // B equal tau (docs/adhesive.md), so B = A is the one-parameter choice.
  return a;
}

// The same forces per DEM contact, their constants from the contact's R_eff. BP04 start and
// end the contact at a tiny overlap (footnote 2) against the singular xi^{-1/4}; a DEM step
// samples the force at its own overlaps, from the first positive one to the last.
class AdhesiveViscoelasticContact final : public DemLaw {
 public:
  AdhesiveViscoelasticContact(double modulus, double gamma, double a, double b)
      : modulus_(modulus), gamma_(gamma), a_(a), b_(b) {}
  double force(const ContactGeometry& g, double xi, double rate) const override {
    return adhesive_viscoelastic_force(at(g), xi, rate);
  }
  double energy(const ContactGeometry& g, double xi) const override { return adhesive_viscoelastic_energy(at(g), xi); }

 private:
  AdhesiveViscoelasticParameters at(const ContactGeometry& g) const {
    return adhesive_parameters(modulus_, gamma_, g.effective_radius, g.effective_mass, a_, b_);
  }
  double modulus_, gamma_, a_, b_;
};

}  // namespace

std::unique_ptr<NormalForceModel> make_adhesive_viscoelastic_force(const AdhesiveViscoelasticParameters& p) {
  return std::make_unique<AdhesiveViscoelasticForce>(p);
}

Made<ForceLaw> make_adhesive_viscoelastic(const Pair& pair, const AdhesiveViscousParameters& p, const Context&) {
  const double gamma = detail::adhesive_surface_energy(pair, "adhesive-viscoelastic");
  const double dissipative = detail::dissipative_constant(pair, p);
  const double b = dissipative_constant_b(pair, p, dissipative);
  const AdhesiveViscoelasticParameters a =
      adhesive_parameters(pair.effective_modulus(), gamma, pair.effective_radius(), pair.effective_mass(), dissipative, b);
  Made<ForceLaw> m;
  m.normal = ForceLaw{make_adhesive_viscoelastic_force(a),
                      std::make_shared<AdhesiveViscoelasticContact>(pair.effective_modulus(), gamma, dissipative, b)};
  m.hertz = HertzScaling{a.rho, a.a};
  m.dissipative_constant = a.a;
  m.viscous_time = detail::viscous_time(pair, p, a.a);
  m.z0 = p.z0;
  return m;
}

}  // namespace bounce::models
