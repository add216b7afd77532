// `viscoelastic-shifted`: the elastic law at the shifted overlap, F = C0 max(xi + A xi', 0)^{3/2},
// BSHP96 (25), clamped at zero.
#include <algorithm>
#include <cmath>

#include "bounce/contact/hertz.hpp"
#include "bounce/models/dem_law.hpp"
#include "bounce/models/normal_force.hpp"
#include "bounce/pair/mixing.hpp"
#include "factories.hpp"
#include "hertz_type.hpp"

namespace bounce::models {

namespace {

// BSHP96 (25), clamped at zero: F = C0 max(xi + A xi', 0)^{3/2}; 0 out of contact.
double shifted_force(double c0, double a, double xi, double rate) {
  if (xi <= 0.0) return 0.0;
  const double shifted = std::max(xi + a * rate, 0.0);
  return c0 * shifted * std::sqrt(shifted);
}

class ShiftedViscoelasticForce final : public detail::HertzTypeForce {
 public:
  ShiftedViscoelasticForce(const HertzGeometry& g, double a) : HertzTypeForce(g), a_(a) {}
  std::string_view name() const override { return "viscoelastic-shifted"; }
  double force(double xi, double rate) const override { return shifted_force(g_.force_constant, a_, xi, rate); }
  double force_sign(double xi, double rate) const override { return xi + a_ * rate; }
 private:
  double a_;
};

}  // namespace

std::unique_ptr<NormalForceModel> make_shifted_viscoelastic_force(const HertzGeometry& geometry,
                                                                  double dissipative_constant) {
  return std::make_unique<ShiftedViscoelasticForce>(geometry, dissipative_constant);
}

Made<ForceLaw> make_viscoelastic_shifted(const Pair& pair, const ViscousParameters& p, const Context& c) {
  const double a = detail::dissipative_constant(pair, p);
  const HertzGeometry geometry = detail::hertz_geometry(pair, c.shape);
  Made<ForceLaw> m;
  m.normal = ForceLaw{make_shifted_viscoelastic_force(geometry, a),
                      std::make_shared<detail::HertzTypeContact<shifted_force>>(pair.effective_modulus(), a)};
  m.hertz = HertzScaling{geometry.force_constant, a};
  m.dissipative_constant = a;
  m.viscous_time = detail::viscous_time(pair, p, a);
  return m;
}

}  // namespace bounce::models
