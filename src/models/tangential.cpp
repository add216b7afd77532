#include "bounce/models/tangential.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"

namespace bounce::models {

std::string_view to_string(TangentialLaw law) { return law == TangentialLaw::asperity ? "asperity" : "step"; }
std::string_view to_string(AsperityForm form) { return form == AsperityForm::published ? "published" : "passive"; }

TangentialLaw parse_tangential_law(std::string_view text) {
  if (text == "asperity") return TangentialLaw::asperity;
  if (text == "step") return TangentialLaw::step;
  throw InvalidArgument("tangential_law", std::string(text), "asperity (BSHP96 (35)) or step (BSHP96 (39))");
}

AsperityForm parse_asperity_form(std::string_view text) {
  if (text == "published") return AsperityForm::published;
  if (text == "passive") return AsperityForm::passive;
  throw InvalidArgument("asperity_form", std::string(text), "passive (default) or published (BSHP96 (35))");
}

void validate(const TangentialModel& m) {
  require_non_negative("friction", m.friction, "friction coefficient mu");
  if (!(m.dense_breaks > 0.0)) {  // +inf resolves every break
    throw InvalidArgument("dense_breaks", fmt::format("{:g}", m.dense_breaks), "breaks per time unit > 0 (or inf)");
  }
  require_positive("kappa", m.kappa, "tangential mass factor kappa of BSHP96 (8)");
  if (m.kappa > 1.0) throw InvalidArgument("kappa", fmt::format("{:g}", m.kappa), "0 < kappa <= 1 (BSHP96 (8))");
  if (m.law == TangentialLaw::asperity) {
    require_positive("asperity", m.asperity_size, "asperity size zeta0 [m] (BSHP96 (32))");
  } else {
    require_non_negative("shear_damping", m.shear_damping, "shear damping gamma_s [1/s] (BSHP96 (39))");
  }
}

namespace {
double norm(const double v[3]) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// The spring's state grown by `step` (the sliding of one time step, scaled), with every break
// at |state| = limit taken out: the spring restarts at each break (BSHP96 (35) with its floor).
void grow_with_breaks(double state[3], const double step[3], double limit) {
  for (int k = 0; k < 3; ++k) state[k] += step[k];
  const double size = norm(state);
  if (!(limit > 0.0)) {
    std::fill(state, state + 3, 0.0);
  } else if (size >= limit) {
    const double rest = std::fmod(size, limit) / size;
    for (int k = 0; k < 3; ++k) state[k] *= rest;
  }
}
}  // namespace

void tangential_step(const TangentialModel& t, double normal_force, double previous_normal_force,
                     double effective_mass, const double sliding[3], double dt, bool update, double h[3],
                     double force[3]) {
  const double fn = std::max(normal_force, 0.0);  // asperities carry no shear in tension
  if (t.law == TangentialLaw::step) {  // BSHP96 (39)
    const double v = norm(sliding);
    const double size = v > 0.0 ? std::min(t.shear_damping * effective_mass * v, t.friction * fn) / v : 0.0;
    for (int k = 0; k < 3; ++k) force[k] = -size * sliding[k];
    return;
  }
  const double stiffness = t.friction * fn / t.asperity_size;  // k of BSHP96 (35)
  if (t.form == AsperityForm::published) {  // BSHP96 (35)-(36): the history is the extension
    if (update) {
      const double step[3] = {sliding[0] * dt, sliding[1] * dt, sliding[2] * dt};
      grow_with_breaks(h, step, t.asperity_size);
    }
    for (int k = 0; k < 3; ++k) force[k] = -stiffness * h[k];
    return;
  }
  const double root = std::sqrt(stiffness);  // passive: the history is sqrt(k) times the extension
  if (update) {
    const double before = std::sqrt(t.friction * std::max(previous_normal_force, 0.0) / t.asperity_size);
    const double mean = 0.5 * (before + root);  // the step's sqrt(k), at its middle
    const double step[3] = {mean * sliding[0] * dt, mean * sliding[1] * dt, mean * sliding[2] * dt};
    grow_with_breaks(h, step, root * t.asperity_size);
  }
  for (int k = 0; k < 3; ++k) force[k] = -root * h[k];
}

}  // namespace bounce::models
