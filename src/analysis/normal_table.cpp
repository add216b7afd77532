// eps^N(g) tables (docs/tables.md): built by CurveBuilder, evaluated by the C99 core that the
// C headers carry too (normal_table_core.h).
#include <math.h>

#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bounce/analysis/sticking.hpp"
#include "bounce/analysis/tables.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "curve_builder.hpp"
#include "table_common.hpp"

namespace bounce::analysis {

namespace detail {
extern const char* const normal_table_core_text;  // normal_table_core.h, compiled in by CMake
}

namespace {
// The lookup is C99 (written into the C headers as it is), so it keeps C's casts.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wconversion"
#include "normal_table_core.h"
#pragma GCC diagnostic pop

constexpr const char* kind = "bounce normal restitution table";

nt_curve view(const PiecewiseCubic& c) {
  return nt_curve{static_cast<long>(c.x.size()), c.x.data(), c.f.data(), c.slope.data(), c.label.data()};
}

nt_table view(const NormalTable& t) { return nt_table{view(t.curve), t.g_min, t.g_max, t.sticking_velocity}; }

nlohmann::json curve_json(const PiecewiseCubic& c) {
  nlohmann::json nodes = nlohmann::json::array();
  for (std::size_t i = 0; i < c.x.size(); ++i) {
    nodes.push_back({c.x[i], c.f[i], c.slope[i], static_cast<long>(c.label[i])});
  }
  return nodes;
}

PiecewiseCubic curve_from_json(const nlohmann::json& nodes) {
  PiecewiseCubic c;
  for (const auto& n : nodes) {
    c.x.push_back(detail::finite_field(n.at(0), "node x"));
    c.f.push_back(detail::finite_field(n.at(1), "node cor"));
    if (!(c.f.back() >= 0.0 && c.f.back() <= 1.0)) {  // an edited table: no collision gives it
      throw InvalidArgument("table", fmt::format("node cor = {}", n.at(1).dump()),
                            "a coefficient of restitution 0 <= cor <= 1 at every node (a table written by bounce table)");
    }
    c.slope.push_back(detail::finite_field(n.at(2), "node slope"));
    c.label.push_back(static_cast<double>(detail::integer_field(n.at(3), "node outcome", 0, 1)));
    if (c.x.size() > 1 && !(c.x.back() > c.x[c.x.size() - 2])) {
      throw InvalidArgument("table", "(nodes not increasing)", "a table written by bounce table");
    }
  }
  if (c.x.size() < 2) throw InvalidArgument("table", "(fewer than 2 nodes)", "a table written by bounce table");
  return c;
}

}  // namespace

// --- PiecewiseCubic ----------------------------------------------------------------

double PiecewiseCubic::in_piece(double want, double at) const {
  const nt_curve c = view(*this);
  const double value = nt_in_piece(&c, want, at);
  if (std::isnan(value)) throw NumericalError(fmt::format("table: no piece labelled {}", want));
  return value;
}

double PiecewiseCubic::label_at(double at) const {
  if (x.size() < 2) throw NumericalError("table: fewer than 2 nodes");
  const nt_curve c = view(*this);
  return nt_label_at(&c, at);
}

double PiecewiseCubic::operator()(double at) const {
  if (x.size() < 2) throw NumericalError("table: fewer than 2 nodes");
  const nt_curve c = view(*this);
  return nt_curve_at(&c, at);
}

// --- eps^N ---------------------------------------------------------------------------

namespace {

void require_in_range(double g, double g_min, double g_max) {
  require_finite("velocity", g);
  if (g < g_min * (1 - 1e-12) || g > g_max * (1 + 1e-12)) {
    throw InvalidArgument("velocity", fmt::format("{:g}", g), fmt::format("{:g} <= g <= {:g} m/s (the table's range)", g_min, g_max));
  }
}

}  // namespace

double NormalTable::cor(double g) const {
  require_in_range(g, g_min, g_max);
  const nt_table t = view(*this);
  return nt_cor(&t, g);
}

// Outside the table's range neither is known: refused as cor() (the C header's -1).
dynamics::Outcome NormalTable::outcome(double g) const {
  require_in_range(g, g_min, g_max);
  const nt_table t = view(*this);
  return nt_sticks(&t, g) ? dynamics::Outcome::stick : dynamics::Outcome::bounce;
}

NormalTable build_normal_table(const Pair& pair, const models::Model& model, double g_min, double g_max,
                               const CollideOptions& options, const TableOptions& table) {
  detail::check_range("velocity", g_min, g_max);
  require_positive("bound", table.bound, "an interpolation error bound");
  NormalTable t;
  t.description = detail::describe(pair, model);
  t.g_min = g_min;
  t.g_max = g_max;
  t.bound = table.bound;
  if (model.traits.adhesive) {
    const StickingVelocity v = sticking_velocity(pair, model, options, 1e-13);
    if (v.upper > g_min) t.sticking_velocity = v.upper;  // the smallest speed found to bounce
    if (v.sticks_up_to_sound_speed || v.upper >= g_max) {
      throw InvalidArgument("velocity_max", format_value(g_max),
                            v.sticks_up_to_sound_speed
                                ? std::string("a pair that bounces somewhere: it sticks at every speed up to the sound speed")
                                : fmt::format("a range reaching above the sticking velocity {:.6g} m/s (below it the grains "
                                              "stick, eps^N = 0: nothing to tabulate)",
                                              v.upper));
    }
  }
  std::size_t done = 0;
  auto tick = [&] {
    if (table.progress && ++done % 50 == 0) table.progress(done, 0);  // adaptive: no total known
  };
  const double vs = t.sticking_velocity;
  detail::WarningLog warnings;
  detail::Function f = [&](double x) {
    const double g = vs > 0.0 ? vs + std::exp(x) : std::exp(x);
    const auto out = collide(pair, model, g, options);
    warnings.add(g, out.warnings);
    return detail::Sample{out.cor, out.outcome == dynamics::Outcome::bounce ? 1.0 : 0.0};
  };
  // With sticking: from 1e-12 v_s above the threshold (eps^N ~ 1e-6 there) up to g_max.
  const double lo = vs > 0.0 ? std::log(1e-12 * vs) : std::log(g_min);
  const double hi = std::log(g_max - vs);
  detail::CurveBuilder builder(f, table.bound, tick);
  t.curve = builder.build(lo, hi, std::max(8, static_cast<int>(std::ceil(2.0 * (hi - lo)))));
  t.warnings = warnings.list();
  if (table.progress) table.progress(done, done);
  return t;
}

std::string NormalTable::to_json() const {
  nlohmann::json j;
  j["kind"] = kind;
  j["description"] = description;
  j["variable"] = "x = ln(g - sticking_velocity) (ln g without sticking); eps^N = 0 below sticking_velocity";
  j["g_min"] = g_min;
  j["g_max"] = g_max;
  j["sticking_velocity"] = sticking_velocity;
  j["bound"] = bound;
  j["nodes"] = curve_json(curve);
  return j.dump(1);
}

NormalTable NormalTable::from_json(const std::string& text) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
    if (j.at("kind") != kind) throw InvalidArgument("table", "kind", "a normal table");
    NormalTable t;
    t.description = j.at("description").get<std::string>();
    t.g_min = detail::finite_field(j.at("g_min"), "g_min");
    t.g_max = detail::finite_field(j.at("g_max"), "g_max");
    t.sticking_velocity = detail::finite_field(j.at("sticking_velocity"), "sticking_velocity");
    t.bound = detail::finite_field(j.at("bound"), "bound");
    if (!(t.g_min > 0.0 && t.g_max > t.g_min && t.sticking_velocity >= 0.0 && t.bound > 0.0)) {
      throw InvalidArgument("table", "(inconsistent ranges)", "a table written by bounce table (0 < g_min < g_max, bound > 0)");
    }
    t.curve = curve_from_json(j.at("nodes"));
    return t;
  } catch (const nlohmann::json::exception& e) {
    throw InvalidArgument("table", "(malformed)",
                          fmt::format("a table written by bounce table (this one is {})", json_error_words(e.id, e.what())));
  }
}

