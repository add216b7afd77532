// The CLI's text output: the front door's Records in words, for a person at a terminal.
#include "text.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace bounce::cli {

namespace {

double num(const Record& r, std::string_view key) { return r.at(key).number(); }
const std::string& str(const Record& r, std::string_view key) { return r.at(key).text(); }

// The fields of a record sorted by key (as the JSON prints them).
std::vector<std::pair<std::string, Value>> sorted(const Record& r) {
  auto fields = r.fields();
  std::sort(fields.begin(), fields.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return fields;
}

std::string lines(const char* prefix, const Value& list) {
  std::string s;
  for (const Value& v : list.list()) s += fmt::format("{}: {}\n", prefix, v.text());
  return s;
}

std::string tangential_line(const Record& t) {
  return fmt::format(
      "tangential   e^T = {:.12g} ({} asperity breaks resolved, {:.3g} s averaged; energy [J]: initial {:.6g}, "
      "final {:.6g}, asperities {:.6g}, left {:.6g}, from the stiffness change {:.6g})\n",
      num(t, "cor"), std::get<std::int64_t>(t.at("breaks").data()), num(t, "averaged_time"), num(t, "initial_kinetic"),
      num(t, "final_kinetic"), num(t, "asperity_dissipated"), num(t, "stored_at_end"), num(t, "stiffness_work"));
}

std::string merged_line(const Record& m) {
  if (m.at("mass").is_null() || std::holds_alternative<std::string>(m.at("mass").data())) {
    return "merged           = the grain stays on the wall\n";
  }
  return fmt::format("merged           = {:.6g} kg at {:.6g} m/s (frame of body 2 before the impact)\n", num(m, "mass"),
                     num(m, "velocity"));
}

}  // namespace

std::string collide_text(const Record& out) {
  // The warnings first: one may say the result describes no real collision (docs/models.md).
  std::string s = lines("warning", out.at("warnings"));
  s += fmt::format("model {} (contact end: {}, method: {}) at {:.6g} m/s\n", str(out, "model"), str(out, "contact_end"),
                   str(out, "method"), num(out, "velocity"));
  if (out.contains("kappa")) {
    s += fmt::format("kappa = {:.6g} (BP04 (8.70))", num(out, "kappa"));
    if (out.contains("characteristic_velocity")) s += fmt::format(", g* = {:.6g} m/s", num(out, "characteristic_velocity"));
    s += "\n";
  }
  const bool stuck = str(out, "outcome") == "stick";
  s += fmt::format("cor          e   = {:.12g}\noutcome          = {}\n", num(out, "cor"), str(out, "outcome"));
  if (out.contains("tangential")) s += tangential_line(out.at("tangential").record());
  s += stuck ? fmt::format("contact time t_c = none: the grains stick (integrated for {:.6g} s)\n",
                           num(out, "integrated_time"))
              : fmt::format("contact time t_c = {:.6g} s\n", num(out, "contact_time"));
  s += out.at("max_overlap").is_null() ? std::string("max overlap      = not reached before sticking was certain\n")
                                       : fmt::format("max overlap      = {:.6g} m\n", num(out, "max_overlap"));
  if (out.contains("merged")) s += merged_line(out.at("merged").record());
  const Record& e = out.at("energy").record();
  s += fmt::format(
      "energy [J]: initial {:.6g}, {} {:.6g}, bulk dissipated {:.6g}, crack dissipated {:.6g}, plastic {:.6g}, "
      "left elastic {:.6g}, left surface {:.6g}\n",
      num(e, "initial_kinetic"), stuck ? "kinetic at stop" : "final",
      num(e, stuck ? "kinetic_at_stop" : "final_kinetic"), num(e, "bulk_dissipated"), num(e, "crack_dissipated"),
      num(e, "plastic_dissipated"), num(e, "elastic_remaining"), num(e, "surface_remaining"));
  if (out.contains("closed_forms")) {
    const Record& closed = out.at("closed_forms").record();
    for (const auto& [key, value] : sorted(closed)) {
      if (key == "warnings") continue;  // with the other warnings, below
      s += value.is_null() ? fmt::format("  {:<28} null (beyond its validity: see the warning)\n", key)
                           : fmt::format("  {:<28} {:.6g}\n", key, value.number());
    }
    if (closed.contains("warnings")) s += lines("warning", closed.at("warnings"));
  }
  return s + lines("note", out.at("notes"));
}

std::string contact_text(const Record& out) {
  const Record& pair = out.at("pair").record();
  std::string s = fmt::format("law: {}\n", str(out, "law"));
  if (out.contains("ellipse")) {  // the curvatures shape the contact: the spheres' R_eff does not enter
    const Record& e = out.at("ellipse").record();
    s += fmt::format("pair: curvatures B1 = {:.6g} 1/m, B2 = {:.6g} 1/m (the contact's; not the spheres' R_eff), "
                     "m_eff = {:.6g} kg, E* = {:.6g} Pa",
                     num(e, "b1"), num(e, "b2"), num(pair, "effective_mass"), num(pair, "effective_modulus"));
  } else {
    s += fmt::format("pair: R_eff = {:.6g} m, m_eff = {:.6g} kg, E* = {:.6g} Pa", num(pair, "effective_radius"),
                     num(pair, "effective_mass"), num(pair, "effective_modulus"));
  }
  if (!pair.at("surface_energy").is_null()) s += fmt::format(", gamma = {:.6g} J/m^2", num(pair, "surface_energy"));
  s += "\n";
  const char* radius_label = out.contains("ellipse") ? "contact radius sqrt(ab)" : "contact radius a    ";
  s += fmt::format("{} = {:.6g} m\n", radius_label, num(out, "contact_radius"));
  s += fmt::format("overlap        delta = {:.6g} m\n", num(out, "overlap"));
  s += fmt::format("force          F     = {:.6g} N\n", num(out, "force"));
  if (out.contains("ellipse")) {
    const Record& e = out.at("ellipse").record();
    s += fmt::format("contact ellipse: a = {:.6g} m, b = {:.6g} m (x0 = a^2/b^2 = {:.6g}), C0 = {:.6g} N/m^1.5\n",
                     num(e, "semi_axis_a"), num(e, "semi_axis_b"), num(e, "x0"), num(e, "force_constant"));
  }
  if (out.contains("pull_off_force")) {
    s += fmt::format("pull-off force (force control)  = {:.6g} N at a = {:.6g} m\n", num(out, "pull_off_force"),
                     num(out, "pull_off_contact_radius"));
    s += fmt::format("zero load                       : a = {:.6g} m, delta = {:.6g} m\n",
                     num(out, "zero_load_contact_radius"), num(out, "zero_load_overlap"));
    s += fmt::format("separation (overlap control)    : delta = {:.6g} m at a = {:.6g} m\n",
                     num(out, "separation_overlap"), num(out, "separation_contact_radius"));
  }
  if (out.contains("tabor_parameter")) {
    s += fmt::format(
        "Tabor parameter mu = {:.4g} (K13 (11): {}), BP04 (8.55) mu = {:.4g} ({}), Maugis lambda = {:.4g}, z0 = {:g} "
        "m\n",
        num(out, "tabor_parameter"), str(out, "regime_k13"), num(out, "tabor_parameter_bp04"), str(out, "regime_bp04"),
        num(out, "maugis_lambda"), num(out, "z0"));
  }
  return s + lines("warning", out.at("warnings"));
}

namespace {

// Ten significant digits (a COR of 2.2e-14 is not 0.0000000000); a null one is a divergent series.
std::string value_line(const std::string& what, const Value& value) {
  return value.is_null() ? fmt::format("  {:<44} diverges (below)\n", what)
                         : fmt::format("  {:<44} {:.10g}\n", what, value.number());
}
std::string value_line(const std::string& what, double value) { return value_line(what, Value(value)); }

std::string coefficients_line(const std::string& what, const Record& series) {
  std::string s = fmt::format("  {:<14}", what);
  const auto& a = series.at("a").list();
  const auto& u = series.at("uncertainty").list();
  for (std::size_t i = 0; i < a.size(); ++i) {
    s += fmt::format(" a{}={:.6g}", i + 1, a[i].number());
    if (u[i].number() > 0) s += fmt::format("(+-{:.1g})", u[i].number());
  }
  return s + "\n";
}

}  // namespace

std::string analytic_text(const Record& out) {
  std::string s = fmt::format("kappa = {:.6g} (BP04 (8.70)), q = (g/g*)^(1/5) = 2 b kappa = {:.6g}, g* = {:.6g} m/s\n",
                              num(out, "kappa"), num(out, "q"), num(out, "characteristic_velocity"));
  const Record& exact = out.at("exact").record();
  const Record& series = out.at("series_8_89").record();
  const Record& pade = out.at("pade_8_92").record();
  s += "coefficient of restitution:\n";
  s += value_line("exact, overlap end rule (master curve)", num(exact, "overlap"));
  s += value_line("exact, force end rule (master curve)", num(exact, "force"));
  s += value_line("implicit equation BP04 (8.85)", num(out, "implicit_8_85"));
  s += value_line("continued fraction BP04 (8.86)", num(out, "continued_fraction_8_86"));
  s += value_line("series (8.89), BP04 simple a_k", series.at("bp04_simple"));
  s += value_line("series (8.89), BP04 a3 = 0.315, a4 = 0.161", series.at("bp04_rigorous"));
  s += value_line("series (8.89), bounce a_k (overlap rule)", series.at("bounce_overlap"));
  s += value_line("series, bounce, force rule (+ kappa^5/2 terms)", series.at("bounce_force"));
  s += value_line("Pade (8.92), BP04's printed d_k", num(pade, "bp04_printed"));
  s += value_line("Pade (8.92)-(8.93) from BP04's a_k", num(pade, "from_bp04_a_k"));
  s += value_line("Pade (8.92)-(8.93) from bounce's a_k", num(pade, "from_bounce_a_k"));
  if (series.contains("warnings"))
    for (const Value& w : series.at("warnings").list()) s += "  (" + w.text() + ")\n";
  s += "series coefficients a_k (e = 1 - a1 q + a2 q^2 - a3 q^3 + ...):\n";
  const Record& coefficients = out.at("coefficients").record();
  s += coefficients_line("BP04 simple", coefficients.at("bp04_simple").record());
  s += coefficients_line("BP04 rigorous", coefficients.at("bp04_rigorous").record());
  s += coefficients_line("bounce", coefficients.at("bounce_overlap").record());
  s += "contact time [s]:\n";
  for (const auto& [key, value] : sorted(out.at("contact_time").record())) s += value_line(key, value.number());
  return s;
}

std::string sticking_text(const Record& j, const std::string& model) {
  std::string s;
  if (j.at("sticking_velocity").is_null()) {
    s = fmt::format("no sticking velocity (model {}): {}\n", model, str(j, "note"));
  } else {
    const auto& bracket = j.at("bracket").list();
    s = fmt::format("sticking velocity {:.8g} m/s (model {}, bracket [{:.8g}, {:.8g}], {} collisions)\n",
                    num(j, "sticking_velocity"), model, bracket[0].number(), bracket[1].number(),
                    std::get<std::int64_t>(j.at("collisions").data()));
  }
  if (j.contains("sticking_velocity_jkr")) {
    s += fmt::format("elastic JKR (exact)  {:.8g} m/s\nK13 (25)             {:.8g} m/s\n", num(j, "sticking_velocity_jkr"),
                     num(j, "sticking_velocity_k13_25"));
  }
  if (j.contains("sticking_velocity_bp04_8_100")) {
    s += fmt::format("BP04 (8.100)         {:.8g} m/s\nBP04 (8.101)         {:.8g} m/s\n",
                     num(j, "sticking_velocity_bp04_8_100"), num(j, "sticking_velocity_bp04_8_101"));
  }
  return s;
}

std::string materials_text(const Value& materials) {
  std::string s = fmt::format("{:<16} {:>10} {:>6} {:>8} {:>11}  {}\n", "name", "E [GPa]", "nu", "rho", "gamma", "source");
  s += fmt::format("{:<16} {:>10} {:>6} {:>8} {:>11}\n", "", "", "", "[kg/m^3]", "[J/m^2]");
  for (const Value& v : materials.list()) {
    const Record& m = v.record();
    std::string gamma = "-";
    if (!m.at("surface_energy").is_null()) gamma = fmt::format("{:g}", num(m, "surface_energy"));
    if (m.contains("surface_energy_range")) {
      const auto& range = m.at("surface_energy_range").list();
      gamma = fmt::format("{:g}-{:g}", range[0].number(), range[1].number());
    }
    s += fmt::format("{:<16} {:>10g} {:>6g} {:>8g} {:>11}  {}\n", str(m, "name"), num(m, "youngs_modulus") / 1e9,
                     num(m, "poisson_ratio"), num(m, "density"), gamma, str(m, "source"));
  }
  // D2: which gamma this is, for users of the aggregate literature, which writes the per-surface one.
  s += "\ngamma is the work of adhesion (K13's; 2 gamma_s of like surfaces). Dominik & Tielens 1997, Chokshi et al.\n"
       "1993 and Wada et al. 2007 write gamma for the energy of one surface, gamma_s: give theirs as\n"
       "--surface-energy (bounce then takes gamma = 2 gamma_s; unlike surfaces combine as 2 sqrt(gamma_s1 gamma_s2)).\n";
  return s;
}

std::string table_value_text(const Record& r) {
  if (r.contains("cor_tangential")) {
    return fmt::format("cor_tangential {:.10g} ({} asperity breaks), table error <= {:g}\n", num(r, "cor_tangential"),
                       std::get<std::int64_t>(r.at("breaks").data()), num(r, "bound"));
  }
  return fmt::format("cor {:.10g} ({}), table error <= {:g}\n", num(r, "cor"), str(r, "outcome"), num(r, "bound"));
}

namespace {

// "0.5 J/m^2": a value with its unit (none for a dimensionless one).
std::string with_unit(double x, const std::string& unit, const char* form = "{:.4g}") {
  const std::string v = fmt::format(fmt::runtime(form), x);
  return unit.empty() ? v : v + " " + unit;
}

std::string range_text(const Value& range, const std::string& unit) {
  const auto& ends = range.list();
  auto end = [&](const Value& v) { return with_unit(v.number(), unit); };
  if (ends[0].is_null() && ends[1].is_null()) return "unconstrained on the grid";
  if (ends[0].is_null()) return fmt::format("< {} (the grid's lower edge is inside)", end(ends[1]));
  if (ends[1].is_null()) return fmt::format("> {} (a lower limit: the grid's upper edge is inside)", end(ends[0]));
  return fmt::format("{} .. {}", fmt::format("{:.4g}", ends[0].number()), end(ends[1]));
}

// A parameter's unit and grid edge as the Record gives them ("" and "" where it has none).
std::string field_of(const Record& f, const char* key, const std::string& name) {
  if (!f.contains(key) || !f.at(key).record().contains(name)) return {};
  return f.at(key).record().at(name).text();
}

// "gamma = 0.0994 J/m^2 (on the grid's lower edge: a limit)", or ">= 1e9 Pa (a lower limit)".
std::string best_text(const Record& f, const Value& best, const std::string& name, const char* form, bool edges = true) {
  const std::string unit = field_of(f, "units", name);
  if (best.is_null() && f.contains("lower_limits") && f.at("lower_limits").record().contains(name)) {
    return fmt::format(">= {} (a lower limit: the data do not determine it)",
                       with_unit(f.at("lower_limits").record().at(name).number(), unit));
  }
  const std::string edge = edges ? field_of(f, "grid_edges", name) : std::string();
  return with_unit(best.number(), unit, form) + (edge.empty() ? "" : " (on the grid's " + edge + " edge: a limit)");
}

// A parameter the data do not determine has no best value (null) but a lower limit.
std::string fitted_lines(const Record& f, const char* best_key, const char* range_key) {
  std::string s;
  for (const Value& name : f.at("fitted").list()) {
    const std::string& n = name.text();
    const Value& best = f.at(best_key).record().at(n);
    if (best.is_null()) {
      s += fmt::format("  {:<8} {}\n", n, best_text(f, best, n, "{:.4g}", false));
      continue;
    }
    // The grid's edges are the best's (K13 (31)); the weighted best's intervals say their own.
    s += fmt::format("  {:<8} = {:<22} range {}\n", n, best_text(f, best, n, "{:.6g}", best_key == std::string("best")),
                     range_text(f.at(range_key).record().at(n), field_of(f, "units", n)));
  }
  return s;
}

// A comparison row's best values with their units, on one line.
std::string comparison_best(const Record& c) {
  std::string s;
  for (const Value& name : c.at("fitted").list()) {
    const std::string& n = name.text();
    s += fmt::format("{}{} {}{}", s.empty() ? "" : ", ", n, c.at("best").record().at(n).is_null() ? "" : "= ",
                     best_text(c, c.at("best").record().at(n), n, "{:.4g}"));
  }
  return s;
}

std::string timing_lines(const Record& f) {
  if (!f.contains("timing")) return {};
  std::string s = "timing:";
  for (const auto& [key, value] : sorted(f.at("timing").record())) s += fmt::format(" {} {:.3g} s,", key, value.number());
  s.back() = '\n';
  return s;
}

}  // namespace

std::string fit_text(const Record& f) {
  std::string s = fmt::format("model {} fitted to {} ({} points, {} collisions)\n", str(f, "model"), str(f, "data"),
                              f.at("points").table().rows.size(), num(f, "collisions"));
  s += fmt::format("chi2 (K13 (31), mean squared residual) = {:.6g}; ranges: chi2 <= 2 chi2_min (K13 §4.1)\n",
                   num(f, "chi2"));
  s += fitted_lines(f, "best", "ranges");
  for (const auto& [key, value] : sorted(f.at("normalised").record())) {
    if (!value.is_null()) s += fmt::format("  {} = {:.4g}\n", key, value.number());
  }
  if (f.contains("chi2_weighted")) {
    s += fmt::format("proper chi2 = {:.6g}", num(f, "chi2_weighted"));
    if (!f.at("reduced_chi2").is_null()) s += fmt::format(", reduced {:.4g}", num(f, "reduced_chi2"));
    s += "; 1 sigma intervals (Delta chi2 = 1):\n" + fitted_lines(f, "best_weighted", "intervals");
  }
  s += fmt::format("AIC = {:.6g}, BIC = {:.6g} ({} parameters)\n", num(f, "aic"), num(f, "bic"), num(f, "parameters"));
  if (f.contains("comparison")) {
    s += "comparison (lowest AIC first is best):\n";
    for (const Value& row : f.at("comparison").list()) {
      const Record& c = row.record();
      s += fmt::format("  {:<52} chi2 {:<11.4g} AIC {:<10.5g} BIC {:<10.5g}\n      {}\n", str(c, "label"), num(c, "chi2"),
                       num(c, "aic"), num(c, "bic"), comparison_best(c));
    }
  }
  s += timing_lines(f);
  s += lines("warning", f.at("warnings"));
  return s;
}

}  // namespace bounce::cli
