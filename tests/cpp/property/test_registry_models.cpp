// Properties every model of the registry must have, on random unlike sphere pairs at
// random speeds within validity: the restitution coefficient is in [0, 1] and no energy is
// created, the energy budget closes, and the two bodies can be swapped. Each case iterates
// the registry's rows, so a new model is covered as soon as it is registered (and fails
// until generators.hpp knows how to draw its parameters).
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "bounce/analysis/collide.hpp"
#include "bounce/models/registry.hpp"
#include "property/checks.hpp"
#include "property/generators.hpp"

using namespace bounce;
using namespace bounce::property;

namespace {

// The parameters of every registry model for this pair and speed; fails naming a model the
// generators do not know.
std::vector<ModelCase> every_model(const Pair& pair, double speed) {
  std::vector<ModelCase> out;
  for (const models::ModelRow& row : models::model_registry().rows()) {
    const auto parameters = model_parameters(row.name, pair, speed);
    if (!parameters) RC_FAIL("no parameter generator for registry model '" + row.name + "': add it to model_parameters()");
    out.push_back(*(*parameters));
  }
  return out;
}

// The methods a model offers: its default, and direct integration where the default is
// the master curve (both are what a user gets).
std::vector<std::string> methods(const ModelCase& c) {
  if (models::model_registry().at(c.name).traits.master_curve) return {"auto", "integrate"};
  return {"auto"};
}

// Every registry model by every method it offers at one pair and speed, with `extra`
// inputs (a yield strength): f(case, model and options, outcome).
template <class F>
void each_collision(const Pair& pair, double speed, const ParameterInputs& extra, F f) {
  for (ModelCase c : every_model(pair, speed)) {
    for (const auto& [name, value] : extra) c.inputs[name] = value;
    for (const std::string& method : methods(c)) {
      c.inputs["method"] = method;
      log_case(pair, speed, c);
      const ModelAndOptions m = make(pair, c);
      f(c, m, analysis::collide(pair, m.model, speed, m.options));
    }
  }
}

}  // namespace

// BP04 (8.62) e = -xi'(t_c)/g with the energy balance (1/2) m g^2 (1 - e^2) = work of the
// dissipative forces >= 0 (BSHP96 (11) for the normal part; K13 appendix C, (C.2)-(C.3),
// for the dynamic-contact models; K13 (28)-(30) for the plastic loss): no model creates
// energy, so 0 <= e^N <= 1 exactly, and every dissipated term is >= 0 exactly. No model of
// the registry can legitimately give e^N > 1 (the tangential e^T of the published asperity
// law can exceed 1 in magnitude, docs/tangential.md; that is not e^N). With a yield strength
// (drawn for half of the cases, Y/E* in [1e-4, 0.1]) the Thornton-Ning loss is added.
// Sticking (e = 0) must say so in the outcome. A sphere on a sphere, an elastic or a rigid wall.
RC_GTEST_PROP(RegistryModels, RestitutionInUnitIntervalAndNoEnergyCreated, ()) {
  const Pair pair = *sphere_or_wall_pair();
  const double speed = *valid_speed(pair);
  const bool plastic = *rc::gen::arbitrary<bool>();
  const double yield = *log_uniform(1e-4, 0.1) * pair.effective_modulus();
  ParameterInputs extra;
  if (plastic) extra["yield"] = yield;
  each_collision(pair, speed, extra, [&](const ModelCase& c, const ModelAndOptions&, const dynamics::CollisionOutcome& out) {
      const std::string who = c.name + " (" + std::get<std::string>(c.inputs.at("method")) + ")";
      require_within(out.cor, 0.0, 1.0, who + " e^N");
      if (out.outcome == dynamics::Outcome::stick) require_within(out.cor, 0.0, 0.0, who + " e^N of a sticking collision");
      // Dissipated work is >= 0; with adhesion it can exceed the impact energy (the
      // surface energy released is dissipated too), so no upper bound.
      const dynamics::EnergyBudget& e = out.energy;
      require_within(e.bulk_dissipated, 0.0, HUGE_VAL, who + " bulk_dissipated [J]");
      require_within(e.crack_dissipated, 0.0, HUGE_VAL, who + " crack_dissipated [J]");
      require_within(e.plastic_dissipated, 0.0, HUGE_VAL, who + " plastic_dissipated [J]");
      if (!models::model_registry().at(c.name).traits.adhesive) {
        // Without adhesion the stored energy is elastic, >= 0. (An adhesive law's potential,
        // BP04 (8.56), includes the negative surface part.)
        require_within(e.elastic_remaining, 0.0, HUGE_VAL, who + " elastic_remaining [J]");
      }
      // e <= 1 in energy; a sticking collision reports the kinetic energy at the time
      // sticking became certain, which adhesion may have raised above the impact energy.
      if (out.outcome == dynamics::Outcome::bounce) {
        require_within(e.final_kinetic, 0.0, e.initial_kinetic, who + " final_kinetic [J]");
      }
  });
}

