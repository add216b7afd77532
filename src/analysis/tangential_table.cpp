// eps^T(g^N, g^T) tables (docs/tables.md): the contact's fundamental solutions on a
// (ln g^N, s) grid and a lookup that replays the asperity breaks on them.
#include <math.h>

#include <array>
#include <cmath>
#include <random>

#include <boost/numeric/odeint.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bounce/analysis/tables.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/dynamics/normal_collision.hpp"
#include "table_common.hpp"

namespace bounce {

namespace detail {
extern const char* const tangential_table_core_text;  // the file below, compiled in by CMake
}

namespace {
// The lookup is C99 (written into the C headers as it is), so it keeps C's casts and
// conversions.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wconversion"
#include "tangential_table_core.h"
#pragma GCC diagnostic pop

namespace odeint = boost::numeric::odeint;
using Row = std::array<double, tt_row_values>;
using State = std::array<double, 6>;  // x, v (normal motion, scaled), y1, y1', y2, y2'

constexpr const char* kind = "bounce tangential restitution table";
constexpr int stencil = 8;              // Lagrange points across the rows
constexpr double first_row_step = 0.1;  // spacing of the first rows in ln g^N
constexpr int first_nodes = 41;
constexpr int max_nodes = 2561;
constexpr std::size_t max_rows = 20000;
// Tolerance of the integration that gives the node values (scaled units): far below
// what the interpolation needs (~1e-9, docs/tables.md).
constexpr double node_tolerance = 1e-14;
// Step in s of the central difference that gives dK/ds (truncation ~1e-12, round-off
// ~1e-10 relative; it only enters the second derivative of y' at a node).
constexpr double derivative_step = 1e-6;

// One row: the normal collision at g^N integrated together with y1, y2 of
// p'' = -K p, K = mu (xi0 / zeta0) f / kappa, BSHP96 (10) with (35), in the scaled units
// of the normal collision (x = xi/xi0, v = xi'/g^N, tau = t g^N/xi0, f = F^N xi0/(m g^2)).
// tau_end is where F^N returns to 0 after the compression: beyond it F^T = 0 and the
// tangential speed no longer changes (asperities carry no shear in tension), whatever
// rule ends the contact.
struct RowBuilder {
  const models::NormalForceModel& model;
  double mass;
  models::TangentialModel tangential;
  const std::vector<double>& s;

