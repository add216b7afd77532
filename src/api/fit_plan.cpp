// What a fit's inputs say (docs/fitting.md): the parameters to fit (declared by the registry),
// their grids (given or the registry's defaults, scaled by gamma_L or E_soft) and each
// trial's inputs.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "bounce/core/error.hpp"
#include "bounce/core/suggest.hpp"
#include "bounce/models/registry.hpp"
#include "bounce/pair/pair_parameters.hpp"
#include "fit_plan.hpp"

namespace bounce::api {

namespace {

// The fits' default for the K13 engines' tolerance: e to ~1e-6 (measured against 1e-10 on
// K13's PSL-quartz pair, docs/fitting.md), four times faster than the collide default 1e-8.
constexpr double fit_adhesive_tolerance = 1e-5;

// The parameters that can be fitted with `model`: its own and the shared ones with a fit
// grid, and the pair's gamma for an adhesive model (the others do not use it).
std::vector<ParameterSpec> fittable_parameters(const std::string& model) {
  std::vector<ParameterSpec> out;
  const auto& row = models::model_registry().at(model);
  for (const ParameterSpec& s : pair_parameters()) {
    if (s.fit && row.traits.adhesive) out.push_back(s);
  }
  for (const ParameterSpec& s : row.parameters) {
    if (s.fit) out.push_back(s);
  }
  return out;
}

}  // namespace

std::vector<std::string> detail::split(const std::string& text, char separator) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const auto at = text.find(separator, start);
    out.push_back(text.substr(start, at == std::string::npos ? std::string::npos : at - start));
    if (at == std::string::npos) return out;
    start = at + 1;
  }
}

