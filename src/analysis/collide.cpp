#include "bounce/analysis/collide.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <variant>

#include <fmt/format.h>

#include "bounce/analytic/adhesive.hpp"
#include "bounce/analytic/master_curve.hpp"
#include "bounce/analytic/viscoelastic.hpp"
#include "bounce/contact/hertz.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/dynamics/adhesive_collision.hpp"
#include "bounce/dynamics/normal_collision.hpp"
#include "bounce/dynamics/tangential.hpp"
#include "bounce/pair/mixing.hpp"
#include "neck.hpp"
#include "warnings.hpp"

namespace bounce::analysis {

namespace {

using dynamics::CollisionOutcome;

// Which body's E, nu and density set c_t (BSHP96 (B3)), by the names the user gives them, and
// whether E looks like a slip of unit: a small c_t is more often a wrong input (GPa typed as Pa)
// than too fast a collision (issue 40, point 4).
std::string sound_speed_inputs(const Pair& pair) {
  const auto c_of = [](const Material& m) {
    return transversal_sound_speed(m.youngs_modulus, m.poisson_ratio, m.density);  // BSHP96 (B3)
  };
  const bool second = !pair.body2().rigid && c_of(pair.body2().material) < c_of(pair.body1().material);
  const Material& m = second ? pair.body2().material : pair.body1().material;
  const std::string n = second ? "2" : "";
  const std::string text = fmt::format(
      "c_t = sqrt(E / (2 (1 + nu) density)) (BSHP96 (B3)) of body {}{}: E{} = {:g} Pa, nu{} = {:g}, density{} = {:g} "
      "kg/m^3", second ? 2 : 1, m.name.empty() ? "" : " (" + m.name + ")", n, m.youngs_modulus, n, m.poisson_ratio, n,
      m.density);
  const std::string question = youngs_modulus_unit_question("E" + n, m.youngs_modulus);
  return question.empty() ? text : text + "; " + question;
}

CollisionOutcome from_master(const Pair& pair, const models::Model& model, double velocity) {
  const ViscoelasticScales s = viscoelastic_scales(pair, model, velocity);
  const analytic::MasterValues v = analytic::viscoelastic_master(s.kappa, model.end_rule);
  CollisionOutcome out;
  out.method = "master";
  out.cor = v.cor;
  out.outcome = dynamics::Outcome::bounce;
  out.contact_time = v.contact_time * s.reference_overlap / velocity;
  out.max_overlap = v.max_overlap * s.reference_overlap;
  const double m = pair.effective_mass();
  dynamics::EnergyBudget& e = out.energy;
  e.initial_kinetic = 0.5 * m * velocity * velocity;
  e.final_kinetic = e.initial_kinetic * v.cor * v.cor;
  if (model.end_rule == models::EndRule::force) {
    // At F = 0: xi' = -(2/3) xi / A, so the overlap left is xi = (3/2) A e g.
    const double xi_end = 1.5 * s.dissipative_constant * v.cor * velocity;
    e.elastic_remaining = 0.4 * s.force_constant * xi_end * xi_end * std::sqrt(xi_end);
  }
  e.bulk_dissipated = e.initial_kinetic - e.final_kinetic - e.elastic_remaining;
  return out;
}

// Master curve or integration, by the requested method and what the model allows.
bool use_master_curve(const models::Model& model, const CollideOptions& options) {
  const bool has = model.traits.master_curve;
  switch (options.method) {
    case Method::automatic:
      return has && !options.record_trajectory && options.tangential_velocity <= 0.0;
    case Method::master:
      if (!has) {
        throw InvalidArgument("method", "master", fmt::format("integrate for model {} (it has no master curve)", model.name));
      }
      if (options.record_trajectory) throw InvalidArgument("method", "master", "integrate when a trajectory is requested");
      if (options.tangential_velocity > 0.0) {
        throw InvalidArgument("method", "master", "integrate or auto for an oblique collision (it is integrated)");
      }
      return true;
    case Method::integrate:
      return false;
  }
  return false;
}

dynamics::NormalCollisionOptions normal_options(const models::Model& model, const CollideOptions& options) {
  dynamics::NormalCollisionOptions o;
  o.end_rule = model.end_rule;
  o.integration = options.integration;
  o.record_trajectory = options.record_trajectory;
  o.trajectory_points = options.trajectory_points;
  return o;
}

// Normal and tangential motion integrated together; the trajectory, on request, from the
// normal motion alone (it does not feel F^T).
CollisionOutcome oblique_force_law(const Pair& pair, const models::Model& model, double velocity,
                                   const CollideOptions& options) {
  dynamics::NormalCollisionOptions o = normal_options(model, options);
  o.record_trajectory = false;
  auto both = dynamics::integrate_tangential_collision(*model.force_law(), pair.effective_mass(), velocity,
                                                       options.tangential_velocity, *model.tangential, o);
  CollisionOutcome out = std::move(both.normal);
  if (out.outcome == dynamics::Outcome::bounce) {
    out.tangential = both.tangential;
  } else {
    out.notes.push_back("the grains stick: no tangential restitution");
  }
  if (options.record_trajectory) {
    o.record_trajectory = true;
    auto normal = dynamics::integrate_normal_collision(*model.force_law(), pair.effective_mass(), velocity, o);
    out.trajectory = std::move(normal.trajectory);
    out.trajectory_thinning = normal.trajectory_thinning;
  }
  return out;
}

CollisionOutcome force_law_collision(const Pair& pair, const models::Model& model, double velocity,
                                     const CollideOptions& options) {
  const bool master = use_master_curve(model, options);
  if (options.tangential_velocity > 0.0) return oblique_force_law(pair, model, velocity, options);
  if (master) return from_master(pair, model, velocity);
  try {
    return dynamics::integrate_normal_collision(*model.force_law(), pair.effective_mass(), velocity,
                                                normal_options(model, options));
  } catch (const dynamics::StepBudgetExceeded& e) {
    if (!model.traits.master_curve) throw;
    throw NumericalError(fmt::format("{} (kappa = {:.3g}: the contact creeps apart for a very long time; the master "
                                     "curve, --method master, gives this collision exactly)",
                                     e.what(), viscoelastic_scales(pair, model, velocity).kappa));
  }
}

// The tangential motion of an oblique collision of a dynamic-contact model, driven by
// the recorded normal force.
void add_recorded_tangential(CollisionOutcome& out, const Pair& pair, const models::Model& model,
                             const CollideOptions& options) {
  if (out.outcome != dynamics::Outcome::bounce) {
    out.notes.push_back("the grains stick: no tangential restitution");
    return;
  }
  out.tangential = dynamics::integrate_tangential_motion(out.trajectory, pair.effective_mass(),
                                                         options.tangential_velocity, *model.tangential,
                                                         options.integration);
  out.notes.push_back("tangential motion driven by the recorded F^N(t) (monotone cubic interpolation)");
}

dynamics::AdhesiveCollisionOptions adhesive_options(const CollideOptions& options) {
  const bool oblique = options.tangential_velocity > 0.0;
  dynamics::AdhesiveCollisionOptions o;
  o.relative_tolerance = options.adhesive_tolerance;
  o.engine = options.stiff_engine;
  // An oblique collision drives its tangential motion with the recorded F^N(t).
  o.record_trajectory = options.record_trajectory || oblique;
  o.trajectory_points = oblique ? std::max(options.trajectory_points, 4000) : options.trajectory_points;
  o.follow_time = options.follow_time;
  o.max_steps = std::min(options.integration.max_steps, o.max_steps);
  return o;
}

dynamics::AdhesiveCollisionOptions contact_options(const models::Model& model, const CollideOptions& options) {
  if (options.method == Method::master) {
    throw InvalidArgument("method", "master", fmt::format("integrate for model {} (it has no master curve)", model.name));
  }
  auto o = adhesive_options(options);
  if (model.end_rule == models::EndRule::pull_off) o.release = dynamics::AdhesiveRelease::pull_off;
  return o;
}

// A contact held on its adhesive branch (jkr-viscoelastic, maugis-viscoelastic).
CollisionOutcome adhesive_contact_collision(const models::AdhesiveContact& contact, double velocity,
                                            const dynamics::AdhesiveCollisionOptions& o) {
  return dynamics::integrate_adhesive_collision(contact.parameters, *contact.geometry, velocity, o);
}

// K13's crack (krijt); where the crack is so fast that its hysteresis is below the integration
// error, its fast-crack limit on JKR's branch (a singular-perturbation reduction).
CollisionOutcome crack_collision(const models::CrackContact& contact, double velocity,
                                 const dynamics::AdhesiveCollisionOptions& o) {
  const models::KrijtParameters& p = contact.parameters;
  const double hysteresis = models::krijt_hysteresis_estimate(p, velocity);
  if (hysteresis >= models::krijt_reduction_threshold) return dynamics::integrate_krijt_collision(p, velocity, o);
  CollisionOutcome out = dynamics::integrate_jkr_viscoelastic_collision(p, velocity, o);
  out.notes.push_back(fmt::format(
      "the crack is so fast that its hysteresis ({:.2g} of the impact energy) is below the integration "
      "error: integrated as the fast-crack limit jkr-viscoelastic (singular-perturbation reduction)",
      hysteresis));
  return out;
}

CollisionOutcome contact_collision(const Pair& pair, const models::Model& model, double velocity,
                                   const CollideOptions& options) {
  const auto o = contact_options(model, options);
  CollisionOutcome out = std::holds_alternative<models::AdhesiveContact>(model.normal)
                             ? adhesive_contact_collision(std::get<models::AdhesiveContact>(model.normal), velocity, o)
                             : crack_collision(std::get<models::CrackContact>(model.normal), velocity, o);
  if (options.tangential_velocity > 0.0) {
    add_recorded_tangential(out, pair, model, options);
    if (!options.record_trajectory) out.trajectory.clear();
  }
  return out;
}

// K13 (28)-(30): plastic losses added to any model when a yield strength is given.
void add_plastic_losses(CollisionOutcome& out, const Pair& pair, double velocity, double yield) {
  if (out.outcome == dynamics::Outcome::stick) return;  // nothing left to lose plastically
  const double v_y =
      analytic::yield_velocity(pair.effective_radius(), pair.effective_mass(), pair.effective_modulus(), yield);
  const double e_p = analytic::cor_thornton_ning(velocity, v_y);
  // Below the yield velocity nothing flows: (30) with e_P = 1 is e itself, which rounding
  // in sqrt(e^2 + e_P^2 - 1) would turn into a tiny loss (or gain) of either sign.
  if (e_p >= 1.0) return;
  dynamics::EnergyBudget& e = out.energy;
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

// A passive normal force (every normal model: elastic, viscous and adhesive forces, plastic
// losses) cannot return more energy than the impact brought: 0 <= e^N <= 1. An integrated e^N
// above 1 by less than the integration's own error is that error and is rounded to 1 (what
// it made up moves to the closure error); beyond it the result is refused, never printed.
void bound_passive_cor(CollisionOutcome& out, double tolerance, bool force_law) {
  // Dissipated work is >= 0 too: a tally below 0 by rounding (hertz: -3e-52 J of 1e-49 J)
  // is 0, what it held moves to the closure error.
  dynamics::EnergyBudget& e = out.energy;
  bool rounded = false;
  for (double* tally : {&e.bulk_dissipated, &e.crack_dissipated}) {
    if (*tally < 0.0 && -*tally <= 1e3 * tolerance * e.initial_kinetic) {
      *tally = 0.0;
      rounded = true;
    }
  }
  if (rounded) e.close();
  // A force law's contact ends with the grains parting: e < 0 is the event location's error where
  // an overdamped contact creeps apart (-8e-15, viscoelastic, A = 1e3 t_H). Within tolerance, 0.
  if (force_law && out.cor < 0.0) {
    if (-out.cor > 1e3 * tolerance) {
      throw NumericalError(fmt::format("e^N = {} < 0: the grains did not part, beyond the integration's tolerance {} "
                                       "(tighten --tolerance)", out.cor, tolerance));
    }
    out.cor = 0.0;
    out.energy.final_kinetic = 0.0;
    out.energy.close();
  }
  if (out.cor <= 1.0) return;
  // 1e3 x the relative tolerance: hertz integrated at 1e-12 overshoots by 2e-11 (event
  // location and dense output each carry about the tolerance, times the ~20 steps).
  if (out.cor - 1.0 > 1e3 * tolerance) {
    throw NumericalError(fmt::format("e^N = {} > 1: the integration created energy beyond its tolerance {} "
                                     "(tighten --tolerance)", out.cor, tolerance));
  }
  out.cor = 1.0;
  out.energy.final_kinetic = out.energy.initial_kinetic;
  out.energy.close();
}

// A trajectory has at most dynamics::max_trajectory_rows rows (docs/cli.md, "Memory"): the
// engines thin a long one as they go, and one joined from two contact episodes here; a note
// says where it was thinned.
void bound_trajectory(CollisionOutcome& out) {
  dynamics::limit_trajectory(out.trajectory, out.trajectory_thinning);
  if (out.trajectory_thinning > 0.0) {
    out.notes.push_back(fmt::format("the trajectory reached the bound of {} rows and was thinned in time: its {} rows "
                                    "are at least {:.3g} s apart (the first and last kept)",
                                    dynamics::max_trajectory_rows, out.trajectory.size(), out.trajectory_thinning));
  }
}

}  // namespace

Method parse_method(std::string_view text) {
  if (text == "integrate") return Method::integrate;
  if (text == "master") return Method::master;
  if (text == "auto") return Method::automatic;
  throw InvalidArgument("method", std::string(text), "auto, integrate or master");
}

CollideOptions collide_options(const Parameters& p) {
  CollideOptions o;
  o.method = parse_method(p.text("method"));
  if (o.method == Method::master) {
    p.refuse_given(std::array{"tolerance"},
                   "none with method master (the master curve is exact to 1e-10; tolerance is direct integration's)");
  }
  if (const ParameterSpec* s = p.spec("tolerance"); s != nullptr) {
    o.integration.relative_tolerance = o.integration.absolute_tolerance = *p.real("tolerance");
  }
  if (p.spec("adhesive_tolerance") != nullptr) o.adhesive_tolerance = *p.real("adhesive_tolerance");
  if (p.spec("stiff_engine") != nullptr && p.text("stiff_engine") == "cvode") {
    o.stiff_engine = dynamics::StiffEngine::cvode;
  }
  return o;
}

void require_impact_velocity(const Pair& pair, double velocity) {
  require_positive("velocity", velocity, "impact velocity [m/s]");
  // Above the transversal sound speed the quasi-static models end (BSHP96 (B11)): a
  // collision there is not a result of any of them (1e308 m/s gave infinities, 1e30 m/s
  // spent seconds on the step budget).
  const double c_t = pair.transversal_sound_speed();
  if (velocity > c_t) {
    throw InvalidArgument("velocity", format_value(velocity),
                          fmt::format("an impact velocity <= the transversal sound speed c_t = {:.4g} m/s, where the "
                                      "quasi-static models end (BSHP96 (B11)); {}",
                                      c_t, sound_speed_inputs(pair)));
  }
  if (!std::isnormal(0.5 * pair.effective_mass() * velocity * velocity)) {
    throw InvalidArgument("velocity", format_value(velocity),
                          "an impact velocity whose kinetic energy (1/2) m_eff g^2 is > 0 in double precision");
  }
}

namespace {

// BP04 (8.70) for a Hertz-type model. A so long (1e300 s, or T_vis / nu^2 with nu near 0) that
// kappa overflows is an input no engine can take (the shifted and adhesive laws' states became
// inf): refused naming A (issue 40, point 5). A = 0 is kappa = 0 (a huge E is no A's fault).
double damping_kappa(const Pair& pair, const models::Model& model, double velocity) {
  const double a = model.hertz->dissipative_constant;
  if (a == 0.0) return 0.0;
  const double kappa = analytic::kappa(a, model.hertz->force_constant, pair.effective_mass(), velocity);
  if (!std::isfinite(kappa)) {
    throw InvalidArgument("A", format_value(a),
                          fmt::format("a dissipative constant (given, or T_vis / nu^2 by K13 after (18)) whose "
                                      "dimensionless damping kappa (BP04 (8.70)) at g = {:g} m/s is finite in double "
                                      "precision; the viscous models need A << the contact time (BSHP96 (B12))",
                                      velocity));
  }
  return kappa;
}

}  // namespace

ViscoelasticScales viscoelastic_scales(const Pair& pair, const models::Model& model, double velocity) {
  require_positive("velocity", velocity, "impact velocity [m/s]");
  if (!model.hertz) {
    throw InvalidArgument("model", model.name, "a Hertz-type model (BP04 §8.3's kappa needs C0 and A)");
  }
  ViscoelasticScales s;
  s.dissipative_constant = model.hertz->dissipative_constant;
  s.force_constant = model.hertz->force_constant;
  const double m = pair.effective_mass();
  s.kappa = damping_kappa(pair, model, velocity);
  s.q = analytic::expansion_variable(s.kappa);
  s.characteristic_velocity = s.dissipative_constant > 0.0
                                  ? analytic::characteristic_velocity(s.dissipative_constant, s.force_constant, m)
                                  : std::numeric_limits<double>::infinity();
  s.reference_overlap = contact::hertz::reference_overlap(s.force_constant, m, velocity);
  s.hertz_contact_time = contact::hertz::collision_time(s.force_constant, m, velocity);
  return s;
}

CollisionOutcome collide(const Pair& pair, const models::Model& model, double velocity, const CollideOptions& options) {
  require_impact_velocity(pair, velocity);
  if (const auto* law = model.force_law()) law->check_speed(velocity);  // every path, oblique ones too
  if (model.hertz) damping_kappa(pair, model, velocity);
  if (options.tangential_velocity > 0.0 && !model.tangential) {
    throw InvalidArgument("friction", "(not given)", "a friction coefficient mu >= 0 (BSHP96 (36))");
  }
  const bool force_law = model.force_law() != nullptr;
  CollisionOutcome out = force_law ? force_law_collision(pair, model, velocity, options)
                                   : contact_collision(pair, model, velocity, options);
  bound_passive_cor(out, force_law ? options.integration.relative_tolerance : options.adhesive_tolerance, force_law);
  bound_trajectory(out);
  if (model.traits.adhesion == models::Adhesion::weak) detail::add_neck_work(out, pair);  // BP04 §8.3.4
  if (model.yield_strength) add_plastic_losses(out, pair, velocity, *model.yield_strength);
  detail::add_warnings(out, pair, model, velocity);
  return out;
}

double cor(const Pair& pair, const models::Model& model, double velocity, const CollideOptions& options) {
  return collide(pair, model, velocity, options).cor;
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

}  // namespace bounce::analysis
