#pragma once
// What the property tests share beyond the generators: colliding a drawn registry model as
// a front end does, the stated accuracy of each engine, and comparisons that fail with
// every number at full precision.

#include <cmath>
#include <sstream>
#include <string>

#include <rapidcheck.h>

#include "bounce/analysis/collide.hpp"
#include "bounce/models/registry.hpp"
#include "property/generators.hpp"

namespace bounce::property {

/// A model of the registry for a pair, with the options its parameters set, as the front
/// door makes them (api::make_case): models::make_model and analysis::collide_options.
struct ModelAndOptions {
  models::Model model;
  analysis::CollideOptions options;
};
inline ModelAndOptions make(const Pair& pair, const ModelCase& c) {
  return {models::make_model(pair, c.name, c.inputs),
          analysis::collide_options(models::bind_model_parameters(c.name, c.inputs))};
}

inline dynamics::CollisionOutcome collide(const Pair& pair, const ModelCase& c, double speed) {
  const ModelAndOptions m = make(pair, c);
  return analysis::collide(pair, m.model, speed, m.options);
}

/// The stated accuracy of the engine that produced an outcome, at the default tolerances.
struct Accuracy {
  double cor;       ///< absolute error of e
  double relative;  ///< relative error of the contact time and the maximum overlap
  double closure;   ///< |closure_error| / initial kinetic energy
};
inline Accuracy stated_accuracy(const models::Model& model, const dynamics::CollisionOutcome& out) {
  if (out.method == "master") {
    // docs/viscoelastic.md, "Stated error: 1e-10" (analytic::master_curve_stated_error): absolute
    // on e, relative on the scaled time and overlap. The budget is closed by construction
    // (bulk_dissipated = initial - final - elastic_remaining), so its closure is rounding:
    // four terms no larger than the initial energy, a few ulps of it (1e-15).
    return {1e-10, 1e-10, 1e-15};
  }
  if (model.traits.adhesive) {
    // docs/adhesive.md: "COR errors <= 2e-9 for T_vis = 1e-16-1e-8 s" (krijt at the default
    // adhesive tolerance 1e-8; jkr-viscoelastic "to 1e-9"), the contact dynamics to that
    // relative tolerance 1e-8; the budget "closes to 1e-5 of the impact energy", the pass
    // criterion of the robustness grid over every K13 material, 1e-3-1e2 m/s, R_eff
    // 1e-8-1e-2 m and T_vis 1e-16-1e-8 s for all three adhesive models ("Robustness").
    return {2e-9, 1e-8, 1e-5};
  }
  // docs/viscoelastic.md, "Accuracy of direct integration": e to 1e-10 (abs.) typically, 3e-9
  // at worst (these properties found 2.3e-9 over 20 000 random pairs, overlap rule: the end
  // of contact located on the dense output), contact times to 1e-10 (rel.) for kappa <~ 10
  // at the default tolerance 1e-12; the budget closes to 2e-9 (worst found 8e-10, a
  // power-law with alpha ~ 1, beta ~ 1.3).
  return {3e-9, 1e-10, 2e-9};
}

/// A number with all 17 digits.
inline std::string full(double x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}

/// Fails the property unless |actual - expected| <= tolerance, printing all three.
inline void require_near(double actual, double expected, double tolerance, const std::string& what) {
  if (std::abs(actual - expected) <= tolerance) return;
  std::ostringstream os;
  os.precision(17);
  os << what << ": " << actual << " vs " << expected << ", difference " << actual - expected << " > tolerance "
     << tolerance;
  RC_FAIL(os.str());
}

/// Fails unless |actual / expected - 1| <= tolerance.
inline void require_relative(double actual, double expected, double tolerance, const std::string& what) {
  if (actual == expected) return;  // also 0 = 0
  require_near(actual / expected, 1.0, tolerance, what + " (ratio)");
}

/// Fails unless lo <= x <= hi exactly.
inline void require_within(double x, double lo, double hi, const std::string& what) {
  if (lo <= x && x <= hi) return;
  std::ostringstream os;
  os.precision(17);
  os << what << " = " << x << " is outside [" << lo << ", " << hi << "]";
  RC_FAIL(os.str());
}

/// Logs a case's inputs at full precision (printed when the property fails).
inline void log_case(const Pair& pair, double speed, const ModelCase& c) {
  std::ostringstream os;
  os.precision(17);
  showValue(pair, os);
  os << " speed=" << speed << " m/s model=";
  showValue(c, os);
  RC_LOG() << os.str() << "\n";
}

}  // namespace bounce::property
