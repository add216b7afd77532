#include "hertz_type.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "bounce/contact/hertz.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/models/krijt.hpp"
#include "bounce/models/registry.hpp"

namespace bounce::models::detail {

double HertzTypeForce::elastic_force(double xi) const { return contact::hertz::force(g_.force_constant, xi); }
double HertzTypeForce::elastic_energy(double xi) const { return contact::hertz::elastic_energy(g_.force_constant, xi); }
double HertzTypeForce::contact_radius(double xi) const { return contact::hertz::contact_radius(g_.equivalent_radius, xi); }
double HertzTypeForce::reference_overlap(double speed) const {  // BP04 (8.65), alpha = 3/2
  return power_law_reference_overlap(g_.force_constant / g_.effective_mass, 1.5, speed);
}

namespace {
// BP04 (8.38) is derived for one material; a rigid wall does not deform.
double from_viscosities(const Pair& pair, const Parameters& p) {
  if (!p.given("eta1")) throw InvalidArgument("eta1", "(not given)", "a shear viscosity >= 0 Pa s");
  if (!p.given("eta2")) throw InvalidArgument("eta2", "(not given)", "a bulk viscosity >= 0 Pa s");
  const double eta1 = *p.real("eta1"), eta2 = *p.real("eta2");
  if (eta1 == 0.0 && eta2 == 0.0) return 0.0;
  const Material& m1 = pair.body1().material;
  const Material& m2 = pair.body2().material;
  if (!pair.body2().rigid && (m1.youngs_modulus != m2.youngs_modulus || m1.poisson_ratio != m2.poisson_ratio)) {
    throw InvalidArgument("eta1", p.typed("eta1"),
                          "viscosities only for bodies of one material (BP04 (8.38)); give A for unlike pairs");
  }
  if (m1.poisson_ratio <= 0.0) {
    throw InvalidArgument("nu", format_value(m1.poisson_ratio),
                          "0 < nu < 0.5 for A from viscosities (BP04 (8.38) divides by nu^2)");
  }
  return dissipative_constant_from_viscosities(eta1, eta2, m1.youngs_modulus, m1.poisson_ratio);
}
}  // namespace

double dissipative_constant(const Pair& pair, const Parameters& p, std::string_view model) {
  const bool a = p.given("A"), viscosities = p.given("eta1") || p.given("eta2"), tvis = p.given("tvis");
  if (a + viscosities + tvis > 1) {  // name the second way given: A beats eta1, eta2, which beat tvis
    std::string second = "tvis";
    for (const char* name : {"eta1", "eta2"}) {
      if (a && p.given(name)) second = name;
    }
    throw InvalidArgument(second, p.typed(second),
                          "one of A, the viscosities eta1 and eta2, or T_vis, not two");
  }
  if (a) return *p.real("A");
  if (tvis) return krijt_dissipative_constant(*p.real("tvis"), pair);  // K13 after (18)
  if (viscosities) return from_viscosities(pair, p);
  throw InvalidArgument("A", "(not given)",
                        fmt::format("a dissipative constant A >= 0 s, eta1 and eta2, or T_vis (model {})", model));
}

double viscous_time(const Pair& pair, const Parameters& p, double a) {
  if (!(p.given("eta1") || p.given("eta2"))) return a;
  const Material& m = pair.body1().material;  // BSHP96 (B13): E1 = E/(1+nu), E2 = E/(3(1-2nu))
  const double e1 = m.youngs_modulus / (1.0 + m.poisson_ratio);
  const double e2 = m.youngs_modulus / (3.0 * (1.0 - 2.0 * m.poisson_ratio));
  return std::max(p.real("eta1").value_or(0.0) / e1, p.real("eta2").value_or(0.0) / e2);
}

std::optional<contact::convex::Curvatures> curvatures(const Pair& pair, const Parameters& p) {
  return contact::convex::curvatures_from(p, pair.body2().is_wall());
}

HertzGeometry hertz_geometry(const Pair& pair, const std::optional<contact::convex::Curvatures>& shape) {
  HertzGeometry g{pair.hertz_constant(), pair.effective_radius(), pair.effective_mass()};
  if (shape) {
    const double d = pair.hertz_compliance_d();
    const contact::convex::ConvexContact c = contact::convex::solve(*shape, d);
    g.force_constant = c.force_constant;  // BP04 (8.21)
    // Equal-area circle: a b = sqrt(x0) (C0 D N(x0) / pi)^2 xi, from BP04 (8.19).
    const double scale = c.force_constant * d * c.n_x0 / std::numbers::pi;
    g.equivalent_radius = std::sqrt(c.x0) * scale * scale;
  }
  return g;
}

double adhesive_surface_energy(const Pair& pair, std::string_view model) {
  const std::string who = "model " + std::string(model);
  const double gamma = pair.require_surface_energy(who);
  return require_positive("gamma", gamma, fmt::format("surface energy gamma [J/m^2] ({} needs gamma > 0)", who));
}

// K13's parameters for the pair: gamma of the pair, T_vis, A (given, or T_vis / nu^2 by
// K13 after (18)), z0 and k. krijt needs T_vis (its crack law); jkr-viscoelastic A or T_vis.
KrijtParameters contact_parameters(const Pair& pair, const Parameters& p, std::string_view name, bool needs_tvis) {
  KrijtParameters k;
  k.effective_radius = pair.effective_radius();
  k.effective_modulus = pair.effective_modulus();
  k.effective_mass = pair.effective_mass();
  k.surface_energy = adhesive_surface_energy(pair, name);
  if (p.given("tvis")) {
    k.relaxation_time = *p.real("tvis");
  } else if (needs_tvis || !p.given("A")) {
    throw InvalidArgument("tvis", "(not given)", fmt::format("a viscous relaxation time T_vis > 0 s (model {})", name));
  }
  k.dissipative_constant = p.given("A") ? *p.real("A") : krijt_dissipative_constant(k.relaxation_time, pair);
  k.z0 = *p.real("z0");
  if (needs_tvis) k.k = *p.real("k");
  return k;
}

// The slots of a model with K13's parameters.
Model contact_model(const KrijtParameters& k, const Parameters& p, NormalInteraction normal) {
  Model m;
  m.normal = std::move(normal);
  m.dissipative_constant = k.dissipative_constant;
  m.viscous_time = p.given("tvis") ? k.relaxation_time : k.dissipative_constant;
  m.z0 = k.z0;
  return m;
}

AdhesiveRelease adhesive_release(const Parameters& p) {
  return parse_end_rule(p.text("contact_end")) == EndRule::pull_off ? AdhesiveRelease::pull_off : AdhesiveRelease::fold;
}

}  // namespace bounce::models::detail
