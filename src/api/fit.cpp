// The front door's fit (docs/fitting.md): each trial's pair and model built by the same
// binding as every other command (fit_plan.cpp), the comparison of models, the batch's two
// steps, and the Record of the result.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "bounce/analytic/adhesive.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/models/registry.hpp"
#include "bounce/pair/pair_parameters.hpp"
#include "fit_plan.hpp"

namespace bounce::api {

namespace {

using detail::Plan;
using detail::split;
using detail::trial_case;

Table profile_table(const analysis::Profile& p) {
  Table t;
  t.columns = {"value", "chi2"};
  for (std::size_t j = 0; j < p.values.size(); ++j) {
    t.rows.push_back({p.values[j], std::isfinite(p.chi2[j]) ? Value(p.chi2[j]) : Value()});
  }
  return t;
}

Record values_record(const std::vector<std::string>& names, const std::vector<double>& values) {
  Record r;
  for (std::size_t a = 0; a < names.size(); ++a) r.set(names[a], values[a]);
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
    if (f.names[a] == "yield") normalised.set("yield_over_E_soft", f.best.values[a] / plan.e_soft);
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
    r.set("best_weighted", values_record(f.names, f.weighted_best->values));
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

Record fit_record(const Plan& plan, const analysis::Experiment& data, const analysis::FitResult& f, bool timing) {
  Record r;
  r.set("model", plan.model);
  r.set("data", data.source);
  r.set("fitted", f.names);
  r.set("best", values_record(f.names, f.best.values));
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

}  // namespace

// A fit prepared: the plan and the problem (whose case_at refers to the plan: it does not
// move, FitJob shares it).
struct FitJob::State {
  Plan plan;
  analysis::FitProblem problem;
  bool timing = false;
};

namespace {

std::shared_ptr<FitJob::State> prepare(const Inputs& inputs, const analysis::Experiment& data, const Progress& progress) {
  const CommandSpec& c = command("fit");
  const detail::Bound bound = detail::bind_inputs(c, inputs);
  auto state = std::make_shared<FitJob::State>();
  state->plan = make_plan(bound, inputs, bound.model);
  state->timing = bound.own.flag("timing");
  const Plan& plan = state->plan;
  analysis::FitProblem& p = state->problem;
  p.data = data;
  for (std::size_t a = 0; a < plan.fitted.size(); ++a) {
    (plan.fitted[a].name == "yield" ? p.yield_axis.emplace() : p.collision_axes.emplace_back()) = plan.axes[a];
  }
  p.case_at = [&plan](std::span<const double> values) {
    Case trial = trial_case(plan, values);
    return analysis::FitCase{std::move(trial.pair), std::move(trial.model), trial.options};
  };
  p.threads = static_cast<unsigned>(*bound.own.real("threads"));
  p.precision = *bound.own.real("precision");
  p.refine = !bound.own.flag("grid_only");
  p.keep_grid = bound.own.flag("chi2_grid");
  if (progress) p.progress = [progress](std::size_t done, std::size_t total) { progress(done, total); };
  // Every speed must be one the pair takes (c_t, double precision): refused naming its line.
  for (const auto& m : data.points) {
    try {
      analysis::require_impact_velocity(*plan.pair, m.velocity);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(fmt::format("{}:{}: velocity", data.source, m.line), format_value(m.velocity), e.allowed());
    }
  }
  return state;
}

// A fit of one model: its prepared state and the result.
struct Fitted {
  std::shared_ptr<const FitJob::State> state;
  analysis::FitResult result;
  const Plan& plan() const { return state->plan; }
};

Fitted run_fit(const Inputs& inputs, const analysis::Experiment& data, const Progress& progress) {
  auto state = prepare(inputs, data, progress);
  analysis::FitResult result = analysis::fit(state->problem);
  return {std::move(state), std::move(result)};
}

// The comparison of K13 Fig 6 and §4.2: the three mechanisms together and without some, as the
// models declare their lines (models::Traits::comparisons), by rank.
struct Comparison {
  std::string label;
  std::string model;
  std::string fit;
  std::optional<double> a;  // a fixed A [s] (0: no bulk damping)
};

std::vector<Comparison> comparisons() {
  std::vector<std::pair<int, Comparison>> lines;
  for (const auto& row : models::model_registry().rows()) {
    for (const auto& k : row.traits.comparisons) lines.push_back({k.rank, {k.label, row.name, k.fit, k.dissipative_constant}});
  }
  std::stable_sort(lines.begin(), lines.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<Comparison> out;
  for (auto& line : lines) out.push_back(std::move(line.second));
  return out;
}

// The user's inputs for a comparison model: the pair's and the numerical ones, the model's
// where that model takes them and does not fit them, grids of the parameters it fits.
Inputs comparison_inputs(const Inputs& user, const Comparison& k) {
  const std::vector<std::string> fitted = split(k.fit, ',');
  auto fits = [&](const std::string& n) { return std::find(fitted.begin(), fitted.end(), n) != fitted.end(); };
  const auto& row = models::model_registry().at(k.model);
  const auto& own = command("fit").parameters;
  Inputs in;
  for (const auto& entry : user) {  // not a structured binding: clang 14 cannot capture one
    const std::string& name = entry.first;
    const ParameterValue& value = entry.second;
    const bool pair = std::any_of(pair_parameters().begin(), pair_parameters().end(),
                                  [&](const ParameterSpec& s) { return s.name == name; });
    const bool model = std::any_of(row.parameters.begin(), row.parameters.end(),
                                   [&](const ParameterSpec& s) { return s.name == name; });
    const bool command_own = std::any_of(own.begin(), own.end(), [&](const ParameterSpec& s) { return s.name == name; });
    if (name == "fit" || name == "compare" || name == "chi2_grid" || name == "model") continue;
    if (name == "grid") {
      std::vector<std::string> items;
      for (const std::string& item : split(std::get<std::string>(value), ',')) {
        if (fits(item.substr(0, item.find('=')))) items.push_back(item);
      }
      if (!items.empty()) in.emplace(name, fmt::format("{}", fmt::join(items, ",")));
      continue;
    }
    if ((pair && !(fits("gamma") && (name == "gamma" || name == "gamma2"))) || command_own || (model && !fits(name))) {
      in.emplace(name, value);
    }
  }
  in["model"] = std::string(k.model);
  in["fit"] = std::string(k.fit);
  if (k.a) {
    for (const char* n : {"A", "tvis", "eta1", "eta2"}) in.erase(n);
    in["A"] = *k.a;
  }
  return in;
}

Record comparison_row(const Comparison& k, const Fitted& f, const analysis::Experiment& data) {
  Record r = fit_record(f.plan(), data, f.result, false);
  Record row;
  row.set("label", k.label);
  row.set("model", k.model);
  for (const char* key : {"fitted", "best", "chi2", "ranges", "parameters", "aic", "bic", "warnings"}) row.set(key, r.at(key));
  if (r.contains("chi2_weighted")) row.set("chi2_weighted", r.at("chi2_weighted"));
  return row;
}

// BP04 (8.88): g* of a Hertz-type model at the fitted values (and at the ends of the ranges
// of its collision parameters), for the models that have one.
void add_characteristic_velocity(Record& r, const Fitted& f) {
  const Plan& plan = f.plan();
  const auto& names = f.result.names;
  const std::size_t collision = names.size() - (names.back() == "yield" ? 1 : 0);
  auto g_star = [&](std::vector<double> values) -> std::optional<double> {
    values.resize(collision);
    const Case c = trial_case(plan, values);
    if (!c.model.hertz || !(c.model.hertz->dissipative_constant > 0.0)) return std::nullopt;
    return analysis::viscoelastic_scales(c.pair, c.model, 1.0).characteristic_velocity;
  };
  const auto best = g_star(f.result.best.values);
  if (!best) return;
  r.set("characteristic_velocity", *best);
  if (collision != 1) return;  // a range of g* only when A (or T_vis) alone sets it
  const analysis::ParameterRange& range = f.result.ranges[0];
  auto at = [&](const std::optional<double>& x) { return x ? Value(*g_star({*x})) : Value(); };
  // g* falls as A grows: the upper end of A gives the lower end of g*.
  r.set("characteristic_velocity_range", Value(Value::List{at(range.hi), at(range.lo)}));
}

// The best fit as a curve over the data's speeds (K13 Fig 6): e (30), e_A, e_P (29), and
// e_JKR of K13 (24) at the fitted gamma for the adhesive models (a speed whose collision
// fails is left out).
Table best_curve(const Fitted& f, const analysis::Experiment& data) {
  const auto& names = f.result.names;
  const bool yield = names.back() == "yield";
  std::vector<double> values = f.result.best.values;
  if (yield) values.pop_back();
  const Case c = trial_case(f.plan(), values);
  double lo = data.points.front().velocity, hi = lo;
  for (const auto& m : data.points) lo = std::min(lo, m.velocity), hi = std::max(hi, m.velocity);
  lo /= 2.0;
  hi = std::min(2.0 * hi, c.pair.transversal_sound_speed());
  const auto gamma = c.pair.surface_energy();
  const bool adhesive = c.model.traits.adhesive && gamma && *gamma > 0.0;
  const double v_s = adhesive ? analytic::sticking_velocity_k13(c.pair.effective_mass(), c.pair.effective_radius(),
                                                               c.pair.effective_modulus(), *gamma)
                              : 0.0;  // K13 (25)
  Table t;
  t.columns = {"velocity", "cor", "cor_adhesive", "cor_plastic", "cor_jkr"};
  constexpr int n = 80;
  for (int i = 0; i < n; ++i) {
    const double v = lo * std::pow(hi / lo, i / (n - 1.0));
    double e_a = 0.0;
    try {
      e_a = analysis::cor(c.pair, c.model, v, c.options);
    } catch (const Error&) {
      continue;
    }
    const std::optional<double> y = yield ? std::optional(f.result.best.values.back()) : std::nullopt;
    const double e_p = y ? analytic::cor_thornton_ning(
                               v, analytic::yield_velocity(c.pair.effective_radius(), c.pair.effective_mass(),
                                                           c.pair.effective_modulus(), *y))
                         : 1.0;  // K13 (28)-(29)
    t.rows.push_back({v, analysis::combine_plastic(e_a, e_p), e_a, e_p,
                      adhesive ? Value(analytic::cor_jkr(v, v_s)) : Value()});  // K13 (24)
  }
  return t;
}

// The Record of a fit: K13's numbers, g*, the best-fit curve, the grid when kept.
Record result_record(const Fitted& f) {
  const analysis::Experiment& data = f.state->problem.data;
  Record r = fit_record(f.plan(), data, f.result, f.state->timing);
  add_characteristic_velocity(r, f);
  r.set("curve", best_curve(f, data));
  if (!f.result.chi2_grid.empty()) {
    Value::List grid;
    for (double x : f.result.chi2_grid) grid.push_back(std::isfinite(x) ? Value(x) : Value());
    const auto& shape = f.result.grid_shape;
    r.set("chi2_grid", Record()
                           .set("shape", Value(std::vector<double>(shape.begin(), shape.end())))
                           .set("values", Value(std::move(grid))));
  }
  return r;
}

}  // namespace

Record fit(const Inputs& inputs, const analysis::Experiment& data, const Progress& progress) {
  const detail::Bound bound = detail::bind_inputs(command("fit"), inputs);
  const Fitted main = run_fit(inputs, data, progress);
  Record r = result_record(main);
  if (!bound.own.flag("compare")) return r;
  Value::List rows;
  for (const Comparison& k : comparisons()) {
    const bool same = main.plan().model == k.model && !k.a &&
                      fmt::format("{}", fmt::join(main.result.names, ",")) == k.fit;
    rows.push_back(comparison_row(k, same ? main : run_fit(comparison_inputs(inputs, k), data, progress), data));
  }
  std::stable_sort(rows.begin(), rows.end(),
                   [](const Value& a, const Value& b) { return a.record().at("aic").number() < b.record().at("aic").number(); });
  r.set("comparison", Value(std::move(rows)));
  return r;
}

FitJob::FitJob(const Inputs& inputs, const analysis::Experiment& data) {
  const detail::Bound bound = detail::bind_inputs(command("fit"), inputs);
  for (const char* name : {"compare", "chi2_grid", "timing"}) {
    if (bound.own.flag(name)) throw InvalidArgument(name, "true", "none in a batch (a fit of one experiment has it)");
  }
  state_ = prepare(inputs, data, {});
}

std::size_t FitJob::grid_points() const { return analysis::grid_point_count(state_->problem); }

std::vector<analysis::GridPoint> FitJob::integrate(std::size_t first, std::size_t count) const {
  return analysis::integrate_grid_points(state_->problem, first, count);
}

Record FitJob::finish(std::vector<analysis::GridPoint> points) const {
  return result_record(Fitted{state_, analysis::fit(state_->problem, std::move(points))});
}

const analysis::FitProblem& FitJob::problem() const { return state_->problem; }

}  // namespace bounce::api
