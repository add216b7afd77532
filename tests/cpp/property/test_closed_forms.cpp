// The closed-form CORs printed beside a collision (collide's and curve's `closed_forms`, Python's
// closed_forms(): all are analysis::named_values of analysis::closed_forms) are in [0, 1] or
// null, for every registry model on random pairs at random speeds, also far outside the models'
// validity as users type them (issue 40, A1: K13 (26) printed e_d = -1.71 and (27) e_i = 1.39).
// A null comes with a warning saying which condition failed.
#include <cmath>
#include <optional>
#include <string>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "bounce/analysis/closed_forms.hpp"
#include "bounce/models/registry.hpp"
#include "property/checks.hpp"
#include "property/generators.hpp"

using namespace bounce;
using namespace bounce::property;

namespace {

// A model of the registry with A / t_H log-uniform over [1e-6, 1e4] at the speed (BSHP96 (B12)
// asks for A << t_c; users type T_vis = 1e-8 s for 10 nm grains, A / t_H ~ 1e4), and for krijt
// T_vis = f A, f = nu^2 in [1e-4, 0.24]; an optional yield strength (K13 (28)-(29)), Y / E_soft
// log-uniform over [1e-4, 1] (a yield strain above 1 is refused: docs/hardening.md).
ModelCase wide_model(const Pair& pair, double speed) {
  const auto names = models::model_registry().names_where([](const models::ModelRow&) { return true; });
  ModelCase c{*rc::gen::elementOf(names), {}};
  const double a = *log_uniform(1e-6, 1e4) * hertz_time(pair, speed);
  const auto& traits = models::model_registry().at(c.name).traits;
  if (c.name == "krijt") {
    c.inputs = {{"A", a}, {"tvis", *log_uniform(1e-4, 0.24) * a}};
  } else if (c.name == "maugis-viscoelastic") {
    c.inputs = {{"A", a}, {"z0", *log_uniform(1e-12, std::min(1e-7, pair.effective_radius() / 10.5))}};
  } else if (traits.closed_forms.viscous || traits.adhesive) {
    c.inputs = {{"A", a}};
  } else if (auto g = model_parameters(c.name, pair, speed)) {
    c = *(*g);
  }
  if (*rc::gen::inRange(0, 2) == 1) c.inputs["yield"] = *log_uniform(1e-4, 1.0) * pair.soft_modulus();
  return c;
}

bool is_cor(const std::string& key) { return key.rfind("e_", 0) == 0; }

}  // namespace

RC_GTEST_PROP(ClosedForms, EveryPrintedCorIsInTheUnitIntervalOrNull, ()) {
  const Pair pair = *sphere_or_wall_pair();
  // From six decades below the small-strain limit up to near the sound speed (BSHP96 (B11)).
  const double speed = *log_uniform(1e-6 * max_valid_speed(pair), 0.9 * pair.transversal_sound_speed());
  const ModelCase c = wide_model(pair, speed);
  log_case(pair, speed, c);
  const analysis::ClosedForms forms = analysis::closed_forms(pair, make(pair, c).model, speed);
  bool any_null = false;
  for (const auto& [key, value] : analysis::named_values(forms)) {
    if (!is_cor(key)) continue;
    any_null = any_null || !value;
    if (value) RC_ASSERT(*value >= 0.0 && *value <= 1.0);
  }
  RC_ASSERT(any_null == !forms.warnings.empty());  // a null says why; nothing else warns here
}
