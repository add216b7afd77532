#include "bounce/models/registry.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"

namespace bounce::models {

const std::vector<ModelInfo>& collision_models() {
  static const std::vector<ModelInfo> table = {
      {"hertz", "elastic spheres, no dissipation", "BP04 (8.24), BSHP96 (14)", true, false, false},
      {"viscoelastic", "Hertz plus the quasi-static viscous force (3/2) A rho sqrt(xi) xi'",
       "BP04 (8.42), BSHP96 (24)", true, false, false},
      {"viscoelastic-shifted", "Hertz law at the shifted overlap xi + A xi', clamped at zero",
       "BSHP96 (25)", false, false, false},
      {"power-law", "F = m (D1 xi^alpha + D2 xi^gamma xi'^beta)", "BP04 (8.63)-(8.69)", false, false, false},
      {"adhesive-viscoelastic", "BP04's quasi-static adhesive force (8.56) with its dissipation (8.57)",
       "BP04 (8.56)-(8.58), SPEC §4.1", false, true, false},
      {"jkr-viscoelastic", "contact radius on the JKR equilibrium (instantaneous crack) plus the bulk force",
       "K13 (8), (9), (19), (20)", false, true, true},
      {"krijt", "K13's dynamic contact: independent a and delta, viscoelastic crack, bulk damping",
       "K13 (2), (14)-(21), appendices B, C", false, true, true},
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

double dissipative_constant_b(const ModelSpec& spec, const Pair& pair, double a) {
  if (spec.dissipative_constant_b) {
    return require_non_negative("B", *spec.dissipative_constant_b, "dissipative constant B [s] of BP04 (8.57)");
  }
  if (spec.shear_viscosity && spec.bulk_viscosity) {
    // SPEC §4.1: B = alpha beta = (3 eta2 - eta1)(1 + nu)(1 - 2 nu) / (3 E nu) (BP04 (8.58) corrected).
    const Material& m = pair.body1().material;
    const double nu = m.poisson_ratio;
    return (3.0 * *spec.bulk_viscosity - *spec.shear_viscosity) * (1.0 + nu) * (1.0 - 2.0 * nu) /
           (3.0 * m.youngs_modulus * nu);
  }
  // With equal relaxation times of shear and dilatation (eta_i = E_i tau) both A and
  // B equal tau (docs/adhesive.md), so B = A is the one-parameter choice.
  return a;
}

double dissipative_constant(const ModelSpec& spec, const Pair& pair) {
  if (spec.name == "hertz") {
    if (spec.dissipative_constant && *spec.dissipative_constant != 0.0) {
      throw InvalidArgument("A", format_value(*spec.dissipative_constant), "no A for the hertz model");
    }
    return 0.0;
  }
  const bool viscosities = spec.shear_viscosity || spec.bulk_viscosity;
  if (!spec.dissipative_constant && !viscosities && spec.relaxation_time) {
    return krijt_dissipative_constant(
        require_positive("tvis", *spec.relaxation_time, "viscous relaxation time T_vis [s]"), pair);
  }
  if (spec.dissipative_constant && viscosities) {
    throw InvalidArgument("A", format_value(*spec.dissipative_constant),
                          "either A or the viscosities eta1, eta2, not both");
  }
  if (spec.dissipative_constant) {
    return require_non_negative("A", *spec.dissipative_constant, "dissipative constant A [s]");
  }
  if (!viscosities) {
    throw InvalidArgument("A", "(not given)",
                          fmt::format("a dissipative constant A >= 0 s, eta1 and eta2, or T_vis (model {})",
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

KrijtParameters krijt_parameters(const ModelSpec& spec, const Pair& pair) {
  KrijtParameters p;
  p.effective_radius = pair.effective_radius();
  p.effective_modulus = pair.effective_modulus();
  p.effective_mass = pair.effective_mass();
  p.surface_energy = pair.require_surface_energy("model " + spec.name);
  require_positive("gamma", p.surface_energy, fmt::format("surface energy gamma [J/m^2] (model {} needs gamma > 0)", spec.name));
  if (spec.relaxation_time) {
    p.relaxation_time = require_positive("tvis", *spec.relaxation_time, "viscous relaxation time T_vis [s]");
  } else if (spec.name == "krijt" || !spec.dissipative_constant) {
    throw InvalidArgument("tvis", "(not given)",
                          fmt::format("a viscous relaxation time T_vis > 0 s (model {})", spec.name));
  }
  if (spec.dissipative_constant) {
    p.dissipative_constant = require_non_negative("A", *spec.dissipative_constant, "dissipative constant A [s]");
  } else {
    p.dissipative_constant = krijt_dissipative_constant(p.relaxation_time, pair);  // K13 after (18)
  }
  p.z0 = require_positive("z0", spec.z0, "equilibrium separation z0 [m]");
  p.k = require_open_interval("k", spec.k, 0.0, 1.0, "k (relaxed / instantaneous modulus)");
  return p;
}

std::unique_ptr<NormalForceModel> make_normal_force(const ModelSpec& spec, const Pair& pair) {
  const ModelInfo& info = model_info(spec.name);
  if (info.dynamic_contact) {
    throw InvalidArgument("model", spec.name, "a force-law model (krijt and jkr-viscoelastic integrate a(t))");
  }
  if (spec.name == "adhesive-viscoelastic") {
    const double gamma = pair.require_surface_energy("model adhesive-viscoelastic");
    require_positive("gamma", gamma, "surface energy gamma [J/m^2] (adhesive model needs gamma > 0)");
    AdhesiveViscoelasticParameters a;
    a.rho = pair.hertz_constant();
    // BP04 (8.56): C = sqrt(6 pi gamma / D) R_eff^{3/4}
    a.adhesion = std::sqrt(6.0 * std::numbers::pi * gamma / pair.hertz_compliance_d()) *
                 std::pow(pair.effective_radius(), 0.75);
    a.a = dissipative_constant(spec, pair);
    a.b = dissipative_constant_b(spec, pair, a.a);
    a.effective_mass = pair.effective_mass();
    a.effective_radius = pair.effective_radius();
    return make_adhesive_viscoelastic_force(a);
  }
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

models::TangentialModel tangential_model(const ModelSpec& spec, const Pair& pair) {
  models::TangentialModel t;
  t.law = spec.tangential_law;
  t.form = spec.asperity_form;
  t.kappa = pair.tangential_mass_factor();
  if (!spec.friction) throw InvalidArgument("friction", "(not given)", "a friction coefficient mu >= 0 (BSHP96 (36))");
  t.friction = require_non_negative("friction", *spec.friction, "friction coefficient mu");
  if (t.law == models::TangentialLaw::asperity) {
    if (!spec.asperity_size) {
      throw InvalidArgument("asperity", "(not given)", "an asperity size zeta0 > 0 m (BSHP96 (32))");
    }
    t.asperity_size = require_positive("asperity", *spec.asperity_size, "asperity size zeta0 [m] (BSHP96 (32))");
  } else {
    if (!spec.shear_damping) {
      throw InvalidArgument("shear_damping", "(not given)", "a shear damping gamma_s >= 0 1/s (BSHP96 (39))");
    }
    t.shear_damping = require_non_negative("shear_damping", *spec.shear_damping, "shear damping gamma_s [1/s]");
  }
  validate(t);
  return t;
}

}  // namespace bounce::models
