#include "warnings.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include <fmt/format.h>

#include "bounce/analytic/adhesive.hpp"
#include "bounce/analytic/viscoelastic.hpp"
#include "bounce/contact/hertz.hpp"
#include "bounce/contact/jkr.hpp"
#include "bounce/contact/surface_forces.hpp"

namespace bounce::analysis::detail {

namespace {

using dynamics::CollisionOutcome;

// The share of the impact energy taken by losses that scale with T_vis above which an outcome
// rests on T_vis (add_tvis_dependence_warning; docs/adhesive-models.md).
constexpr double tvis_dependence_share = 0.5;

// The duration the quasi-static conditions compare with: the contact time of a bounce. A
// sticking collision has none (the grains stay together); its contact_time is when the
// engine found sticking certain, at low speed long before the maximum compression, so it
// is no measure of how fast the contact changes. There the elastic Hertz contact time at
// the impact speed stands in when it is longer (exact constant of BSHP96 (A13));
// a collision that bounced in the engine and sticks by its plastic losses keeps its
// own, longer, contact time. docs/adhesive.md.
struct CollisionTime {
  double value;
  const char* name;
};
CollisionTime collision_time(const CollisionOutcome& out, const Pair& pair, double velocity) {
  const double hertz = contact::hertz::collision_time(pair.hertz_constant(), pair.effective_mass(), velocity);
  if (out.outcome == dynamics::Outcome::stick && hertz > out.contact_time) {
    return {hertz, "the elastic Hertz contact time (sticking stopped the integration earlier)"};
  }
  return {out.contact_time, "the contact time"};
}

// An E outside the range of grain materials is accepted (any E > 0 is valid) but said: it is
// most likely in the wrong unit (pair/material.hpp).
void add_material_warnings(CollisionOutcome& out, const Pair& pair) {
  const auto check = [&](const char* body, const Material& m) {
    const std::string name = m.name.empty() ? "explicit" : m.name;
    // Densities of grains from aerogels to osmium; surface energies of solids below ~10 J/m^2 (K13
    // table 2: 0.014-1.6): outside, a unit slip is likelier (g/cm^3, erg/cm^2 = mJ/m^2).
    if (m.density < 10.0 || m.density > 3e4)
      out.warnings.push_back(fmt::format("{} ({}): density = {:g} kg/m^3 is outside 10-30000 kg/m^3, the range of grain "
                                         "materials: is it in the unit [kg/m^3] ({:g} g/cm^3 would be {:g} kg/m^3)?",
                                         body, name, m.density, m.density, m.density * 1e3));
    if (m.surface_energy && *m.surface_energy > 10.0)
      out.warnings.push_back(fmt::format("{} ({}): gamma = {:g} J/m^2 is above 10 J/m^2, beyond the surface energies of "
                                         "solids: is it in the unit [J/m^2] ({:g} erg/cm^2 = mJ/m^2 would be {:g} J/m^2)?",
                                         body, name, *m.surface_energy, *m.surface_energy, *m.surface_energy * 1e-3));
    if (plausible_youngs_modulus(m.youngs_modulus)) return;
    out.warnings.push_back(fmt::format("{} ({}): Young's modulus E = {:g} Pa is outside {:g}-{:g} Pa, the range of grain "
                                       "materials from soft gels to diamond: is it in the unit [Pa]?",
                                       body, name, m.youngs_modulus,
                                       plausible_youngs_modulus_min, plausible_youngs_modulus_max));
  };
  check("body1", pair.body1().material);
  if (!pair.body2().rigid) check("body2", pair.body2().material);
}

// Quasi-static validity (BSHP96 (B11)-(B12), BP04 (8.26)), small strain, and the material's E.
void add_validity_warnings(CollisionOutcome& out, const Pair& pair, double velocity, double viscous_time,
                           const CollisionTime& t_c) {
  add_material_warnings(out, pair);
  const double c_t = pair.transversal_sound_speed();
  if (velocity > 0.1 * c_t) {
    out.warnings.push_back(fmt::format(
        "impact velocity {:.3g} m/s is not << the transversal sound speed {:.3g} m/s: the "
        "quasi-static approximation (BSHP96 (B11)) does not hold",
        velocity, c_t));
  }
  if (viscous_time > 0.1 * t_c.value && t_c.value > 0.0) {
    out.warnings.push_back(fmt::format("viscous time scale {:.3g} s is not << {} {:.3g} s (BSHP96 (B12), BP04 (8.26))",
                                       viscous_time, t_c.name, t_c.value));
  }
  const double strain = std::sqrt(out.max_overlap / pair.effective_radius());
  if (strain > 0.1) {
    out.warnings.push_back(fmt::format(
        "contact radius / R_eff = {:.3g} is not small: Hertz theory assumes small strains", strain));
  }
}

// K13 appendix A: where bulk and crack viscosity become negligible (the elastic JKR
// estimates do not apply otherwise); for K13's crack law.
void add_k13_appendix_a_warnings(CollisionOutcome& out, const Pair& pair, const models::KrijtParameters& p,
                                 double contact_time) {
  const double nu = std::sqrt(p.relaxation_time / p.dissipative_constant);
  const double bulk = analytic::bulk_quasi_static_limit(nu, contact_time);
  if (p.relaxation_time >= bulk) {
    out.warnings.push_back(fmt::format(
        "K13 (A.2) does not hold: T_vis = {:.3g} s >= 1e-2 nu^2 t_c = {:.3g} s, bulk viscous dissipation is "
        "significant (the elastic JKR estimate (24) does not apply)", p.relaxation_time, bulk));
  }
  const double gamma = p.surface_energy;
  const double a = out.max_overlap > 0.0
                       ? std::sqrt(pair.effective_radius() * out.max_overlap)
                       : contact::jkr::equilibrium_contact_radius({pair.effective_radius(), pair.effective_modulus(), gamma});
  const double crack = analytic::crack_quasi_static_limit(p.z0, a, p.effective_modulus, gamma, contact_time);
  if (p.relaxation_time >= crack) {
    out.warnings.push_back(fmt::format(
        "K13 (A.4) does not hold: T_vis = {:.3g} s >= {:.3g} s, adhesion hysteresis at the crack is "
        "significant (the elastic JKR estimate (24) does not apply)", p.relaxation_time, crack));
  }
}

// K13's viscous losses scale with T_vis: the crack's hysteresis through c = E* z0^2/(gamma T_vis)
// (K13 (16)) and, where A = T_vis/nu^2 (K13 after (18)), the bulk force (19). Of the impact energy
// E0 the rebound keeps e^2 E0, elastic JKR's snap-on and release take W (K13 (24)-(25), exact), plastic
// flow its own; the rest went to the T_vis losses (for a stick, e = 0: what they had to take).
// Over half, halving T_vis returns at least a quarter of E0 to the rebound (e up by >= 0.16) and
// doubling it takes all, to first order in T_vis: the outcome rests on T_vis (docs/adhesive-models.md).
void add_tvis_dependence_warning(CollisionOutcome& out, const models::Model& model, const models::KrijtParameters& p,
                                 double velocity) {
  const double e0 = 0.5 * p.effective_mass * velocity * velocity;
  const double jkr = analytic::jkr_collision_loss(p.effective_radius, p.effective_modulus, p.surface_energy);
  const double bulk_given = model.dissipative_constant_from_tvis ? 0.0 : out.energy.bulk_dissipated;
  const double share = 1.0 - out.cor * out.cor - (jkr + out.energy.plastic_dissipated + bulk_given) / e0;
  if (!(share > tvis_dependence_share)) return;
  const double v_c = std::sqrt(2.0 * jkr / p.effective_mass);
  const char* losses = model.dissipative_constant_from_tvis ? "the crack's hysteresis and the bulk damping (A = T_vis/nu^2)"
                                                            : "the crack's hysteresis";
  out.warnings.push_back(
      out.outcome == dynamics::Outcome::stick
          ? fmt::format("the outcome rests on T_vis: the grains stick only because {} took at least {:.2g} of the "
                        "impact energy (elastic JKR bounces above v_c = {:.3g} m/s); at a smaller T_vis they bounce "
                        "(docs/adhesive-models.md)", losses, share, v_c)
          : fmt::format("the outcome rests on T_vis: {} took {:.2g} of the impact energy, beyond elastic JKR's "
                        "snap-on and release; at half this T_vis e is higher by more than 0.1 "
                        "(docs/adhesive-models.md)", losses, share));
}

// K13 §2.1.2: the JKR-based adhesive models assume the Tabor parameter mu > 5.
void add_tabor_warning(CollisionOutcome& out, const Pair& pair, const models::Model& model) {
  const double gamma = *pair.surface_energy();
  const double mu = contact::surface::tabor_parameter(pair.effective_radius(), pair.effective_modulus(), gamma, model.z0);
  if (mu < 5.0) {
    out.warnings.push_back(fmt::format(
        "Tabor parameter mu = {:.3g} < 5 (K13 (11), z0 = {:g} m): the JKR-based adhesive model may not apply "
        "(DMT below 0.1, Maugis-Dugdale between)", mu, model.z0));
  }
}

// BP04 (8.99): a viscoelastic description ignores adhesion only while e g >> sqrt(2 W0/m),
// W0 the work of the JKR tensile force (8.95); BP04's own estimate (adhesive-
// viscoelastic) assumes the same weak adhesion. ">>" is taken as a factor 3 (9 in energy).
void add_adhesion_validity_warning(CollisionOutcome& out, const Pair& pair, double velocity, bool weak) {
  const auto gamma = pair.surface_energy();
  if (!gamma || *gamma <= 0.0) return;
  const double w0 = analytic::tensile_work(pair.effective_radius(), pair.effective_modulus(), *gamma);
  const double escape = std::sqrt(2.0 * w0 / pair.effective_mass());
  const double e = weak && out.outcome == dynamics::Outcome::bounce
                       ? std::sqrt(out.cor * out.cor + escape * escape / (velocity * velocity))  // e before adhesion
                       : out.cor;
  if (e * velocity >= 3.0 * escape) return;
  out.warnings.push_back(fmt::format(
      "BP04 (8.99) does not hold: e g = {:.3g} m/s is not >> sqrt(2 W0/m) = {:.3g} m/s (gamma = {:g} J/m^2): {}",
      e * velocity, escape, *gamma,
      weak ? "adhesion is not weak, BP04's estimate is rough (see krijt)"
           : "adhesion is not negligible, use an adhesive model"));
}

// BSHP96 states -1 <= eps^T <= 1; the published asperity law can leave that range by
// the energy its spring gains from the changing stiffness (docs/tangential.md).
void add_tangential_warnings(CollisionOutcome& out) {
  if (!out.tangential || std::abs(out.tangential->cor) <= 1.0) return;
  out.warnings.push_back(fmt::format(
      "|eps^T| = {:.4g} > 1: the published asperity law's spring gained {:.3g} J from its changing stiffness "
      "(BSHP96's bound -1 <= eps^T <= 1 fails; --asperity-form passive cannot gain energy)",
      std::abs(out.tangential->cor), out.tangential->stiffness_work));
}

// Far outside the viscous models (docs/models.md, "Validity"): they expand in A/t_c and T_vis/t_c
// (BSHP96 (B12), K13 (A.2)); a viscous time as long as the elastic contact itself describes no
// real collision (nu = 1e-6 made A = T_vis/nu^2 = 10 s). Said first, before any other warning.
void add_far_outside_warning(CollisionOutcome& out, const Pair& pair, const models::Model& model, double velocity) {
  const double t_h = contact::hertz::collision_time(pair.hertz_constant(), pair.effective_mass(), velocity);
  const auto* crack = std::get_if<models::CrackContact>(&model.normal);
  const double a = model.dissipative_constant.value_or(0.0);
  const double tvis = crack ? crack->parameters.relaxation_time : 0.0;
  const bool by_a = a >= tvis;
  const double longest = std::max(a, tvis);
  if (!(longest >= t_h) || !(t_h > 0.0)) return;
  out.warnings.insert(out.warnings.begin(),
                      fmt::format("far outside the model's validity: {} = {:.3g} s is {:.3g} times the elastic contact "
                                  "time t_H = {:.3g} s, where the viscous models need A, T_vis << t_c (BSHP96 (B12), "
                                  "K13 (A.2)){}: this result describes no real collision",
                                  by_a ? "A" : "T_vis", longest, longest / t_h, t_h,
                                  by_a ? "; A is the given one or T_vis / nu^2 (K13 after (18))" : ""));
}

}  // namespace

void add_warnings(CollisionOutcome& out, const Pair& pair, const models::Model& model, double velocity) {
  const CollisionTime t_c = collision_time(out, pair, velocity);
  add_validity_warnings(out, pair, velocity, model.viscous_time, t_c);
  const models::Adhesion adhesion = model.traits.adhesion;
  if (adhesion == models::Adhesion::jkr || adhesion == models::Adhesion::weak) add_tabor_warning(out, pair, model);
  const auto* crack = std::get_if<models::CrackContact>(&model.normal);
  if (crack && t_c.value > 0.0) add_k13_appendix_a_warnings(out, pair, crack->parameters, t_c.value);
  if (crack) add_tvis_dependence_warning(out, model, crack->parameters, velocity);
  if (adhesion == models::Adhesion::negligible || adhesion == models::Adhesion::weak) {
    add_adhesion_validity_warning(out, pair, velocity, adhesion == models::Adhesion::weak);
  }
  add_tangential_warnings(out);
  add_far_outside_warning(out, pair, model, velocity);
}

}  // namespace bounce::analysis::detail
