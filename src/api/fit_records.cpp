// The Record of a fit's result (docs/fitting.md, "Output"): best values, ranges, profiles,
// points, statistics, scales and timing, as the CLI prints them and Python returns them.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "bounce/analysis/fit.hpp"
#include "bounce/analytic/adhesive.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/pair/pair_parameters.hpp"
#include "fit_plan.hpp"

namespace bounce::api {

using detail::Plan;

namespace {

Table profile_table(const analysis::Profile& p) {
  Table t;
  t.columns = {"value", "chi2"};
  for (std::size_t j = 0; j < p.values.size(); ++j) {
    t.rows.push_back({p.values[j], std::isfinite(p.chi2[j]) ? Value(p.chi2[j]) : Value()});
  }
  return t;
}

// The values by name; a yield strength the data do not determine (its lower limit) is null.
Record values_record(const std::vector<std::string>& names, const std::vector<double>& values,
                     std::optional<double> yield_limit = std::nullopt) {
  Record r;
  for (std::size_t a = 0; a < names.size(); ++a) {
    const bool free = yield_limit && names[a] == "yield" && values[a] == *yield_limit;
    r.set(names[a], free ? Value() : Value(values[a]));
  }
  return r;
}

Record ranges_record(const std::vector<std::string>& names, const std::vector<analysis::ParameterRange>& ranges) {
  Record r;
  for (std::size_t a = 0; a < names.size(); ++a) {
    Value::List ends{ranges[a].lo ? Value(*ranges[a].lo) : Value(), ranges[a].hi ? Value(*ranges[a].hi) : Value()};
    r.set(names[a], Value(std::move(ends)));
  }
  return r;
}

// Each fitted parameter's SI unit from its declaration ("J/m^2", "s", "Pa"; "" when
// dimensionless), so that every front end prints a value with its unit.
Record units_record(const Plan& plan) {
  Record r;
  for (const ParameterSpec& s : plan.fitted) r.set(s.name, s.unit);
  return r;
}

// The parameters whose best value sits on an edge of its grid: "lower" or "upper" (a limit,
// not a value: docs/fitting.md, "Output"); the others are left out.
Record edges_record(const std::vector<std::string>& names, const std::vector<int>& edges) {
  Record r;
  for (std::size_t a = 0; a < names.size() && a < edges.size(); ++a) {
    if (edges[a] != 0) r.set(names[a], edges[a] < 0 ? "lower" : "upper");
  }
  return r;
}

Table points_table(const analysis::Experiment& data, const std::vector<double>& model_cor) {
  Table t;
  t.columns = {"line", "velocity", "cor", "cor_error", "outcome", "model_cor", "residual"};
  for (std::size_t n = 0; n < data.points.size(); ++n) {
    const auto& m = data.points[n];
    t.rows.push_back({m.line, m.velocity, m.cor, m.cor_error ? Value(*m.cor_error) : Value(), m.stuck ? "stick" : "bounce",
                      model_cor[n], m.cor - model_cor[n]});
  }
  return t;
}

// AIC and BIC of a least-squares fit: Gaussian errors of unknown sigma (N ln(RSS/N)) or,
// with errors given, the proper chi^2.
void add_information_criteria(Record& r, std::size_t n, std::size_t k, double fit_term) {
  const double nn = static_cast<double>(n), kk = static_cast<double>(k);
  r.set("parameters", k);
  r.set("aic", fit_term + 2.0 * kk);
  r.set("bic", fit_term + kk * std::log(nn));
}

// The normalised values and the scales K13 Figs 7 and 8 plot against: the reduced radius, the
// normalisations, and the plastic length scale (33) at half the largest measured speed (K13
// §4.2.2).
void add_scales(Record& r, const Plan& plan, const analysis::Experiment& data, const analysis::FitResult& f) {
  Record normalised;
  for (std::size_t a = 0; a < f.names.size(); ++a) {
    if (f.names[a] == "gamma" && plan.gamma_l) normalised.set("gamma_over_gamma_L", f.best.values[a] / *plan.gamma_l);
    if (f.names[a] == "yield") {
      normalised.set("yield_over_E_soft", f.yield_lower_limit ? Value() : Value(f.best.values[a] / plan.e_soft));
    }
  }
  r.set("normalised", std::move(normalised));
  const Pair& pair = *plan.pair;
  double v_max = 0.0;
  for (const auto& m : data.points) v_max = std::max(v_max, m.velocity);
  Record scales;
  scales.set("effective_radius", pair.effective_radius());
  scales.set("gamma_L", plan.gamma_l ? Value(*plan.gamma_l) : Value());
  scales.set("E_soft", plan.e_soft);
  if (v_max > 0.0) {
    scales.set("plastic_length_scale", analytic::plastic_length_scale(pair.effective_mass(), 0.5 * v_max,
                                                                      pair.effective_radius(), pair.effective_modulus()));
  }
  r.set("scales", std::move(scales));
}

// The grid's best, its extent and the profiles.
void add_grid(Record& r, const analysis::FitResult& f) {
  r.set("grid_best", values_record(f.names, f.grid_best.values));
  r.set("grid_chi2", f.grid_best.chi2);
  Record grid, profiles;
  for (std::size_t a = 0; a < f.names.size(); ++a) {
    const auto& v = f.profiles[a].values;
    grid.set(f.names[a], Record().set("lo", v.front()).set("hi", v.back()).set("points", v.size()));
    profiles.set(f.names[a], profile_table(f.profiles[a]));
  }
  r.set("grid", std::move(grid));
  r.set("profiles", std::move(profiles));
}

// With errors given, the proper chi^2 and its intervals; the information criteria either way.
void add_statistics(Record& r, const analysis::Experiment& data, const analysis::FitResult& f) {
  const std::size_t n = data.points.size(), k = f.names.size();
  if (f.weighted_best) {
    r.set("chi2_weighted", f.weighted_best->chi2);
    r.set("reduced_chi2", n > k ? Value(f.weighted_best->chi2 / static_cast<double>(n - k)) : Value());
    r.set("best_weighted", values_record(f.names, f.weighted_best->values, f.yield_lower_limit));
    r.set("intervals", ranges_record(f.names, f.intervals));
    add_information_criteria(r, n, k, f.weighted_best->chi2);
  } else {
    add_information_criteria(r, n, k, static_cast<double>(n) * std::log(std::max(f.best.chi2, 1e-300)));
  }
}

Record timing_record(const analysis::FitResult& f) {
  return Record()
      .set("grid_collisions", f.collision_seconds)
      .set("grid_collisions_cpu", f.collision_cpu_seconds)
      .set("cost_per_collision", f.collision_cpu_seconds / static_cast<double>(f.grid_collisions))
      .set("plastic", f.plastic_seconds)
      .set("chi2", f.chi2_seconds)
      .set("refinement", f.refine_seconds);
}

}  // namespace

Record detail::fit_record(const Plan& plan, const analysis::Experiment& data, const analysis::FitResult& f, bool timing) {
  Record r;
  r.set("model", plan.model);
  r.set("data", data.source);
  r.set("fitted", f.names);
  r.set("best", values_record(f.names, f.best.values, f.yield_lower_limit));
  r.set("units", units_record(plan));
  r.set("grid_edges", edges_record(f.names, f.grid_edges));
  if (f.yield_lower_limit) r.set("lower_limits", Record().set("yield", *f.yield_lower_limit));
  r.set("chi2", f.best.chi2);
  r.set("ranges", ranges_record(f.names, f.ranges));
  add_scales(r, plan, data, f);
  add_grid(r, f);
  r.set("points", points_table(data, f.cor));
  add_statistics(r, data, f);
  r.set("collisions", f.collisions);
  r.set("failed_trials", f.failed_trials);
  r.set("warnings", f.warnings);
  if (timing) r.set("timing", timing_record(f));
  return r;
}


}  // namespace bounce::api
