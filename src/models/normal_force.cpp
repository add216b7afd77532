#include "bounce/models/normal_force.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "bounce/contact/hertz.hpp"

namespace bounce::models {

namespace {

// BP04 (8.65) for F_el = m D1 xi^alpha.
double power_law_reference_overlap(double d1, double alpha, double speed) {
  return std::pow((alpha + 1.0) / (2.0 * d1), 1.0 / (1.0 + alpha)) *
         std::pow(speed, 2.0 / (1.0 + alpha));
}

class ViscoelasticForce final : public NormalForceModel {
 public:
  ViscoelasticForce(const HertzGeometry& g, double a, std::string_view name)
      : g_(g), a_(a), name_(name) {}
  std::string_view name() const override { return name_; }
  double force(double xi, double rate) const override {  // BP04 (8.42), (8.37)
    if (xi <= 0.0) return 0.0;
    const double root = std::sqrt(xi);
    return g_.force_constant * root * (xi + 1.5 * a_ * rate);
  }
  double force_sign(double xi, double rate) const override {
    return xi + 1.5 * a_ * rate;  // F = C0 sqrt(xi) (xi + (3/2) A xi'), continued through xi = 0
  }
  double elastic_force(double xi) const override { return hertz::force(g_.force_constant, xi); }
  double elastic_energy(double xi) const override {
    return hertz::elastic_energy(g_.force_constant, xi);
  }
  double contact_radius(double xi) const override {
    return hertz::contact_radius(g_.equivalent_radius, xi);
  }
  double reference_overlap(double speed) const override {  // BP04 (8.65), alpha = 3/2
    return power_law_reference_overlap(g_.force_constant / g_.effective_mass, 1.5, speed);
  }

 private:
  HertzGeometry g_;
  double a_;
  std::string name_;
};

class ShiftedViscoelasticForce final : public NormalForceModel {
 public:
  ShiftedViscoelasticForce(const HertzGeometry& g, double a) : g_(g), a_(a) {}
  std::string_view name() const override { return "viscoelastic-shifted"; }
  double force(double xi, double rate) const override {  // BSHP96 (25), clamped at zero
    if (xi <= 0.0) return 0.0;
    const double shifted = std::max(xi + a_ * rate, 0.0);
    return g_.force_constant * shifted * std::sqrt(shifted);
  }
  double force_sign(double xi, double rate) const override { return xi + a_ * rate; }
  double elastic_force(double xi) const override { return hertz::force(g_.force_constant, xi); }
  double elastic_energy(double xi) const override {
    return hertz::elastic_energy(g_.force_constant, xi);
  }
  double contact_radius(double xi) const override {
    return hertz::contact_radius(g_.equivalent_radius, xi);
  }
  double reference_overlap(double speed) const override {
    return power_law_reference_overlap(g_.force_constant / g_.effective_mass, 1.5, speed);
  }

 private:
  HertzGeometry g_;
  double a_;
};

class PowerLawForce final : public NormalForceModel {
 public:
  PowerLawForce(const PowerLawParameters& p, double m, double radius)
      : p_(p), m_(m), radius_(radius) {}
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
  double elastic_force(double xi) const override {
    return xi <= 0.0 ? 0.0 : m_ * p_.d1 * std::pow(xi, p_.alpha);
  }
  double elastic_energy(double xi) const override {
    return xi <= 0.0 ? 0.0 : m_ * p_.d1 * std::pow(xi, p_.alpha + 1.0) / (p_.alpha + 1.0);
  }
  double contact_radius(double xi) const override { return hertz::contact_radius(radius_, xi); }
  double reference_overlap(double speed) const override {  // BP04 (8.65)
    return power_law_reference_overlap(p_.d1, p_.alpha, speed);
  }

 private:
  PowerLawParameters p_;
  double m_;
  double radius_;
};

class AdhesiveViscoelasticForce final : public NormalForceModel {
 public:
  explicit AdhesiveViscoelasticForce(const AdhesiveViscoelasticParameters& p) : p_(p) {}
  std::string_view name() const override { return "adhesive-viscoelastic"; }
  double force(double xi, double rate) const override {  // BP04 (8.56) + (8.57)
    if (xi <= 0.0) return 0.0;
    const double q = std::sqrt(std::sqrt(xi));  // xi^{1/4}
    return p_.rho * xi * q * q + p_.rho * 1.5 * p_.a * q * q * rate - p_.adhesion * xi / q +
           0.75 * p_.b * p_.adhesion * rate / q;
  }
  double force_sign(double xi, double rate) const override { return force(xi, rate); }
  double elastic_force(double xi) const override {  // (8.56)
    if (xi <= 0.0) return 0.0;
    return p_.rho * xi * std::sqrt(xi) - p_.adhesion * std::pow(xi, 0.75);
  }
  double elastic_energy(double xi) const override {  // integral of (8.56)
    if (xi <= 0.0) return 0.0;
    return 0.4 * p_.rho * xi * xi * std::sqrt(xi) - 4.0 / 7.0 * p_.adhesion * std::pow(xi, 1.75);
  }
  double contact_radius(double xi) const override { return hertz::contact_radius(p_.effective_radius, xi); }
  double reference_overlap(double speed) const override {
    return power_law_reference_overlap(p_.rho / p_.effective_mass, 1.5, speed);
  }
  bool adhesive() const override { return true; }
  double cutoff_overlap(double speed) const override { return p_.cutoff_fraction * reference_overlap(speed); }

 private:
  AdhesiveViscoelasticParameters p_;
};

}  // namespace

std::unique_ptr<NormalForceModel> make_adhesive_viscoelastic_force(const AdhesiveViscoelasticParameters& p) {
  return std::make_unique<AdhesiveViscoelasticForce>(p);
}

std::unique_ptr<NormalForceModel> make_viscoelastic_force(const HertzGeometry& geometry,
                                                          double dissipative_constant,
                                                          std::string_view name) {
  return std::make_unique<ViscoelasticForce>(geometry, dissipative_constant, name);
}

std::unique_ptr<NormalForceModel> make_shifted_viscoelastic_force(const HertzGeometry& geometry,
                                                                  double dissipative_constant) {
  return std::make_unique<ShiftedViscoelasticForce>(geometry, dissipative_constant);
}

std::unique_ptr<NormalForceModel> make_power_law_force(const PowerLawParameters& parameters,
                                                       double effective_mass,
                                                       double equivalent_radius) {
  return std::make_unique<PowerLawForce>(parameters, effective_mass, equivalent_radius);
}

}  // namespace bounce::models
