// `bounce analytic`: for one pair and velocity, kappa and g* with the exact COR
// (both end rules) beside BP04's approximations (8.85), (8.86), (8.89), (8.92).
#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "bounce/analysis/collide.hpp"
#include "bounce/analytic/master_curve.hpp"
#include "bounce/analytic/viscoelastic.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "cli.hpp"
#include "commands.hpp"

namespace bounce::cli {

namespace {

struct AnalyticCommand {
  explicit AnalyticCommand(CLI::App* app) : bodies(app), numbers(app), model(app, numbers) {}
  BodyOptions bodies;
  NumberOptions numbers;
  ModelOptions model;
  bool json = false;
};

nlohmann::json series_json(const analytic::IntegerSeries& s) {
  return {{"a", s.a}, {"uncertainty", s.uncertainty}};
}

nlohmann::json pade_json(const analytic::PadeCoefficients& d) {
  return {{"d1", d.d1}, {"d2", d.d2}, {"d3", d.d3}, {"d4", d.d4}, {"d5", d.d5}};
}

int run_analytic(const AnalyticCommand& c) {
  const Pair pair = c.bodies.pair();
  models::ModelSpec spec = c.model.spec();
  if (spec.name != "viscoelastic") {
    throw InvalidArgument("--model", spec.name, "viscoelastic (the closed forms of BP04 §8.3 are for it)");
  }
  const double velocity = require_positive(
      "velocity", c.numbers.require("--velocity", "an impact velocity > 0 m/s"), "impact velocity [m/s]");
  const ViscoelasticScales s = viscoelastic_scales(pair, spec, velocity);
  if (s.dissipative_constant <= 0.0) {
    throw InvalidArgument("--A", "0", "A > 0 s (with A = 0 the collision is elastic: e = 1)");
  }
  using models::EndRule;
  const double k = s.kappa;
  const double q = s.q;
  const auto bp04_simple = analytic::bp04_simple_series();
  const auto bp04_rigorous = analytic::bp04_rigorous_series();
  const auto ours = analytic::master_series_overlap();
  const auto force_correction = analytic::master_series_force_correction();
  // BP04's printed d_k (8.93) and those (8.93) gives from a given set of a_k.
  const analytic::PadeCoefficients bp04_printed = analytic::bp04_printed_pade();
  const auto pade_rigorous = analytic::pade_coefficients(bp04_rigorous);
  const auto pade_ours = analytic::pade_coefficients(ours);

  nlohmann::json out;
  out["velocity"] = velocity;
  out["dissipative_constant"] = s.dissipative_constant;
  out["kappa"] = k;
  out["q"] = q;
  out["characteristic_velocity"] = s.characteristic_velocity;
  out["b"] = analytic::b_constant();
  out["exact"] = {{"overlap", analytic::master_cor(k, EndRule::overlap)},
                  {"force", analytic::master_cor(k, EndRule::force)}};
  out["implicit_8_85"] = analytic::cor_implicit(k);
  out["continued_fraction_8_86"] = analytic::cor_continued_fraction(k);
  out["series_8_89"] = {{"bp04_simple", analytic::cor_series(q, bp04_simple)},
                        {"bp04_rigorous", analytic::cor_series(q, bp04_rigorous)},
                        {"bounce_overlap", analytic::cor_series(q, ours)},
                        {"bounce_force", analytic::cor_series_force(k, ours, force_correction)}};
  out["pade_8_92"] = {{"bp04_printed", analytic::cor_pade(q, bp04_printed)},
                      {"from_bp04_a_k", analytic::cor_pade(q, pade_rigorous)},
                      {"from_bounce_a_k", analytic::cor_pade(q, pade_ours)}};
  out["coefficients"] = {{"bp04_simple", series_json(bp04_simple)},
                         {"bp04_rigorous", series_json(bp04_rigorous)},
                         {"bounce_overlap", series_json(ours)},
                         {"bounce_force_correction", {{"d", force_correction.d}, {"uncertainty", force_correction.uncertainty}}},
                         {"pade_bp04_printed", pade_json(bp04_printed)},
                         {"pade_from_bp04_a_k", pade_json(pade_rigorous)},
                         {"pade_from_bounce_a_k", pade_json(pade_ours)}};
  const double m = pair.effective_mass();
  out["contact_time"] = {
      {"hertz_exact", analytic::hertz_contact_time(s.force_constant, m, velocity)},
      {"bshp96_a13", analytic::hertz_contact_time_bshp96(s.force_constant, m, velocity)},
      {"k13_22", analytic::hertz_contact_time_k13(m, pair.effective_radius(), pair.effective_modulus(), velocity)},
      {"viscoelastic_overlap", analytic::viscoelastic_master(k, EndRule::overlap).contact_time * s.reference_overlap / velocity},
      {"viscoelastic_force", analytic::viscoelastic_master(k, EndRule::force).contact_time * s.reference_overlap / velocity}};
  if (c.json) {
    print_json(out);
    return 0;
  }
  std::cout << fmt::format("kappa = {:.6g} (BP04 (8.70)), q = (g/g*)^(1/5) = 2 b kappa = {:.6g}, g* = {:.6g} m/s\n",
                           k, q, s.characteristic_velocity);
  std::cout << "coefficient of restitution:\n";
  auto line = [](const std::string& what, double value) {
    std::cout << fmt::format("  {:<44} {:.10f}\n", what, value);
  };
  line("exact, overlap end rule (master curve)", out["exact"]["overlap"].get<double>());
  line("exact, force end rule (master curve)", out["exact"]["force"].get<double>());
  line("implicit equation BP04 (8.85)", out["implicit_8_85"].get<double>());
  line("continued fraction BP04 (8.86)", out["continued_fraction_8_86"].get<double>());
  line("series (8.89), BP04 simple a_k", out["series_8_89"]["bp04_simple"].get<double>());
  line("series (8.89), BP04 a3 = 0.315, a4 = 0.161", out["series_8_89"]["bp04_rigorous"].get<double>());
  line("series (8.89), bounce a_k (overlap rule)", out["series_8_89"]["bounce_overlap"].get<double>());
  line("series, bounce, force rule (+ kappa^5/2 terms)", out["series_8_89"]["bounce_force"].get<double>());
  line("Pade (8.92), BP04's printed d_k", out["pade_8_92"]["bp04_printed"].get<double>());
  line("Pade (8.92)-(8.93) from BP04's a_k", out["pade_8_92"]["from_bp04_a_k"].get<double>());
  line("Pade (8.92)-(8.93) from bounce's a_k", out["pade_8_92"]["from_bounce_a_k"].get<double>());
  std::cout << "series coefficients a_k (e = 1 - a1 q + a2 q^2 - a3 q^3 + ...):\n";
  auto coefficients = [](const std::string& what, const analytic::IntegerSeries& series) {
    std::cout << fmt::format("  {:<14}", what);
    for (std::size_t i = 0; i < series.a.size(); ++i) {
      std::cout << fmt::format(" a{}={:.6g}", i + 1, series.a[i]);
      if (series.uncertainty[i] > 0) std::cout << fmt::format("(+-{:.1g})", series.uncertainty[i]);
    }
    std::cout << "\n";
  };
  coefficients("BP04 simple", bp04_simple);
  coefficients("BP04 rigorous", bp04_rigorous);
  coefficients("bounce", ours);
  std::cout << "contact time [s]:\n";
  for (const auto& [key, value] : out["contact_time"].items()) line(key, value.get<double>());
  return 0;
}

}  // namespace

Command add_analytic_command(CLI::App& root) {
  auto* app = root.add_subcommand(
      "analytic", "kappa, g* and the exact COR beside BP04's implicit, series and Pade forms");
  auto c = std::make_shared<AnalyticCommand>(app);
  c->numbers.add("--velocity", "impact velocity g [m/s]");
  app->add_flag("--json", c->json, "print JSON");
  return {app, [c]() { return run_analytic(*c); }};
}

}  // namespace bounce::cli
