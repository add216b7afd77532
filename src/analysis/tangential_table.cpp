// eps^T(g^N, g^T) tables (docs/tables.md): the contact's fundamental solutions on a
// (ln g^N, s) grid and a lookup that replays the asperity breaks on them.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bounce/analysis/tables.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "table_common.hpp"
#include "tangential_core.hpp"

namespace bounce::analysis {

namespace detail {
extern const char* const tangential_table_core_text;  // tangential_table_core.h, compiled in by CMake
}

namespace {
constexpr const char* kind = "bounce tangential restitution table";
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
  const detail::tt_table v = detail::view(t);
  const double e = detail::tt_cor(&v, gn, gt, breaks);
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
    t.check_points = detail::integer_field(j.at("check_points"), "check_points", 0, 1'000'000'000'000);
    t.asperity_size = j.at("asperity_size").get<double>();
    t.order = static_cast<int>(detail::integer_field(j.at("order"), "order", 2, detail::tt_max_order));
    t.x0 = j.at("x0").get<double>();
    t.dx = j.at("dx").get<double>();
    t.s = j.at("s").get<std::vector<double>>();
    t.rows = j.at("rows").get<std::vector<double>>();
    t.nodes = j.at("nodes").get<std::vector<double>>();
  } catch (const nlohmann::json::exception& e) {
    throw InvalidArgument("table", "(malformed)",
                          fmt::format("a table written by bounce table (this one is {})", json_error_words(e.id, e.what())));
  }
  const std::size_t n = t.s.size(), r = t.row_count();
  const bool shape = n >= 2 && t.s.front() == 0.0 && t.s.back() == 1.0 && std::is_sorted(t.s.begin(), t.s.end()) &&
                     t.rows.size() == r * detail::tt_row_values && t.nodes.size() == r * n * detail::tt_node_values &&
                     t.order >= 2 && t.order <= detail::tt_max_order && r >= static_cast<std::size_t>(t.order) && t.dx > 0.0 &&
                     t.asperity_size > 0.0 && t.gn_min > 0.0 && t.gn_max > t.gn_min && t.gt_min > 0.0 &&
                     t.gt_max > t.gt_min &&
                     std::isfinite(t.gn_max) && std::isfinite(t.gt_max) && std::isfinite(t.asperity_size) &&
                     std::isfinite(t.x0) && std::isfinite(t.dx) && std::isfinite(t.bound) && t.bound > 0.0 &&
                     std::all_of(t.s.begin(), t.s.end(), [](double v) { return std::isfinite(v); }) &&
                     std::all_of(t.nodes.begin(), t.nodes.end(), [](double v) { return std::isfinite(v); }) &&
                     std::all_of(t.rows.begin(), t.rows.end(), [](double v) { return std::isfinite(v); });
  if (!shape) throw InvalidArgument("table", "(inconsistent sizes or values)", "a table written by bounce table");
  // The fundamental solutions' Wronskian y1 y2' - y2 y1' is 1 at every node (p'' = -K p
  // keeps it; written tables hold it to 2e-14): a table that breaks it was altered, and its
  // lookups could replay 1e8 asperity breaks (the fuzzer's y2 0.71 -> 4.71 took 3.6 s).
  for (std::size_t i = 0; i < t.nodes.size(); i += detail::tt_node_values) {
    const double* y = &t.nodes[i];
    if (!(std::abs(y[0] * y[3] - y[2] * y[1] - 1.0) <= 1e-9)) {
      throw InvalidArgument("table", "(fundamental solutions with Wronskian != 1)", "a table written by bounce table");
    }
  }
  detail::require_bounded_lookups(t, "table", fmt::format("g_tangential_max = {:g}", t.gt_max),
                                  "; a table written by bounce table");
  return t;
}

std::string TangentialTable::to_csv() const {
  std::string out = "row,velocity,s,tau,y1,dy1,y2,dy2,K,dK_ds\n";
  const std::size_t n = s.size();
  for (std::size_t r = 0; r < row_count(); ++r) {
    const double gn = std::exp(x0 + static_cast<double>(r) * dx), tau_end = rows[r * detail::tt_row_values];
    for (std::size_t j = 0; j < n; ++j) {
      const double* v = nodes.data() + (r * n + j) * detail::tt_node_values;
      out += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", r, gn, s[j],
                         tau_end * s[j] * s[j], v[0], v[1], v[2], v[3], v[4], v[5]);
    }
  }
  return out;
}

std::string TangentialTable::to_c_header(const std::string& prefix) const {
  detail::check_prefix(prefix);
  const std::string core = detail::renamed_core(detail::tangential_table_core_text, "tt_", prefix);
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
static inline double PREFIX_cor_tangential(double gn, double gt) {{
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

}  // namespace bounce::analysis
