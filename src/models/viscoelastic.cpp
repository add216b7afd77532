// `hertz` and `viscoelastic`: F = C0 (xi^{3/2} + (3/2) A sqrt(xi) xi'), BP04 (8.37), (8.42),
// BSHP96 (24); hertz is the same law with A = 0.
#include <cmath>
#include <string>

#include "bounce/contact/hertz.hpp"
#include "bounce/models/normal_force.hpp"
#include "bounce/pair/mixing.hpp"
#include "factories.hpp"
#include "hertz_type.hpp"

namespace bounce::models {

namespace {

// BP04 (8.42), (8.37): F = C0 sqrt(xi) (xi + (3/2) A xi'); 0 out of contact.
double viscoelastic_force(double c0, double a, double xi, double rate) {
  if (xi <= 0.0) return 0.0;
  const double root = std::sqrt(xi);
  return c0 * root * (xi + 1.5 * a * rate);
}

class ViscoelasticForce final : public detail::HertzTypeForce {
 public:
  ViscoelasticForce(const HertzGeometry& g, double a, std::string_view name) : HertzTypeForce(g), a_(a), name_(name) {}
  std::string_view name() const override { return name_; }
  double force(double xi, double rate) const override { return viscoelastic_force(g_.force_constant, a_, xi, rate); }
  double force_sign(double xi, double rate) const override {
    return xi + 1.5 * a_ * rate;  // F = C0 sqrt(xi) (xi + (3/2) A xi'), continued through xi = 0
  }
 private:
  double a_;
  std::string name_;
};

// The law for the pair (C0 of its shape) and per DEM contact (C0 = rho of each contact's R_eff).
Made<ForceLaw> hertz_type(const Pair& pair, const Context& c, double a, std::string_view name) {
  Made<ForceLaw> m;
  const HertzGeometry geometry = detail::hertz_geometry(pair, c.shape);
  m.normal = ForceLaw{make_viscoelastic_force(geometry, a, name),
                      std::make_shared<detail::HertzTypeContact<viscoelastic_force>>(pair.effective_modulus(), a)};
  m.hertz = HertzScaling{geometry.force_constant, a};
  return m;
}

}  // namespace

std::unique_ptr<NormalForceModel> make_viscoelastic_force(const HertzGeometry& geometry, double dissipative_constant,
                                                          std::string_view name) {
  return std::make_unique<ViscoelasticForce>(geometry, dissipative_constant, name);
}

Made<ForceLaw> make_hertz(const Pair& pair, const NoParameters&, const Context& c) {
  return hertz_type(pair, c, 0.0, "hertz");
}

Made<ForceLaw> make_viscoelastic(const Pair& pair, const ViscousParameters& p, const Context& c) {
  const double a = detail::dissipative_constant(pair, p);
  Made<ForceLaw> m = hertz_type(pair, c, a, "viscoelastic");
  m.dissipative_constant = a;
  m.viscous_time = detail::viscous_time(pair, p, a);
  return m;
}

}  // namespace bounce::models
