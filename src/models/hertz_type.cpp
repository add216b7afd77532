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
double from_viscosities(const Pair& pair, const ViscousParameters& p) {
  if (!p.shear_viscosity) throw InvalidArgument("eta1", "(not given)", "a shear viscosity >= 0 Pa s");
  if (!p.bulk_viscosity) throw InvalidArgument("eta2", "(not given)", "a bulk viscosity >= 0 Pa s");
  const double eta1 = *p.shear_viscosity, eta2 = *p.bulk_viscosity;
  if (eta1 == 0.0 && eta2 == 0.0) return 0.0;
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
}  // namespace

double shortest_contact_time(const Pair& pair) {  // BSHP96 (A13) at g = c_t
  return contact::hertz::collision_time(pair.hertz_constant(), pair.effective_mass(), pair.transversal_sound_speed());
}

double require_short_viscous_time(const Pair& pair, double value, const std::string& name, const std::string& what) {
  const double t_h = shortest_contact_time(pair);
  if (value <= longest_viscous_time_ratio * t_h) return value;
  throw InvalidArgument(name, format_value(value),
                        fmt::format("{} <= {:.3g} s, {:g} times the shortest elastic contact time of the pair, t_H(c_t) = "
                                    "{:.3g} s: the viscous models need it << the contact time (BSHP96 (B12))",
                                    what, longest_viscous_time_ratio * t_h, longest_viscous_time_ratio, t_h));
}

double dissipative_constant(const Pair& pair, const ViscousParameters& p, std::string_view model) {
  const bool a = p.dissipative_constant.has_value(), tvis = p.relaxation_time.has_value();
  const bool viscosities = p.shear_viscosity || p.bulk_viscosity;
  if (a + viscosities + tvis > 1) {  // name the second way given: A beats eta1, eta2, which beat tvis
    std::pair<const char*, double> second{"tvis", p.relaxation_time.value_or(0.0)};
    if (a && p.bulk_viscosity) second = {"eta2", *p.bulk_viscosity};
    if (a && p.shear_viscosity) second = {"eta1", *p.shear_viscosity};
    throw InvalidArgument(second.first, format_value(second.second),
                          "one of A, the viscosities eta1 and eta2, or T_vis, not two");
  }
  if (a) return require_short_viscous_time(pair, *p.dissipative_constant, "A", "a dissipative constant A [s]");
  if (tvis) return krijt_dissipative_constant(*p.relaxation_time, pair);  // K13 after (18)
  if (viscosities) return from_viscosities(pair, p);
  throw InvalidArgument("A", "(not given)",
                        fmt::format("a dissipative constant A >= 0 s, eta1 and eta2, or T_vis (model {})", model));
}

double viscous_time(const Pair& pair, const ViscousParameters& p, double a) {
  if (!(p.shear_viscosity || p.bulk_viscosity)) return a;
  const Material& m = pair.body1().material;  // BSHP96 (B13): E1 = E/(1+nu), E2 = E/(3(1-2nu))
  const double e1 = m.youngs_modulus / (1.0 + m.poisson_ratio);
  const double e2 = m.youngs_modulus / (3.0 * (1.0 - 2.0 * m.poisson_ratio));
  return std::max(p.shear_viscosity.value_or(0.0) / e1, p.bulk_viscosity.value_or(0.0) / e2);
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
// K13 after (18)), z0 and k. krijt needs T_vis (its crack law); the others A or T_vis.
KrijtParameters contact_parameters(const Pair& pair, const ContactModelParameters& p, std::string_view name,
                                   std::optional<double> k) {
  KrijtParameters out;
  out.effective_radius = pair.effective_radius();
  out.effective_modulus = pair.effective_modulus();
  out.effective_mass = pair.effective_mass();
  out.surface_energy = adhesive_surface_energy(pair, name);
  if (p.relaxation_time) {
    out.relaxation_time = require_short_viscous_time(pair, *p.relaxation_time, "tvis", "a viscous relaxation time T_vis [s]");
  } else if (k || !p.dissipative_constant) {
    throw InvalidArgument("tvis", "(not given)",
                          fmt::format("a viscous relaxation time T_vis > 0 s (model {}{})", name, k ? "" : "; or A"));
  }
  out.dissipative_constant = p.dissipative_constant
                                 ? require_short_viscous_time(pair, *p.dissipative_constant, "A", "a dissipative constant A [s]")
                                 : krijt_dissipative_constant(out.relaxation_time, pair);
  out.z0 = p.z0;
  if (k) out.k = *k;
  return out;
}

// The slots of a model with K13's parameters.
Model contact_model(const KrijtParameters& k, const ContactModelParameters& p, NormalInteraction normal) {
  Model m;
  m.normal = std::move(normal);
  m.dissipative_constant = k.dissipative_constant;
  m.dissipative_constant_from_tvis = !p.dissipative_constant.has_value();  // contact_parameters: then T_vis / nu^2
  m.viscous_time = p.relaxation_time ? k.relaxation_time : k.dissipative_constant;
  m.z0 = k.z0;
  return m;
}

AdhesiveRelease adhesive_release(EndRule rule) {
  return rule == EndRule::pull_off ? AdhesiveRelease::pull_off : AdhesiveRelease::fold;
}

}  // namespace bounce::models::detail