// Every number in its shortest round-trip form. The last node is g_max and, without sticking,
// the first is g_min (the builder's ends): printed as given, not v_s + exp(x) (19.99999999999998
// for 20); the other velocities are v_s + exp(x).
std::string NormalTable::to_csv() const {
  const double offset = sticking_velocity > 0.0 ? sticking_velocity : 0.0;
  const std::size_t n = curve.x.size();
  std::string s = "velocity,x,cor,slope,outcome\n";
  for (std::size_t i = 0; i < n; ++i) {
    const double g = i + 1 == n ? g_max : i == 0 && offset == 0.0 ? g_min : offset + std::exp(curve.x[i]);
    s += fmt::format("{},{},{},{},{}\n", g, curve.x[i], curve.f[i], curve.slope[i],
                     curve.label[i] != 0.0 ? "bounce" : "stick");
  }
  return s;
}

std::string NormalTable::to_c_header(const std::string& prefix) const {
  detail::check_prefix(prefix);
  std::string s = fmt::format(
      "/* eps^N(g) written by bounce table: {}.\n"
      " * g in [{:g}, {:g}] m/s; below the sticking velocity {:.17g} m/s the grains stick (eps^N = 0).\n"
      " * Interpolation error <= {:g}. Self-contained C99: include it once per program. */\n"
      "#ifndef {}_H\n#define {}_H\n#include <math.h>\n",
      description, g_min, g_max, sticking_velocity, bound, prefix, prefix);
  s += detail::renamed_core(detail::normal_table_core_text, "nt_", prefix);
  s += detail::c_array("double", prefix + "_x", curve.x) + detail::c_array("double", prefix + "_f", curve.f) +
       detail::c_array("double", prefix + "_d", curve.slope) + detail::c_array("double", prefix + "_label", curve.label);
  s += fmt::format(
      "static const {0}_nt_table {0}_table = {{{{{1}, {0}_x, {0}_f, {0}_d, {0}_label}}, {2:.17g}, {3:.17g}, {4:.17g}}};\n",
      prefix, curve.x.size(), g_min, g_max, sticking_velocity);
  s += detail::with_prefix(R"(
/* 1 if grains meeting at g [m/s] stick. */
static inline int PREFIX_sticks(double g) { return PREFIX_nt_sticks(&PREFIX_table, g); }
/* eps^N at g [m/s]; NaN outside [g_min, g_max]. */
static inline double PREFIX_cor(double g) { return PREFIX_nt_cor(&PREFIX_table, g); }
#endif
)",
                           prefix);
  return s;
}

}  // namespace bounce::analysis