namespace {

std::vector<ParameterSpec> chosen_parameters(const std::string& model, const std::string& text) {
  const auto offered = fittable_parameters(model);
  std::vector<std::string> names;
  for (const auto& s : offered) names.push_back(s.name);
  const std::vector<std::string> wanted =
      text.empty() ? models::model_registry().at(model).fit : detail::split(text, ',');
  if (wanted.empty()) {
    throw InvalidArgument("fit", "(not given)",
                          fmt::format("the parameters to fit with model {}: some of {}", model, fmt::join(names, ", ")));
  }
  std::vector<ParameterSpec> out;
  for (const std::string& w : wanted) {
    const auto it = std::find_if(offered.begin(), offered.end(), [&](const ParameterSpec& s) { return s.name == w; });
    if (it == offered.end()) {
      throw InvalidArgument("fit", text.empty() ? w : text,
                            fmt::format("parameters that model {} can fit: some of {} ({} is none of them{})", model,
                                        fmt::join(names, ", "), w, did_you_mean(w, names)));
    }
    if (std::any_of(out.begin(), out.end(), [&](const ParameterSpec& s) { return s.name == w; })) {
      throw InvalidArgument("fit", text, "each parameter once");
    }
    out.push_back(*it);
  }
  std::stable_partition(out.begin(), out.end(), [](const ParameterSpec& s) { return s.name != "yield"; });
  return out;
}

// "P=LO:HI:N,..." (SI units, log-spaced) over the defaults of the registry.
std::map<std::string, std::vector<double>> given_grids(const std::string& text, const std::vector<ParameterSpec>& fitted) {
  std::map<std::string, std::vector<double>> out;
  if (text.empty()) return out;
  for (const std::string& item : detail::split(text, ',')) {
    const auto eq = item.find('=');
    const std::string name = item.substr(0, eq);
    const auto spec = std::find_if(fitted.begin(), fitted.end(), [&](const ParameterSpec& s) { return s.name == name; });
    if (eq == std::string::npos || spec == fitted.end()) {
      throw InvalidArgument("grid", item, "P=LO:HI:N for a fitted parameter P, items separated by commas");
    }
    if (out.count(name)) throw InvalidArgument("grid", item, "one grid per parameter");
    std::vector<double> v;
    try {
      v = detail::parse_range("grid", item.substr(eq + 1), true);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument("grid", item, e.allowed());
    }
    if (v.size() > 100'000) throw InvalidArgument("grid", item, "at most 100000 values per parameter");
    if (v.size() > 1 && !(v.back() > v.front())) throw InvalidArgument("grid", item, "LO < HI (or N = 1 for a fixed value)");
    v.erase(std::unique(v.begin(), v.end()), v.end());
    for (double x : v) {
      if (!spec->range.contains(x)) throw InvalidArgument("grid", item, spec->range.describe(spec->what()));
    }
    out.emplace(name, std::move(v));
  }
  return out;
}

double scale_of(const detail::Plan& plan, const ParameterSpec& s) {
  const std::string& scale = s.fit->scale;
  if (scale.empty()) return 1.0;
  if (scale == "E_soft") return plan.e_soft;
  if (scale == "gamma_L") {
    if (!plan.gamma_l) {
      throw InvalidArgument("grid", s.name,
                            fmt::format("a grid {0}=LO:HI:N [J/m^2]: the materials have no surface energy to scale "
                                        "the default grid by",
                                        s.name));
    }
    return *plan.gamma_l;
  }
  throw std::logic_error("unknown fit scale " + scale);
}

std::vector<double> default_grid(const detail::Plan& plan, const ParameterSpec& s) {
  const double k = scale_of(plan, s);
  const double lo = s.fit->lo * k, hi = s.fit->hi * k;
  std::vector<double> v(s.fit->points);
  for (std::size_t j = 0; j < v.size(); ++j) {
    const double f = v.size() == 1 ? 0.0 : static_cast<double>(j) / static_cast<double>(v.size() - 1);
    v[j] = std::exp(std::log(lo) + f * (std::log(hi) - std::log(lo)));
  }
  // The declared range may be narrower than a scaled default (gamma <= 1e3 J/m^2), and a fitted
  // time (A, T_vis) ends where the viscous models end for the pair, 1e6 t_H(c_t): the default A
  // grid's 1e-2 s refused PSL on quartz's trials there, and `fit --compare` failed.
  const double longest = s.unit == "s" && plan.pair ? models::longest_viscous_time(*plan.pair)
                                                                : std::numeric_limits<double>::infinity();
  std::erase_if(v, [&](double x) { return !s.range.contains(x) || x > longest; });
  return v;
}

}  // namespace

// A trial's case: the fixed inputs as bound once, the fitted values set (gamma: both bodies').
Case detail::trial_case(const detail::Plan& plan, std::span<const double> values) {
  detail::Bound b = plan.bound;
  for (std::size_t a = 0; a < values.size(); ++a) {
    const std::string& name = plan.fitted[a].name;
    Parameters& group = b.pair.spec(name) != nullptr ? b.pair : b.model_parameters;
    group.set(name, values[a]);
    if (name == "gamma") b.pair.set("gamma2", values[a]);
  }
  return detail::make_case(b);
}

detail::Plan detail::make_plan(const Bound& bound, const Inputs& inputs, const std::string& model) {
  detail::Plan plan;
  plan.model = model;
  plan.fitted = chosen_parameters(model, bound.own.text("fit"));
  for (const auto& [name, value] : inputs) {
    if (!bound.own.spec(name)) plan.fixed.emplace(name, value);
  }
  for (const ParameterSpec& s : plan.fitted) {
    for (const std::string& given : {s.name, s.name == "gamma" ? std::string("gamma2") : std::string()}) {
      if (auto it = plan.fixed.find(given); !given.empty() && it != plan.fixed.end()) {
        throw InvalidArgument(given, value_text(it->second),
                              fmt::format("no fixed value: {} is fitted (drop it from --fit to hold it fixed)", s.name));
      }
    }
  }
  if (!plan.fixed.count("adhesive_tolerance") && models::model_registry().at(model).traits.engine != models::Engine::force_law) {
    plan.fixed["adhesive_tolerance"] = fit_adhesive_tolerance;
  }
  plan.bound = bind_inputs(command("fit"), plan.fixed);
  const Pair& pair = plan.pair.emplace(bounce::make_pair(bound.pair));
  plan.gamma_l = pair.surface_energy();
  plan.e_soft = pair.soft_modulus();
  const auto grids = given_grids(bound.own.text("grid"), plan.fitted);
  for (const ParameterSpec& s : plan.fitted) {
    const auto it = grids.find(s.name);
    plan.axes.push_back({s.name, it != grids.end() ? it->second : default_grid(plan, s)});
  }
  return plan;
}

}  // namespace bounce::api
