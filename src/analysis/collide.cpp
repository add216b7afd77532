#include "bounce/analysis/collide.hpp"

#include <cmath>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "bounce/analytic/adhesive.hpp"
#include "bounce/analytic/master_curve.hpp"
#include "bounce/analytic/viscoelastic.hpp"
#include "bounce/contact/jkr.hpp"
#include "bounce/contact/surface_forces.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/dynamics/adhesive_collision.hpp"
#include "bounce/dynamics/normal_collision.hpp"

namespace bounce {

namespace {

// BSHP96 (B3): transversal speed of sound c_t = sqrt(E / (2 rho (1 + nu))).
double transversal_sound_speed(const Material& m) {
  return std::sqrt(m.youngs_modulus / (2.0 * m.density * (1.0 + m.poisson_ratio)));
}

// Quasi-static validity (BSHP96 (B11)-(B12), BP04 (8.26)) and small strain.
void add_validity_warnings(dynamics::CollisionOutcome& out, const Pair& pair, double velocity,
                           double viscous_time) {
  double c_t = transversal_sound_speed(pair.body1().material);
  if (!pair.body2().rigid) c_t = std::min(c_t, transversal_sound_speed(pair.body2().material));
  if (velocity > 0.1 * c_t) {
    out.warnings.push_back(fmt::format(
        "impact velocity {:.3g} m/s is not << the transversal sound speed {:.3g} m/s: the "
        "quasi-static approximation (BSHP96 (B11)) does not hold",
        velocity, c_t));
  }
  if (viscous_time > 0.1 * out.contact_time && out.contact_time > 0.0) {
    out.warnings.push_back(fmt::format(
        "viscous time scale {:.3g} s is not << the contact time {:.3g} s (BSHP96 (B12), BP04 (8.26))",
        viscous_time, out.contact_time));
  }
  const double strain = std::sqrt(out.max_overlap / pair.effective_radius());
  if (strain > 0.1) {
    out.warnings.push_back(fmt::format(
        "contact radius / R_eff = {:.3g} is not small: Hertz theory assumes small strains", strain));
  }
}

bool has_master_curve(const models::ModelSpec& spec) {
  return models::model_info(spec.name).has_master_curve;
}

dynamics::CollisionOutcome from_master(const models::ModelSpec& spec, const Pair& pair, double velocity) {
  const ViscoelasticScales s = viscoelastic_scales(pair, spec, velocity);
  const analytic::MasterValues v = analytic::viscoelastic_master(s.kappa, spec.end_rule);
  dynamics::CollisionOutcome out;
  out.method = "master";
  out.cor = v.cor;
  out.outcome = dynamics::Outcome::bounce;
  out.contact_time = v.contact_time * s.reference_overlap / velocity;
  out.max_overlap = v.max_overlap * s.reference_overlap;
  const double m = pair.effective_mass();
  dynamics::EnergyBudget& e = out.energy;
  e.initial_kinetic = 0.5 * m * velocity * velocity;
  e.final_kinetic = e.initial_kinetic * v.cor * v.cor;
  if (spec.end_rule == models::EndRule::force) {
    // At F = 0: xi' = -(2/3) xi / A, so the overlap left is xi = (3/2) A e g.
    const double xi_end = 1.5 * s.dissipative_constant * v.cor * velocity;
    e.elastic_remaining = 0.4 * s.force_constant * xi_end * xi_end * std::sqrt(xi_end);
  }
  e.bulk_dissipated = e.initial_kinetic - e.final_kinetic - e.elastic_remaining;
  return out;
}

// K13 §2.1.2: the JKR-based adhesive models assume the Tabor parameter mu > 5; K13
// appendix A: where bulk and crack viscosity become negligible (reported as notes
// that the elastic JKR estimates do not apply).
void add_adhesive_warnings(dynamics::CollisionOutcome& out, const models::ModelSpec& spec, const Pair& pair) {
  const double gamma = *pair.surface_energy();
  const double mu = surface::tabor_parameter(pair.effective_radius(), pair.effective_modulus(), gamma, spec.z0);
  if (mu < 5.0) {
    out.warnings.push_back(fmt::format(
        "Tabor parameter mu = {:.3g} < 5 (K13 (11), z0 = {:g} m): the JKR-based adhesive model may not apply "
        "(DMT below 0.1, Maugis-Dugdale between)", mu, spec.z0));
  }
  if (spec.name != "krijt" || out.contact_time <= 0.0) return;
  const models::KrijtParameters p = models::krijt_parameters(spec, pair);
  const double nu = std::sqrt(p.relaxation_time / p.dissipative_constant);
  const double bulk = analytic::bulk_quasi_static_limit(nu, out.contact_time);
  if (p.relaxation_time >= bulk) {
    out.warnings.push_back(fmt::format(
        "K13 (A.2) does not hold: T_vis = {:.3g} s >= 1e-2 nu^2 t_c = {:.3g} s, bulk viscous dissipation is "
        "significant (the elastic JKR estimate (24) does not apply)", p.relaxation_time, bulk));
  }
  const double a = out.max_overlap > 0.0 ? std::sqrt(pair.effective_radius() * out.max_overlap)
                                         : jkr::equilibrium_contact_radius({pair.effective_radius(), pair.effective_modulus(), gamma});
  const double crack = analytic::crack_quasi_static_limit(p.z0, a, p.effective_modulus, gamma, out.contact_time);
  if (p.relaxation_time >= crack) {
    out.warnings.push_back(fmt::format(
        "K13 (A.4) does not hold: T_vis = {:.3g} s >= {:.3g} s, adhesion hysteresis at the crack is "
        "significant (the elastic JKR estimate (24) does not apply)", p.relaxation_time, crack));
  }
}

// BP04 (8.99): a viscoelastic description ignores adhesion only while e g >> sqrt(2 W0/m),
// W0 the work of the JKR tensile force (8.95); BP04's own estimate (adhesive-
// viscoelastic) assumes the same weak adhesion. ">>" is taken as a factor 3 (9 in energy).
void add_adhesion_validity_warning(dynamics::CollisionOutcome& out, const Pair& pair, double velocity,
                                   const std::string& model) {
  const auto gamma = pair.surface_energy();
  if (!gamma || *gamma <= 0.0) return;
  const double w0 = analytic::tensile_work(pair.effective_radius(), pair.effective_modulus(), *gamma);
  const double escape = std::sqrt(2.0 * w0 / pair.effective_mass());
  const double e = model == "adhesive-viscoelastic" && out.outcome == dynamics::Outcome::bounce
                       ? std::sqrt(out.cor * out.cor + escape * escape / (velocity * velocity))  // e before adhesion
                       : out.cor;
  if (e * velocity >= 3.0 * escape) return;
  out.warnings.push_back(fmt::format(
      "BP04 (8.99) does not hold: e g = {:.3g} m/s is not >> sqrt(2 W0/m) = {:.3g} m/s (gamma = {:g} J/m^2): {}",
      e * velocity, escape, *gamma,
      model == "adhesive-viscoelastic" ? "adhesion is not weak, BP04's estimate is rough (see krijt)"
                                       : "adhesion is not negligible, use an adhesive model"));
}

// BSHP96 states -1 <= eps^T <= 1; the published asperity law can leave that range by
// the energy its spring gains from the changing stiffness (SPEC §5, docs/tangential.md).
void add_tangential_warnings(dynamics::CollisionOutcome& out) {
  if (!out.tangential || std::abs(out.tangential->cor) <= 1.0) return;
  out.warnings.push_back(fmt::format(
      "|eps^T| = {:.4g} > 1: the published asperity law's spring gained {:.3g} J from its changing stiffness "
      "(BSHP96's bound -1 <= eps^T <= 1 fails; --asperity-form passive cannot gain energy)",
      std::abs(out.tangential->cor), out.tangential->stiffness_work));
}

// The tangential motion of an oblique collision of a dynamic-contact model, driven by
// the recorded normal force.
void add_tangential(dynamics::CollisionOutcome& out, const Pair& pair, const models::TangentialModel& model,
                    const CollideOptions& options) {
  if (out.outcome != dynamics::Outcome::bounce) {
    out.notes.push_back("the grains stick: no tangential restitution");
    return;
  }
  out.tangential = dynamics::integrate_tangential_motion(out.trajectory, pair.effective_mass(),
                                                         options.tangential_velocity, model, options.integration);
  out.notes.push_back("tangential motion driven by the recorded F^N(t) (monotone cubic interpolation)");
}

// K13 (28)-(30): plastic losses added to any model when a yield strength is given.
void add_plastic_losses(dynamics::CollisionOutcome& out, const Pair& pair, double velocity, double yield) {
  require_positive("yield", yield, "yield strength Y [Pa]");
  const double v_y = analytic::yield_velocity(pair.effective_radius(), pair.effective_mass(),
                                              pair.effective_modulus(), yield);
  const double e_p = analytic::cor_thornton_ning(velocity, v_y);
  dynamics::EnergyBudget& e = out.energy;
  if (out.outcome == dynamics::Outcome::stick) return;  // nothing left to lose plastically
  const double e_total = analytic::cor_with_plastic(out.cor, e_p);
  e.plastic_dissipated = e.final_kinetic - e.initial_kinetic * e_total * e_total;
  e.final_kinetic = e.initial_kinetic * e_total * e_total;
  if (e_total == 0.0) {
    out.outcome = dynamics::Outcome::stick;
    out.warnings.push_back(
        "K13 (30) gives e^2 < 0: the plastic loss exceeds what adhesion and viscosity left, the grains stick");
  }
  out.cor = e_total;
}

double viscous_time_scale(const models::ModelSpec& spec, const Pair& pair) {
  if (spec.name == "power-law") return 0.0;
  if (models::model_info(spec.name).dynamic_contact) {
    return spec.relaxation_time.value_or(models::dissipative_constant(spec, pair));
  }
  const double a = models::dissipative_constant(spec, pair);
  if (spec.shear_viscosity || spec.bulk_viscosity) {
    // BSHP96 (B13): tau_i = eta_i / E_i with E1 = E/(1+nu), E2 = E/(3(1-2nu)).
    const Material& m = pair.body1().material;
    const double e1 = m.youngs_modulus / (1.0 + m.poisson_ratio);
    const double e2 = m.youngs_modulus / (3.0 * (1.0 - 2.0 * m.poisson_ratio));
    return std::max(spec.shear_viscosity.value_or(0.0) / e1, spec.bulk_viscosity.value_or(0.0) / e2);
  }
  return a;  // for eta2/E2 = eta1/E1 = tau, (8.38) gives exactly A = tau
}

}  // namespace

Method parse_method(const std::string& text) {
  if (text == "integrate") return Method::integrate;
  if (text == "master") return Method::master;
  if (text == "auto") return Method::automatic;
  throw InvalidArgument("method", text, "integrate, master or auto");
}

ViscoelasticScales viscoelastic_scales(const Pair& pair, const models::ModelSpec& spec, double velocity) {
  require_positive("velocity", velocity, "impact velocity [m/s]");
  ViscoelasticScales s;
  const models::HertzGeometry g = models::hertz_geometry(spec, pair);
  s.dissipative_constant = models::dissipative_constant(spec, pair);
  s.force_constant = g.force_constant;
  const double m = pair.effective_mass();
  s.kappa = analytic::kappa(s.dissipative_constant, g.force_constant, m, velocity);
  s.q = analytic::expansion_variable(s.kappa);
  s.characteristic_velocity = s.dissipative_constant > 0.0
                                  ? analytic::characteristic_velocity(s.dissipative_constant, g.force_constant, m)
                                  : std::numeric_limits<double>::infinity();
  s.reference_overlap = std::pow(1.25 * m * velocity * velocity / g.force_constant, 0.4);  // (8.65)
  s.hertz_contact_time = analytic::hertz_contact_time(g.force_constant, m, velocity);
  return s;
}

dynamics::CollisionOutcome collide(const Pair& pair, const models::ModelSpec& spec, double velocity,
                                   const CollideOptions& options) {
  require_positive("velocity", velocity, "impact velocity [m/s]");
  const models::ModelInfo& info = models::model_info(spec.name);
  if (info.dynamic_contact) {
    if (options.method == Method::master) {
      throw InvalidArgument("method", "master", fmt::format("integrate for model {} (it has no master curve)", spec.name));
    }
    if (spec.end_rule == models::EndRule::force) {
      throw InvalidArgument("contact_end", "force", fmt::format("overlap for model {} (its contact ends when the crack runs away)", spec.name));
    }
    const models::KrijtParameters p = models::krijt_parameters(spec, pair);
    const bool oblique = options.tangential_velocity > 0.0;
    const auto tangential = oblique ? std::optional(models::tangential_model(spec, pair)) : std::nullopt;
    dynamics::AdhesiveCollisionOptions o;
    o.relative_tolerance = options.adhesive_tolerance;
    o.engine = options.stiff_engine;
    // An oblique collision drives its tangential motion with the recorded F^N(t).
    o.record_trajectory = options.record_trajectory || oblique;
    o.trajectory_points = oblique ? std::max(options.trajectory_points, 4000) : options.trajectory_points;
    o.follow_time = options.follow_time;
    o.max_steps = std::min(options.integration.max_steps, o.max_steps);
    const double hysteresis = models::krijt_hysteresis_estimate(p, velocity);
    const bool reduced = spec.name == "krijt" && hysteresis < models::krijt_reduction_threshold;
    dynamics::CollisionOutcome out = spec.name == "krijt" && !reduced
                                         ? dynamics::integrate_krijt_collision(p, velocity, o)
                                         : dynamics::integrate_jkr_viscoelastic_collision(p, velocity, o);
    if (reduced) {
      out.notes.push_back(fmt::format(
          "the crack is so fast that its hysteresis ({:.2g} of the impact energy) is below the integration "
          "error: integrated as the fast-crack limit jkr-viscoelastic (singular-perturbation reduction)",
          hysteresis));
    }
    if (oblique) {
      add_tangential(out, pair, *tangential, options);
      if (!options.record_trajectory) out.trajectory.clear();
    }
    if (spec.yield_strength) add_plastic_losses(out, pair, velocity, *spec.yield_strength);
    add_validity_warnings(out, pair, velocity, viscous_time_scale(spec, pair));
    add_adhesive_warnings(out, spec, pair);
    add_tangential_warnings(out);
    return out;
  }
  const auto force = models::make_normal_force(spec, pair);  // validates the model
  bool use_master = false;
  switch (options.method) {
    case Method::automatic:
      use_master = has_master_curve(spec) && !options.record_trajectory;
      break;
    case Method::master:
      if (!has_master_curve(spec)) {
        throw InvalidArgument("method", "master",
                              fmt::format("integrate for model {} (it has no master curve)", spec.name));
      }
      if (options.record_trajectory) {
        throw InvalidArgument("method", "master", "integrate when a trajectory is requested");
      }
      use_master = true;
      break;
    case Method::integrate:
      break;
  }
  dynamics::CollisionOutcome out;
  if (options.tangential_velocity > 0.0 && options.method == Method::master) {
    throw InvalidArgument("method", "master", "integrate or auto for an oblique collision (it is integrated)");
  }
  if (options.tangential_velocity > 0.0) {  // oblique: normal and tangential motion together
    const models::TangentialModel tangential = models::tangential_model(spec, pair);
    dynamics::NormalCollisionOptions o;
    o.end_rule = spec.end_rule;
    o.integration = options.integration;
    auto both = dynamics::integrate_tangential_collision(*force, pair.effective_mass(), velocity,
                                                         options.tangential_velocity, tangential, o);
    out = std::move(both.normal);
    if (out.outcome == dynamics::Outcome::bounce) {
      out.tangential = both.tangential;
    } else {
      out.notes.push_back("the grains stick: no tangential restitution");
    }
    if (options.record_trajectory) {  // the normal motion does not feel F^T
      o.record_trajectory = true;
      o.trajectory_points = options.trajectory_points;
      out.trajectory = dynamics::integrate_normal_collision(*force, pair.effective_mass(), velocity, o).trajectory;
    }
  } else if (use_master) {
    out = from_master(spec, pair, velocity);
  } else {
    dynamics::NormalCollisionOptions o;
    o.end_rule = spec.end_rule;
    o.integration = options.integration;
    o.record_trajectory = options.record_trajectory;
    o.trajectory_points = options.trajectory_points;
    out = dynamics::integrate_normal_collision(*force, pair.effective_mass(), velocity, o);
  }
  if (spec.yield_strength) add_plastic_losses(out, pair, velocity, *spec.yield_strength);
  add_validity_warnings(out, pair, velocity, viscous_time_scale(spec, pair));
  if (info.adhesive) add_adhesive_warnings(out, spec, pair);
  if (spec.name != "power-law") add_adhesion_validity_warning(out, pair, velocity, spec.name);
  add_tangential_warnings(out);
  return out;
}

double cor(const Pair& pair, const models::ModelSpec& model, double velocity, const CollideOptions& options) {
  return collide(pair, model, velocity, options).cor;
}

std::vector<dynamics::CollisionOutcome> collide_curve(const Pair& pair, const models::ModelSpec& model,
                                                      const std::vector<double>& velocities,
                                                      const CollideOptions& options,
                                                      const std::function<void(std::size_t, std::size_t)>& progress) {
  std::vector<dynamics::CollisionOutcome> out;
  out.reserve(velocities.size());
  for (std::size_t i = 0; i < velocities.size(); ++i) {
    out.push_back(collide(pair, model, velocities[i], options));
    if (progress) progress(i + 1, velocities.size());
  }
  return out;
}

MergedBody merged_body(const Pair& pair, double velocity) {  // momentum conservation
  MergedBody m;
  const double m1 = pair.body1().mass(), m2 = pair.body2().mass();
  if (pair.body2().is_wall()) {
    m.mass = std::numeric_limits<double>::infinity();
    m.velocity = 0.0;
  } else {
    m.mass = m1 + m2;
    m.velocity = m1 * velocity / (m1 + m2);
  }
  return m;
}

}  // namespace bounce
