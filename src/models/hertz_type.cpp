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
#include "bounce/pair/material.hpp"

namespace bounce::models::detail {

double HertzTypeForce::elastic_force(double xi) const { return contact::hertz::force(g_.force_constant, xi); }
double HertzTypeForce::elastic_energy(double xi) const { return contact::hertz::elastic_energy(g_.force_constant, xi); }
double HertzTypeForce::contact_radius(double xi) const { return contact::hertz::contact_radius(g_.equivalent_radius, xi); }
double HertzTypeForce::reference_overlap(double speed) const {  // BP04 (8.65), alpha = 3/2
  return power_law_reference_overlap(g_.force_constant / g_.effective_mass, 1.5, speed);
}

namespace {
// BP04 (8.38) is derived for one material; a rigid wall does not deform. Both viscosities are
// given (the parameter table's rule).
double from_viscosities(const Pair& pair, const ViscousParameters& p) {
  const double eta1 = p.shear_viscosity.value_or(0.0), eta2 = p.bulk_viscosity.value_or(0.0);
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

// The bound falls with t_H(c_t): a modulus typed in the wrong unit (E = 1e30 Pa) shrinks it, and
// the refusal of T_vis or A then asks about E (as the impact velocity's does, issue 40 point 4).
double require_short_viscous_time(const Pair& pair, double value, const std::string& name, const std::string& what) {
  const double longest = longest_viscous_time(pair), t_h = shortest_contact_time(pair);
  if (value <= longest) return value;
  std::string question = youngs_modulus_unit_question("E", pair.body1().material.youngs_modulus);
  if (question.empty() && !pair.body2().rigid) {
    question = youngs_modulus_unit_question("E2", pair.body2().material.youngs_modulus);
  }
  throw InvalidArgument(name, format_value(value),
                        fmt::format("{} <= {:.3g} s, {:g} times the shortest elastic contact time of the pair, t_H(c_t) = "
                                    "{:.3g} s: the viscous models need it << the contact time (BSHP96 (B12)){}",
                                    what, longest, longest_viscous_time_ratio, t_h,
                                    question.empty() ? "" : "; " + question));
}

// One of A, the viscosities or T_vis is given (the parameter table's rule, checked where the
// model is made).
double dissipative_constant(const Pair& pair, const ViscousParameters& p) {
  if (p.dissipative_constant) {
    return require_short_viscous_time(pair, *p.dissipative_constant, "A", "a dissipative constant A [s]");
  }
  if (p.relaxation_time) return krijt_dissipative_constant(*p.relaxation_time, pair);  // K13 after (18)
  return from_viscosities(pair, p);
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

// The adhesive pair of a contact model: gamma of the pair, A (given, or T_vis / nu^2 by K13
// after (18): one of them is, the parameter table's rule), z0.
AdhesivePair adhesive_pair(const Pair& pair, const ContactModelParameters& p, std::string_view name) {
  AdhesivePair out;
  out.effective_radius = pair.effective_radius();
  out.effective_modulus = pair.effective_modulus();
  out.effective_mass = pair.effective_mass();
  out.surface_energy = adhesive_surface_energy(pair, name);
  const std::optional<double> tvis =
      p.relaxation_time ? std::optional(require_short_viscous_time(pair, *p.relaxation_time, "tvis",
                                                                   "a viscous relaxation time T_vis [s]"))
                        : std::nullopt;
  out.dissipative_constant = p.dissipative_constant
                                 ? require_short_viscous_time(pair, *p.dissipative_constant, "A", "a dissipative constant A [s]")
                                 : krijt_dissipative_constant(tvis.value_or(0.0), pair);
  out.z0 = p.z0;
  return out;
}

// K13's parameters: the adhesive pair, T_vis (given: the table's rule) and k.
KrijtParameters krijt_parameters(const Pair& pair, const CrackModelParameters& p) {
  KrijtParameters out;
  static_cast<AdhesivePair&>(out) = adhesive_pair(pair, p, "krijt");
  out.relaxation_time = p.relaxation_time.value_or(0.0);
  out.k = p.k;
  return out;
}

AdhesiveRelease adhesive_release(EndRule rule) {
  return rule == EndRule::pull_off ? AdhesiveRelease::pull_off : AdhesiveRelease::fold;
}

}  // namespace bounce::models::detail

namespace bounce::models {

double longest_viscous_time(const Pair& pair) {
  return detail::longest_viscous_time_ratio * detail::shortest_contact_time(pair);
}

}  // namespace bounce::models
