#include "bounce/models/registry.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"

namespace bounce::models {

const std::vector<ModelInfo>& collision_models() {
  static const std::vector<ModelInfo> table = {
      {"hertz", "elastic spheres, no dissipation", "BP04 (8.24), BSHP96 (14)", true},
      {"viscoelastic", "Hertz plus the quasi-static viscous force (3/2) A rho sqrt(xi) xi'",
       "BP04 (8.42), BSHP96 (24)", true},
      {"viscoelastic-shifted", "Hertz law at the shifted overlap xi + A xi', clamped at zero",
       "BSHP96 (25)", false},
      {"power-law", "F = m (D1 xi^alpha + D2 xi^gamma xi'^beta)", "BP04 (8.63)-(8.69)", false},
  };
  return table;
}

const ModelInfo& model_info(const std::string& name) {
  for (const ModelInfo& info : collision_models()) {
    if (info.name == name) return info;
  }
  std::vector<std::string> names;
  for (const ModelInfo& info : collision_models()) names.push_back(info.name);
  throw InvalidArgument("model", name, fmt::format("one of {}", fmt::join(names, ", ")));
}

double dissipative_constant_from_viscosities(double eta1, double eta2, double e, double nu) {  // BP04 (8.38)
  const double difference = 3.0 * eta2 - eta1;
  return difference * difference / (3.0 * (3.0 * eta2 + 2.0 * eta1)) * (1.0 - nu * nu) *
         (1.0 - 2.0 * nu) / (e * nu * nu);
}

double dissipative_constant(const ModelSpec& spec, const Pair& pair) {
  if (spec.name == "hertz") {
    if (spec.dissipative_constant && *spec.dissipative_constant != 0.0) {
      throw InvalidArgument("A", format_value(*spec.dissipative_constant), "no A for the hertz model");
    }
    return 0.0;
  }
  const bool viscosities = spec.shear_viscosity || spec.bulk_viscosity;
  if (spec.dissipative_constant && viscosities) {
    throw InvalidArgument("A", format_value(*spec.dissipative_constant),
                          "either A or the viscosities eta1, eta2, not both");
  }
  if (spec.dissipative_constant) {
    return require_non_negative("A", *spec.dissipative_constant, "dissipative constant A [s]");
  }
  if (!viscosities) {
    throw InvalidArgument("A", "(not given)",
                          fmt::format("a dissipative constant A >= 0 s, or eta1 and eta2 (model {})",
                                      spec.name));
  }
  if (!spec.shear_viscosity) throw InvalidArgument("eta1", "(not given)", "a shear viscosity >= 0 Pa s");
  if (!spec.bulk_viscosity) throw InvalidArgument("eta2", "(not given)", "a bulk viscosity >= 0 Pa s");
  const double eta1 = require_non_negative("eta1", *spec.shear_viscosity, "shear viscosity [Pa s]");
  const double eta2 = require_non_negative("eta2", *spec.bulk_viscosity, "bulk viscosity [Pa s]");
  if (eta1 == 0.0 && eta2 == 0.0) return 0.0;
  // (8.38) is derived for one material; a rigid wall does not deform.
  const Material& m1 = pair.body1().material;
  const Material& m2 = pair.body2().material;
  if (!pair.body2().rigid && (m1.youngs_modulus != m2.youngs_modulus || m1.poisson_ratio != m2.poisson_ratio)) {
    throw InvalidArgument("eta1", format_value(eta1),
                          "viscosities only for bodies of one material (BP04 (8.38)); give A for unlike pairs");
  }
  if (m1.poisson_ratio <= 0.0) {
    throw InvalidArgument("nu", format_value(m1.poisson_ratio),
                          "0 < nu < 0.5 for A from viscosities (BP04 (8.38) divides by nu^2)");
  }
  return dissipative_constant_from_viscosities(eta1, eta2, m1.youngs_modulus, m1.poisson_ratio);
}

HertzGeometry hertz_geometry(const ModelSpec& spec, const Pair& pair) {
  HertzGeometry g{pair.hertz_constant(), pair.effective_radius(), pair.effective_mass()};
  if (spec.curvatures) {
    const double d = pair.hertz_compliance_d();
    const convex::ConvexContact c = convex::solve(*spec.curvatures, d);
    g.force_constant = c.force_constant;
    // Equal-area circle: a b = sqrt(x0) (C0 D N(x0) / pi)^2 xi, from BP04 (8.19).
    const double scale = c.force_constant * d * c.n_x0 / std::numbers::pi;
    g.equivalent_radius = std::sqrt(c.x0) * scale * scale;
  }
  return g;
}

std::unique_ptr<NormalForceModel> make_normal_force(const ModelSpec& spec, const Pair& pair) {
  const ModelInfo& info = model_info(spec.name);
  if (spec.name == "power-law") {
    if (!spec.power_law) {
      throw InvalidArgument("power_d1", "(not given)", "the power-law constants D1, D2 and exponents");
    }
    const PowerLawParameters& p = *spec.power_law;
    require_positive("power_d1", p.d1, "D1 > 0");
    require_non_negative("power_d2", p.d2, "D2");
    require_positive("power_alpha", p.alpha, "the elastic exponent alpha");
    require_positive("power_beta", p.beta, "the rate exponent beta");
    require_non_negative("power_gamma", p.gamma, "the overlap exponent gamma of the dissipative term");
    return make_power_law_force(p, pair.effective_mass(), pair.effective_radius());
  }
  const double a = dissipative_constant(spec, pair);
  const HertzGeometry geometry = hertz_geometry(spec, pair);
  if (spec.name == "viscoelastic-shifted") return make_shifted_viscoelastic_force(geometry, a);
  return make_viscoelastic_force(geometry, a, info.name);
}

}  // namespace bounce::models
