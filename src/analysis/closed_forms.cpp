#include "bounce/analysis/closed_forms.hpp"

#include <cmath>

#include <fmt/format.h>

#include "bounce/analysis/collide.hpp"
#include "bounce/analytic/adhesive.hpp"
#include "bounce/analytic/master_curve.hpp"
#include "bounce/analytic/viscoelastic.hpp"
#include "bounce/contact/surface_forces.hpp"

namespace bounce::analysis {

namespace {

void add_adhesive(ClosedForms& c, const Pair& pair, const models::Model& model, double gamma, double v) {
  const double r = pair.effective_radius(), e = pair.effective_modulus(), m = pair.effective_mass();
  c.sticking_velocity_jkr = analytic::sticking_velocity_jkr(m, r, e, gamma);
  c.sticking_velocity_k13_25 = analytic::sticking_velocity_k13(m, r, e, gamma);  // K13 (25)
  c.e_jkr = analytic::cor_jkr(v, *c.sticking_velocity_jkr);                     // K13 (24)
  c.tabor_parameter = contact::surface::tabor_parameter(r, e, gamma, model.z0);  // K13 (11)
  if (model.traits.closed_forms.bp04_weak) {
    const double w0 = analytic::tensile_work(r, e, gamma);  // BP04 (8.95)
    const ViscoelasticScales s = viscoelastic_scales(pair, model, v);
    c.tensile_work_bp04_8_95 = w0;
    c.e_ad_bp04_8_98 =  // BP04 (8.98)
        analytic::cor_adhesive_bp04(analytic::master_cor(s.kappa, models::EndRule::overlap), v, w0, m);
  }
}

// K13 (26)-(27). (26) is the first order of e_D in A / t_H (BSHP96's expansion of the
// viscoelastic COR): valid for 5.57 A / t_H << 1, and beyond 1 it is negative and (27) above 1
// (e_D^2 > 1). There both are left out with a warning naming the condition (docs/adhesive.md).
void add_viscous(ClosedForms& c, double dissipative_constant) {
  c.dissipative_constant = dissipative_constant;
  const double e_d = analytic::cor_viscous_k13(dissipative_constant, c.hertz_time_k13_22);  // K13 (26)
  if (e_d >= 0.0 || !std::isfinite(e_d)) {  // -inf (t_H underflowed to 0): kept, refused as not finite
    c.e_d = e_d;
    if (c.e_jkr) c.e_i = analytic::cor_independent(*c.e_jkr, e_d);  // K13 (27)
    return;
  }
  c.warnings.push_back(fmt::format(
      "{} null: K13 (26) e_D = 1 - 5.57 A/t_H is first order in A/t_H and holds for 5.57 A/t_H <= 1, here {:.3g} "
      "(A = {:.3g} s, t_H = {:.3g} s): the dissipation is not small",
      c.e_jkr ? "e_d (26) and e_i (27) are" : "e_d (26) is", 1.0 - e_d, dissipative_constant, c.hertz_time_k13_22));
}

}  // namespace

ClosedForms closed_forms(const Pair& pair, const models::Model& model, double v) {
  ClosedForms c;
  const double r = pair.effective_radius(), e = pair.effective_modulus(), m = pair.effective_mass();
  c.hertz_time_k13_22 = analytic::hertz_contact_time_k13(m, r, e, v);  // K13 (22)
  const auto gamma = pair.surface_energy();
  const models::ClosedFormSet& declared = model.traits.closed_forms;
  if (declared.jkr && gamma && *gamma > 0.0) add_adhesive(c, pair, model, *gamma, v);
  if (!declared.jkr && gamma && *gamma > 0.0) {
    c.tabor_parameter = contact::surface::tabor_parameter(r, e, *gamma, model.z0);  // K13 (11)
  }
  if (declared.viscous && model.dissipative_constant) add_viscous(c, *model.dissipative_constant);
  if (model.yield_strength) {
    c.yield_velocity = analytic::yield_velocity(r, m, e, *model.yield_strength);  // K13 (28)
    c.e_plastic = analytic::cor_thornton_ning(v, *c.yield_velocity);             // K13 (29)
    c.plastic_length_scale = analytic::plastic_length_scale(m, v, r, e);         // K13 (33)
  }
  return c;
}

std::vector<std::pair<std::string, std::optional<double>>> named_values(const ClosedForms& c) {
  std::vector<std::pair<std::string, std::optional<double>>> v;
  const auto put = [&v](const char* key, const std::optional<double>& x) {
    if (x) v.emplace_back(key, *x);
  };
  put("sticking_velocity_jkr", c.sticking_velocity_jkr);
  put("sticking_velocity_k13_25", c.sticking_velocity_k13_25);
  put("e_jkr", c.e_jkr);
  v.emplace_back("hertz_time_k13_22", c.hertz_time_k13_22);
  put("tabor_parameter", c.tabor_parameter);
  put("dissipative_constant", c.dissipative_constant);
  if (c.dissipative_constant) v.emplace_back("e_d", c.e_d);  // null beyond (26)'s validity
  if (c.dissipative_constant && c.e_jkr) v.emplace_back("e_i", c.e_i);
  put("tensile_work_bp04_8_95", c.tensile_work_bp04_8_95);
  put("e_ad_bp04_8_98", c.e_ad_bp04_8_98);
  put("yield_velocity", c.yield_velocity);
  put("e_plastic", c.e_plastic);
  put("plastic_length_scale", c.plastic_length_scale);
  return v;
}

}  // namespace bounce::analysis