// The energy budget closes (dynamics::EnergyBudget: initial = final + bulk + crack +
// plastic + elastic_remaining + surface_remaining, K13 appendix C) to the stated bound of
// the engine that produced it (stated_accuracy: 2e-9 of the impact energy for direct
// integration, docs/viscoelastic.md; 1e-5 for the adhesive models, docs/adhesive.md;
// rounding for the master curve, whose budget is closed by construction). Spheres and walls.
RC_GTEST_PROP(RegistryModels, EnergyBudgetClosesWithinStatedBound, ()) {
  const Pair pair = *sphere_or_wall_pair();
  const double speed = *valid_speed(pair);
  each_collision(pair, speed, {}, [&](const ModelCase& c, const ModelAndOptions& m, const dynamics::CollisionOutcome& out) {
      const dynamics::EnergyBudget& e = out.energy;
      // The stated bound is relative to the impact energy; the sum itself is rounded at
      // double precision relative to its largest terms, which with adhesion can exceed the
      // impact energy by many orders (a micron grain sticking at 1e-8 m/s exchanges 1e16
      // times it): seven terms, their sum rounded to at most 8 ulps of their magnitude.
      const double magnitude = e.initial_kinetic + e.final_kinetic + std::abs(e.bulk_dissipated) +
                               std::abs(e.crack_dissipated) + std::abs(e.plastic_dissipated) +
                               std::abs(e.elastic_remaining) + std::abs(e.surface_remaining);
      const double rounding = 8.0 * std::numeric_limits<double>::epsilon() * magnitude;
      const double bound = stated_accuracy(m.model, out).closure * e.initial_kinetic + rounding;
      require_near(e.closure_error, 0.0, bound, c.name + " (" + out.method + ") closure_error [J]");
  });
}

// Swapping body 1 and body 2 (unlike materials and radii) changes nothing: the collision
// depends on the pair only through the symmetric mixing rules R_eff, m_eff (BSHP96 (5),
// (6)), E* (K13 after (1)), gamma (K13 footnote 8) and the smaller sound speed. e, the
// contact time and the maximum overlap agree to the engine's stated accuracy (a rounding-level
// change of a parameter may change the adaptive steps, never more than that error).
RC_GTEST_PROP(RegistryModels, SwappingTheBodiesChangesNothing, ()) {
  const Pair pair = *sphere_pair();
  const Pair other = swapped(pair);
  const double speed = *valid_speed(pair);
  each_collision(pair, speed, {}, [&](const ModelCase& c, const ModelAndOptions& m, const dynamics::CollisionOutcome& a) {
      const auto b = collide(other, c, speed);
      const Accuracy accuracy = stated_accuracy(m.model, a);
      const std::string who = c.name + " (" + a.method + ")";
      RC_ASSERT(a.outcome == b.outcome);
      require_near(b.cor, a.cor, accuracy.cor, who + " e^N swapped");
      require_relative(b.contact_time, a.contact_time, accuracy.relative, who + " contact time swapped");
      require_relative(b.max_overlap, a.max_overlap, accuracy.relative, who + " max overlap swapped");
  });
}