  void operator()(double gn, Row& row, double* node) const {
    const double xi0 = model.reference_overlap(gn), time_unit = xi0 / gn;
    dynamics::NormalCollisionOptions o;
    o.end_rule = models::EndRule::force;
    o.integration.relative_tolerance = o.integration.absolute_tolerance = 1e-13;
    const double tau_end = dynamics::integrate_normal_collision(model, mass, gn, o).contact_time / time_unit;
    const double k_scale = tangential.friction * (xi0 / tangential.asperity_size) / tangential.kappa;
    auto force = [&](double x, double v) { return std::max(model.force(xi0 * x, gn * v) * xi0 / (mass * gn * gn), 0.0); };
    auto system = [&](const State& y, State& dydt, double) {
      const double f = force(y[0], y[1]), k = k_scale * f;
      dydt = {y[1], -f, y[3], -k * y[2], y[5], -k * y[4]};
    };
    // Each node at s - ds, s, s + ds within [0, 1] (strictly increasing times: the dense
    // output cannot repeat one); the neighbours give dK/ds.
    std::vector<double> at;
    std::vector<std::array<std::size_t, 3>> index;  // per node: left, own, right point in `at`
    for (const double sj : s) {
      std::array<std::size_t, 3> k{};
      if (sj - derivative_step >= 0.0) at.push_back(sj - derivative_step);
      k[0] = at.size() - (sj - derivative_step >= 0.0 ? 1 : 0);
      k[1] = at.size();
      at.push_back(sj);
      if (sj + derivative_step <= 1.0) at.push_back(sj + derivative_step);
      k[2] = at.size() - 1;
      index.push_back(k);
    }
    std::vector<double> times;
    for (const double a : at) times.push_back(tau_end * a * a);
    std::vector<State> states;
    State y{model.cutoff_overlap(gn) / xi0, 1.0, 1.0, 0.0, 0.0, 1.0};
    auto stepper = odeint::make_dense_output(node_tolerance, node_tolerance, odeint::runge_kutta_dopri5<State>());
    odeint::integrate_times(stepper, system, y, times.begin(), times.end(), 1e-6,
                            [&](const State& state, double) { states.push_back(state); });
    if (states.size() != times.size()) throw NumericalError("tangential table: a row's integration stopped early");
    auto k_at = [&](std::size_t i) { return k_scale * force(states[i][0], states[i][1]); };
    row = {tau_end, std::log(time_unit)};
    for (std::size_t j = 0; j < s.size(); ++j) {
      const auto [lo, own, hi] = index[j];
      const State& c = states[own];
      const double values[tt_node_values] = {c[2], c[3], c[4], c[5], k_at(own), (k_at(hi) - k_at(lo)) / (at[hi] - at[lo])};
      std::copy(values, values + tt_node_values, node + j * tt_node_values);
    }
  }
};

tt_table view(const TangentialTable& t) {
  return tt_table{static_cast<int>(t.row_count()), static_cast<int>(t.s.size()), t.order, t.x0, t.dx,
                  t.asperity_size, t.s.data(), t.rows.data(), t.nodes.data()};
}

// Random points (g^N, g^T), log-uniform, from a fixed seed: the build is reproducible.
struct CheckPoint {
  double gn, gt, direct;
};

}  // namespace

namespace {

// eps^T and the number of breaks, after the range checks.
double lookup(const TangentialTable& t, double gn, double gt, long* breaks) {
  require_finite("velocity", gn);
  require_finite("tangential_velocity", gt);
  const double slack = 1e-12;
  if (gn < t.gn_min * (1 - slack) || gn > t.gn_max * (1 + slack)) {
    throw InvalidArgument("velocity", fmt::format("{:g}", gn),
                          fmt::format("{:g} <= g^N <= {:g} m/s (the table's range)", t.gn_min, t.gn_max));
  }
  if (gt < t.gt_min * (1 - slack) || gt > t.gt_max * (1 + slack)) {
    throw InvalidArgument("tangential_velocity", fmt::format("{:g}", gt),
                          fmt::format("{:g} <= g^T <= {:g} m/s (the table's range)", t.gt_min, t.gt_max));
  }
  const tt_table v = view(t);
  const double e = tt_cor(&v, gn, gt, breaks);
  if (!std::isfinite(e)) throw NumericalError(fmt::format("tangential table: no value at g^N = {:g}, g^T = {:g} m/s", gn, gt));
  return e;
}

}  // namespace

double TangentialTable::cor(double gn, double gt) const { return lookup(*this, gn, gt, nullptr); }

long TangentialTable::breaks(double gn, double gt) const {
  long count = 0;
  lookup(*this, gn, gt, &count);
  return count;
}

bool is_tangential_table(const std::string& json) {
  const auto j = nlohmann::json::parse(json, nullptr, false);
  return !j.is_discarded() && j.is_object() && j.contains("kind") && j["kind"] == kind;
}

TangentialTable build_tangential_table(const Pair& pair, const models::ModelSpec& spec, double gn_min,
                                       double gn_max, double gt_min, double gt_max, const CollideOptions& options,
                                       const TableOptions& table) {
  detail::check_range("velocity", gn_min, gn_max);
  detail::check_range("tangential_velocity", gt_min, gt_max);
  require_positive("bound", table.bound, "an interpolation error bound > 0");
  const auto& info = models::model_info(spec.name);
  if (info.adhesive || info.dynamic_contact) {
    throw InvalidArgument("model", spec.name,
                          "a non-adhesive force-law model for an eps^T table (hertz, viscoelastic, "
                          "viscoelastic-shifted, power-law; docs/tables.md)");
  }
  const models::TangentialModel tangential = models::tangential_model(spec, pair);
  if (tangential.law != models::TangentialLaw::asperity) {
    throw InvalidArgument("tangential_law", std::string(models::to_string(tangential.law)),
                          "asperity for an eps^T table (the step law is not tabulated; docs/tables.md)");
  }
  if (tangential.form != models::AsperityForm::published) {
    throw InvalidArgument("asperity_form", std::string(models::to_string(tangential.form)),
                          "published for an eps^T table (the passive form is not tabulated; docs/tables.md)");
  }
  const auto force = models::make_normal_force(spec, pair);
  const double mass = pair.effective_mass();

  // The direct integration averages the sawtooth where asperities break more than
  // dense_breaks times per time unit; the table resolves every break, so its range must
  // stay clear of that (with a factor 2 for speeds above g^T, published form).
  for (const double gn : {gn_min, gn_max}) {
    const double time_unit = force->reference_overlap(gn) / gn;
    const double limit = 0.5 * tangential.dense_breaks * tangential.asperity_size / time_unit;
    if (gt_max > limit) {
      throw InvalidArgument("tangential_velocity_max", fmt::format("{:g}", gt_max),
                            fmt::format("<= {:.3g} m/s: faster, asperities break so densely at g^N = {:g} m/s that "
                                        "the direct integration averages them (docs/tangential.md)",
                                        limit, gn));
    }
  }

  TangentialTable t;
  t.description = detail::describe(pair, spec) +
                  fmt::format(", asperity law (published), mu = {:g}, zeta0 = {:g} m, kappa = {:g}",
                              tangential.friction, tangential.asperity_size, tangential.kappa);
  t.gn_min = gn_min;
  t.gn_max = gn_max;
  t.gt_min = gt_min;
  t.gt_max = gt_max;
  t.bound = table.bound;
  t.asperity_size = tangential.asperity_size;
  t.order = stencil;
  t.x0 = std::log(gn_min);
  const double span = std::log(gn_max) - t.x0;
  std::size_t rows = std::max<std::size_t>(stencil, static_cast<std::size_t>(std::ceil(span / first_row_step)) + 1);
  int nodes = first_nodes;

  std::size_t done = 0, estimate = 4000;
  auto tick = [&] {
    if (table.progress && ++done % 50 == 0) table.progress(done, std::max(estimate, done + 1));
  };
  auto build = [&] {
    const RowBuilder builder{*force, mass, tangential, t.s};
    t.s.resize(static_cast<std::size_t>(nodes));
    for (int j = 0; j < nodes; ++j) t.s[static_cast<std::size_t>(j)] = static_cast<double>(j) / (nodes - 1);
    t.dx = span / static_cast<double>(rows - 1);
    t.rows.assign(rows * tt_row_values, 0.0);
    t.nodes.assign(rows * t.s.size() * tt_node_values, 0.0);
    for (std::size_t r = 0; r < rows; ++r) {
      Row row{};
      builder(std::exp(t.x0 + static_cast<double>(r) * t.dx), row, t.nodes.data() + r * t.s.size() * tt_node_values);
      std::copy(row.begin(), row.end(), t.rows.begin() + static_cast<std::ptrdiff_t>(r * tt_row_values));
      tick();
    }
  };
  CollideOptions direct = options;
  direct.method = Method::integrate;
  direct.record_trajectory = false;
  auto direct_cor = [&](double gn, double gt) {
    direct.tangential_velocity = gt;
    const auto out = collide(pair, spec, gn, direct);
    tick();
    return out.tangential->cor;
  };
  std::mt19937_64 random(20261123);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto random_gt = [&] { return gt_min * std::pow(gt_max / gt_min, unit(random)); };
  auto worst = [&](const std::vector<CheckPoint>& points) {
    const tt_table v = view(t);
    double e = 0.0;
    for (const auto& p : points) {
      const double value = tt_cor(&v, p.gn, p.gt, nullptr);
      e = std::isfinite(value) ? std::max(e, std::abs(value - p.direct)) : HUGE_VAL;
    }
    return e;
  };

  // 1. Nodes: checked on the rows themselves (no interpolation across rows there).
  std::vector<CheckPoint> on_rows;
  for (int i = 0; i < 100; ++i) {
    const double x = t.x0 + span * std::floor(unit(random) * static_cast<double>(rows)) / static_cast<double>(rows - 1);
    const double gn = std::exp(std::min(x, t.x0 + span)), gt = random_gt();
    on_rows.push_back({gn, gt, direct_cor(gn, gt)});
  }
  for (build(); worst(on_rows) > table.bound / 8;) {
    if (nodes >= max_nodes) {
      throw NumericalError(fmt::format("tangential table: {} nodes per row do not reach {:g} at the rows", nodes, table.bound / 8));
    }
    nodes = 2 * nodes - 1;
    build();
  }
  // 2. Rows: checked at random points between them.
  std::vector<CheckPoint> between;
  for (int i = 0; i < 400; ++i) {
    const double gn = gn_min * std::pow(gn_max / gn_min, unit(random)), gt = random_gt();
    between.push_back({gn, gt, direct_cor(gn, gt)});
  }
  for (double e = worst(between);; e = worst(between)) {
    t.checked_error = e;
    if (e <= table.bound / 4) break;
    if (rows >= max_rows) {
      throw NumericalError(fmt::format("tangential table: {} rows do not reach {:g} between the rows", rows, table.bound / 4));
    }
    rows = 2 * rows - 1;
    build();
  }
  t.checked_error = std::max(t.checked_error, worst(on_rows));
  t.check_points = static_cast<long>(on_rows.size() + between.size());
  if (table.progress) table.progress(done, done);
  return t;
}

std::string TangentialTable::to_json() const {
  nlohmann::json j;
  j["kind"] = kind;
  j["description"] = description;
  j["variables"] = "rows: x = ln g^N equally spaced from x0 by dx; nodes: s = sqrt(tau/tau_end); docs/tables.md";
  j["g_normal_min"] = gn_min;
  j["g_normal_max"] = gn_max;
  j["g_tangential_min"] = gt_min;
  j["g_tangential_max"] = gt_max;
  j["bound"] = bound;
  j["checked_error"] = checked_error;
  j["check_points"] = check_points;
  j["asperity_size"] = asperity_size;
  j["order"] = order;
  j["x0"] = x0;
  j["dx"] = dx;
  j["s"] = s;
  j["rows"] = rows;
  j["nodes"] = nodes;
  return j.dump();
}

TangentialTable TangentialTable::from_json(const std::string& text) {
  TangentialTable t;
  try {
    const auto j = nlohmann::json::parse(text);
    if (j.at("kind") != kind) throw InvalidArgument("table", "kind", "a tangential table (bounce table --tangential-velocities)");
    t.description = j.at("description").get<std::string>();
    t.gn_min = j.at("g_normal_min").get<double>();
    t.gn_max = j.at("g_normal_max").get<double>();
    t.gt_min = j.at("g_tangential_min").get<double>();
    t.gt_max = j.at("g_tangential_max").get<double>();
    t.bound = j.at("bound").get<double>();
    t.checked_error = j.at("checked_error").get<double>();
    t.check_points = j.at("check_points").get<long>();
    t.asperity_size = j.at("asperity_size").get<double>();
    t.order = j.at("order").get<int>();
    t.x0 = j.at("x0").get<double>();
    t.dx = j.at("dx").get<double>();
    t.s = j.at("s").get<std::vector<double>>();
    t.rows = j.at("rows").get<std::vector<double>>();
    t.nodes = j.at("nodes").get<std::vector<double>>();
  } catch (const nlohmann::json::exception& e) {
    throw InvalidArgument("table", "(malformed)", fmt::format("a table written by bounce table ({})", e.what()));
  }
  const std::size_t n = t.s.size(), r = t.row_count();
  const bool shape = n >= 2 && t.s.front() == 0.0 && t.s.back() == 1.0 && std::is_sorted(t.s.begin(), t.s.end()) &&
                     t.rows.size() == r * tt_row_values && t.nodes.size() == r * n * tt_node_values &&
                     t.order >= 2 && t.order <= tt_max_order && r >= static_cast<std::size_t>(t.order) && t.dx > 0.0 &&
                     t.asperity_size > 0.0 && t.gn_min > 0.0 && t.gn_max > t.gn_min && t.gt_min > 0.0 &&
                     t.gt_max > t.gt_min &&
                     std::all_of(t.nodes.begin(), t.nodes.end(), [](double v) { return std::isfinite(v); }) &&
                     std::all_of(t.rows.begin(), t.rows.end(), [](double v) { return std::isfinite(v); });
  if (!shape) throw InvalidArgument("table", "(inconsistent sizes or values)", "a table written by bounce table");
  return t;
}

std::string TangentialTable::to_csv() const {
  std::string out = "row,velocity,s,tau,y1,dy1,y2,dy2,K,dK_ds\n";
  const std::size_t n = s.size();
  for (std::size_t r = 0; r < row_count(); ++r) {
    const double gn = std::exp(x0 + static_cast<double>(r) * dx), tau_end = rows[r * tt_row_values];
    for (std::size_t j = 0; j < n; ++j) {
      const double* v = nodes.data() + (r * n + j) * tt_node_values;
      out += fmt::format("{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", r, gn, s[j],
                         tau_end * s[j] * s[j], v[0], v[1], v[2], v[3], v[4], v[5]);
    }
  }
  return out;
}

std::string TangentialTable::to_c_header(const std::string& prefix) const {
  detail::check_prefix(prefix);
  std::string core = detail::tangential_table_core_text;
  const std::string renamed = prefix + "_tt_";
  for (std::size_t p = core.find("tt_"); p != std::string::npos; p = core.find("tt_", p + renamed.size())) {
    core.replace(p, 3, renamed);
  }
  std::string h = fmt::format(
      "/* eps^T(g^N, g^T) written by bounce table: {}.\n"
      " * g^N in [{:g}, {:g}] m/s, g^T in [{:g}, {:g}] m/s; error <= {:g} (largest at {} check points\n"
      " * against direct integration: {:.2g}). Self-contained C99: include it once per program. */\n"
      "#ifndef {}_H\n#define {}_H\n#include <math.h>\n",
      description, gn_min, gn_max, gt_min, gt_max, bound, check_points, checked_error, prefix, prefix);
  h += core;
  h += detail::c_array("double", prefix + "_s", s) + detail::c_array("double", prefix + "_rows", rows) +
       detail::c_array("double", prefix + "_nodes", nodes);
  h += fmt::format("static const {0}_tt_table {0}_table = {{{1}, {2}, {3}, {4:.17g}, {5:.17g}, {6:.17g}, {0}_s, {0}_rows, {0}_nodes}};\n",
                   prefix, row_count(), s.size(), order, x0, dx, asperity_size);
  h += detail::with_prefix(fmt::format(R"(
/* eps^T at g^N, g^T [m/s]; NaN outside the table's range. */
static double PREFIX_cor_tangential(double gn, double gt) {{
  if (!(gn >= {:.17g} && gn <= {:.17g} && gt >= {:.17g} && gt <= {:.17g})) return NAN;
  return PREFIX_tt_cor(&PREFIX_table, gn, gt, 0);
}}
#endif
)",
                                           gn_min * (1 - 1e-12), gn_max * (1 + 1e-12), gt_min * (1 - 1e-12),
                                           gt_max * (1 + 1e-12)),
                           prefix);
  return h;
}

}  // namespace bounce
