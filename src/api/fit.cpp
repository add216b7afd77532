// The front door's fit (docs/fitting.md): each trial's pair and model built by the same
// binding as every other command (fit_plan.cpp), the comparison of models and the batch's two
// steps; the Record of the result is fit_records.cpp's.
#include <algorithm>
#include <array>
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

using detail::fit_record;
using detail::Plan;
using detail::split;
using detail::trial_case;


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
  for (const char* key : {"fitted", "best", "units", "grid_edges", "chi2", "ranges", "parameters", "aic", "bic", "warnings"}) {
    row.set(key, r.at(key));
  }
  for (const char* key : {"chi2_weighted", "lower_limits"}) {
    if (r.contains(key)) row.set(key, r.at(key));
  }
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
  // A yield strength the data do not reach is left out: the curve has no plastic loss.
  const bool yield = names.back() == "yield" && !f.result.yield_lower_limit;
  std::vector<double> values = f.result.best.values;
  if (names.back() == "yield") values.pop_back();
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

namespace {

constexpr std::array<const char*, 3> not_in_batch = {"compare", "chi2_grid", "timing"};

// A misspelt key of a batch lists the keys a batch takes: not the three it refuses.
InvalidArgument batch_keys_only(const InvalidArgument& e) {
  std::string allowed = e.allowed();
  for (const char* name : not_in_batch) {
    const std::string item = fmt::format(", {}", name);
    if (const auto at = allowed.find(item); at != std::string::npos) allowed.erase(at, item.size());
  }
  return InvalidArgument(e.parameter(), e.value(), allowed);
}

}  // namespace

FitJob::FitJob(const Inputs& inputs, const analysis::Experiment& data) {
  const detail::Bound bound = [&] {
    try {
      return detail::bind_inputs(command("fit"), inputs);
    } catch (const InvalidArgument& e) {
      throw batch_keys_only(e);
    }
  }();
  for (const char* name : not_in_batch) {
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
