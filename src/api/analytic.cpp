// The front door's `analytic`: for one pair and velocity, kappa and g* with the exact COR
// (both end rules) beside BP04's approximations (8.85), (8.86), (8.89), (8.92).
#include <fmt/format.h>

#include "binding.hpp"
#include "bounce/analytic/master_curve.hpp"
#include "bounce/analytic/viscoelastic.hpp"
#include "bounce/contact/hertz.hpp"
#include "bounce/core/error.hpp"

namespace bounce::api {

namespace {

using models::EndRule;

Record series_record(const analytic::IntegerSeries& s) {
  return Record().set("a", s.a).set("uncertainty", s.uncertainty);
}

Record pade_record(const analytic::PadeCoefficients& d) {
  return Record().set("d1", d.d1).set("d2", d.d2).set("d3", d.d3).set("d4", d.d4).set("d5", d.d5);
}

// The model must be dissipative (the command takes only viscoelastic, and none of the
// parameters the closed forms ignore: its CommandSpec).
void check(const Case& c, const analysis::ViscoelasticScales& s) {
  if (s.dissipative_constant <= 0.0) {
    const bool given = c.model_parameters.given("A");
    throw InvalidArgument(given ? "A" : "model", given ? "0" : c.model.name,
                          "A > 0 s (with A = 0 the collision is elastic: e = 1)");
  }
}

// The ratio test's radius of convergence of BP04 (8.89) from its last two coefficients, a_{n-1}/a_n:
// beyond it the truncated series' terms grow, and its value is no COR (4.29, 1.96 and 1.73 for
// BP04's simple, BP04's rigorous and bounce's a_k).
double radius_of_convergence(const analytic::IntegerSeries& s) {
  const std::size_t n = s.a.size();
  return s.a[n - 2] / s.a[n - 1];
}

// BP04 (8.89) at q, or null with a warning where q is beyond the series' radius of convergence or
// the truncated sum leaves [0, 1].
Value series_value(const char* name, double value, double q, double radius, Value::List& warnings) {
  if (q < radius && value >= 0.0 && value <= 1.0) return value;
  warnings.emplace_back(fmt::format(
      "series (8.89) {} is not a coefficient of restitution at q = {:.4g}: {} (an expansion in small q; the Pade "
      "(8.92) and the exact master curve hold at every q)",
      name, q,
      q >= radius ? fmt::format("q >= {:.3g}, its radius of convergence by the ratio test (a_{{n-1}}/a_n)", radius)
                  : fmt::format("its sum {:.4g} is outside [0, 1]", value)));
  return Value();
}

Record series_values(double k, double q) {
  const auto bp04_simple = analytic::bp04_simple_series();
  const auto bp04_rigorous = analytic::bp04_rigorous_series();
  const auto ours = analytic::master_series_overlap();
  const auto force_correction = analytic::master_series_force_correction();
  Value::List warnings;
  Record r;
  r.set("bp04_simple", series_value("with BP04's simple a_k", analytic::cor_series(q, bp04_simple), q,
                                    radius_of_convergence(bp04_simple), warnings))
      .set("bp04_rigorous", series_value("with BP04's a3 = 0.315, a4 = 0.161", analytic::cor_series(q, bp04_rigorous),
                                         q, radius_of_convergence(bp04_rigorous), warnings))
      .set("bounce_overlap", series_value("with bounce's a_k", analytic::cor_series(q, ours), q,
                                          radius_of_convergence(ours), warnings))
      .set("bounce_force", series_value("with bounce's a_k, force rule",
                                        analytic::cor_series_force(k, ours, force_correction), q,
                                        radius_of_convergence(ours), warnings));
  if (!warnings.empty()) r.set("warnings", Value(std::move(warnings)));
  return r;
}

Record coefficients() {
  const auto bp04_rigorous = analytic::bp04_rigorous_series();
  const auto ours = analytic::master_series_overlap();
  const auto force_correction = analytic::master_series_force_correction();
  return Record()
      .set("bp04_simple", series_record(analytic::bp04_simple_series()))
      .set("bp04_rigorous", series_record(bp04_rigorous))
      .set("bounce_overlap", series_record(ours))
      .set("bounce_force_correction",
           Record().set("d", force_correction.d).set("uncertainty", force_correction.uncertainty))
      .set("pade_bp04_printed", pade_record(analytic::bp04_printed_pade()))
      .set("pade_from_bp04_a_k", pade_record(analytic::pade_coefficients(bp04_rigorous)))
      .set("pade_from_bounce_a_k", pade_record(analytic::pade_coefficients(ours)));
}

Record contact_times(const Case& c, const analysis::ViscoelasticScales& s, double velocity) {
  const double m = c.pair.effective_mass(), k = s.kappa;
  return Record()
      .set("hertz_exact", contact::hertz::collision_time(s.force_constant, m, velocity))
      .set("bshp96_a13", analytic::hertz_contact_time_bshp96(s.force_constant, m, velocity))
      .set("k13_22", analytic::hertz_contact_time_k13(m, c.pair.effective_radius(), c.pair.effective_modulus(), velocity))
      .set("viscoelastic_overlap",
           analytic::viscoelastic_master(k, EndRule::overlap).contact_time * s.reference_overlap / velocity)
      .set("viscoelastic_force",
           analytic::viscoelastic_master(k, EndRule::force).contact_time * s.reference_overlap / velocity);
}

}  // namespace

Record analytic(const Inputs& inputs) {
  const Case c = make_case("analytic", inputs);
  const double velocity = c.own.require_real("velocity", "an impact velocity > 0 m/s");
  if (!c.model.hertz) {
    throw InvalidArgument("model", c.model.name, "viscoelastic (the closed forms of BP04 §8.3 are for it)");
  }
  const analysis::ViscoelasticScales s = analysis::viscoelastic_scales(c.pair, c.model, velocity);
  check(c, s);
  const double k = s.kappa, q = s.q;
  const auto bp04_rigorous = analytic::bp04_rigorous_series();
  const auto ours = analytic::master_series_overlap();
  Record out;
  out.set("velocity", velocity);
  out.set("dissipative_constant", s.dissipative_constant);
  out.set("kappa", k);
  out.set("q", q);
  out.set("characteristic_velocity", s.characteristic_velocity);
  out.set("b", analytic::b_constant());
  out.set("exact", Record()
                       .set("overlap", analytic::master_cor(k, EndRule::overlap))
                       .set("force", analytic::master_cor(k, EndRule::force)));
  out.set("implicit_8_85", analytic::cor_implicit(k));
  out.set("continued_fraction_8_86", analytic::cor_continued_fraction(k));
  out.set("series_8_89", series_values(k, q));
  out.set("pade_8_92", Record()
                           .set("bp04_printed", analytic::cor_pade(q, analytic::bp04_printed_pade()))
                           .set("from_bp04_a_k", analytic::cor_pade(q, analytic::pade_coefficients(bp04_rigorous)))
                           .set("from_bounce_a_k", analytic::cor_pade(q, analytic::pade_coefficients(ours))));
  out.set("coefficients", coefficients());
  out.set("contact_time", contact_times(c, s, velocity));
  return out;
}

}  // namespace bounce::api
