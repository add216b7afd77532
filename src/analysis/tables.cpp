#include "bounce/analysis/tables.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bounce/analysis/sticking.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "table_common.hpp"

namespace bounce {

using detail::c_array;
using detail::check_prefix;
using detail::check_range;
using detail::describe;
using detail::with_prefix;

namespace {

// Jumps are located to this width (in the logarithmic variable).
constexpr double jump_width = 1e-11;
// Step of the finite differences that give the node slopes: small enough for a
// truncation of ~1e-9, large enough that evaluation noise (~1e-10) stays ~1e-6.
constexpr double slope_step = 1e-4;
constexpr std::size_t max_nodes = 200000;

// Cubic Hermite on [x0, x1].
double hermite(double x0, double f0, double d0, double x1, double f1, double d1, double x) {
  const double h = x1 - x0, t = (x - x0) / h, t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * f0 + (t3 - 2 * t2 + t) * h * d0 + (-2 * t3 + 3 * t2) * f1 + (t3 - t2) * h * d1;
}

}  // namespace

// --- PiecewiseCubic ----------------------------------------------------------------

double PiecewiseCubic::in_piece(long want, double at) const {
  // The interval of this piece that contains `at`, or its first/last interval.
  long first = -1, last = -1;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (label[i] != want) continue;
    if (first < 0) first = static_cast<long>(i);
    last = static_cast<long>(i);
  }
  if (first < 0) throw NumericalError(fmt::format("table: no piece labelled {}", want));
  if (first == last) return f[static_cast<std::size_t>(first)] + slope[static_cast<std::size_t>(first)] * (at - x[static_cast<std::size_t>(first)]);
  auto i = static_cast<std::size_t>(first);
  while (i + 2 <= static_cast<std::size_t>(last) && at > x[i + 1]) ++i;
  return hermite(x[i], f[i], slope[i], x[i + 1], f[i + 1], slope[i + 1], at);
}

long PiecewiseCubic::label_at(double at) const {
  if (x.empty()) throw NumericalError("table: empty curve");
  const auto it = std::upper_bound(x.begin(), x.end(), at);
  if (it == x.begin()) return label.front();
  if (it == x.end()) return label.back();
  const auto i = static_cast<std::size_t>(it - x.begin()) - 1;
  if (label[i] == label[i + 1]) return label[i];
  return at < 0.5 * (x[i] + x[i + 1]) ? label[i] : label[i + 1];  // inside a jump's bracket
}

double PiecewiseCubic::operator()(double at) const {
  const auto it = std::upper_bound(x.begin(), x.end(), at);
  const std::size_t n = x.size();
  std::size_t i = it == x.begin() ? 0 : static_cast<std::size_t>(it - x.begin()) - 1;
  if (i + 1 >= n) i = n - 2;
  if (label[i] == label[i + 1]) return hermite(x[i], f[i], slope[i], x[i + 1], f[i + 1], slope[i + 1], at);
  return in_piece(label_at(at), at);
}

namespace {

// --- building a PiecewiseCubic -----------------------------------------------------

struct Sample {
  double value;
  long label;
};
using Function = std::function<Sample(double)>;

class CurveBuilder {
 public:
  CurveBuilder(Function f, double bound, const std::function<void()>& tick) : f_(std::move(f)), bound_(bound), tick_(tick) {}

  PiecewiseCubic build(double lo, double hi, int initial) {
    std::map<double, Sample> nodes;
    auto add = [&](double at) {
      if (!nodes.count(at)) nodes.emplace(at, eval(at));
    };
    for (int i = 0; i <= initial; ++i) add(lo + (hi - lo) * i / initial);
    // Locate every jump between neighbours to jump_width.
    for (bool again = true; again;) {
      again = false;
      for (auto it = nodes.begin(); std::next(it) != nodes.end(); ++it) {
        auto next = std::next(it);
        if (it->second.label == next->second.label || next->first - it->first <= jump_width) continue;
        double a = it->first, b = next->first;
        const long left = it->second.label;
        Sample sb = next->second;
        while (b - a > jump_width) {
          const double mid = 0.5 * (a + b);
          const Sample s = eval(mid);
          if (s.label == left) {
            a = mid;
          } else {
            b = mid;
            sb = s;
          }
        }
        nodes.emplace(a, eval(a));
        nodes.emplace(b, sb);
        again = true;
        break;
      }
      if (nodes.size() > max_nodes) throw NumericalError("table: too many jumps to locate");
    }
    // Slopes, then refinement of every interval inside a piece.
    std::map<double, double> slopes;
    for (const auto& [at, s] : nodes) slopes[at] = slope(at, s, lo, hi);
    std::deque<std::pair<double, double>> queue;
    for (auto it = nodes.begin(); std::next(it) != nodes.end(); ++it) {
      auto next = std::next(it);
      if (it->second.label == next->second.label) queue.emplace_back(it->first, next->first);
    }
    while (!queue.empty()) {
      const auto [a, b] = queue.front();
      queue.pop_front();
      if (b - a <= 2 * jump_width) continue;
      const double mid = 0.5 * (a + b);
      const Sample s = eval(mid);
      const Sample& sa = nodes.at(a);
      if (s.label != sa.label) {  // a jump the first grid missed: locate it, refine both sides
        double lo_a = a, hi_b = mid;
        Sample shi = s;
        while (hi_b - lo_a > jump_width) {
          const double m = 0.5 * (lo_a + hi_b);
          const Sample sm = eval(m);
          if (sm.label == sa.label) {
            lo_a = m;
          } else {
            hi_b = m;
            shi = sm;
          }
        }
        for (auto [at, smp] : {std::pair{lo_a, eval(lo_a)}, std::pair{hi_b, shi}, std::pair{mid, s}}) {
          if (nodes.emplace(at, smp).second) slopes[at] = slope(at, smp, lo, hi);
        }
        queue.emplace_back(a, lo_a);
        queue.emplace_back(hi_b, mid);
        queue.emplace_back(mid, b);
        continue;
      }
      const double guess = hermite(a, sa.value, slopes.at(a), b, nodes.at(b).value, slopes.at(b), mid);
      if (std::abs(guess - s.value) > 0.25 * bound_) {
        nodes.emplace(mid, s);
        slopes[mid] = slope(mid, s, lo, hi);
        queue.emplace_back(a, mid);
        queue.emplace_back(mid, b);
      }
      if (nodes.size() > max_nodes) throw NumericalError("table: the refinement does not converge (max nodes)");
    }
    PiecewiseCubic c;
    for (const auto& [at, s] : nodes) {
      c.x.push_back(at);
      c.f.push_back(s.value);
      c.slope.push_back(slopes.at(at));
      c.label.push_back(s.label);
    }
    return c;
  }

  Sample eval(double at) {
    if (tick_) tick_();
    return f_(at);
  }

 private:
  // A second-order difference inside the node's piece.
  double slope(double at, const Sample& s, double lo, double hi) {
    const double h = slope_step;
    const bool left_ok = at - h >= lo - 1e-12, right_ok = at + h <= hi + 1e-12;
    Sample plus{0, 0}, minus{0, 0};
    if (left_ok) minus = eval(at - h);
    if (right_ok) plus = eval(at + h);
    const bool left = left_ok && minus.label == s.label, right = right_ok && plus.label == s.label;
    if (left && right) return (plus.value - minus.value) / (2 * h);
    if (right) {
      const Sample plus2 = eval(at + 2 * h);
      return (-3 * s.value + 4 * plus.value - plus2.value) / (2 * h);
    }
    if (left) {
      const Sample minus2 = eval(at - 2 * h);
      return (3 * s.value - 4 * minus.value + minus2.value) / (2 * h);
    }
    return 0.0;  // a one-node piece (a jump bracket too narrow to differentiate)
  }

  Function f_;
  double bound_;
  std::function<void()> tick_;
};

nlohmann::json curve_json(const PiecewiseCubic& c) {
  nlohmann::json nodes = nlohmann::json::array();
  for (std::size_t i = 0; i < c.x.size(); ++i) nodes.push_back({c.x[i], c.f[i], c.slope[i], c.label[i]});
  return nodes;
}

PiecewiseCubic curve_from_json(const nlohmann::json& nodes) {
  PiecewiseCubic c;
  for (const auto& n : nodes) {
    c.x.push_back(n.at(0).get<double>());
    c.f.push_back(n.at(1).get<double>());
    c.slope.push_back(n.at(2).get<double>());
    c.label.push_back(n.at(3).get<long>());
  }
  if (c.x.size() < 2) throw InvalidArgument("table", "(fewer than 2 nodes)", "a table written by bounce table");
  return c;
}

// The C version of PiecewiseCubic (the same algorithm as above).
constexpr const char* c_piecewise = R"(
static double PREFIX_hermite(double x0, double f0, double d0, double x1, double f1, double d1, double x) {
  double h = x1 - x0, t = (x - x0) / h, t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * f0 + (t3 - 2 * t2 + t) * h * d0 + (-2 * t3 + 3 * t2) * f1 + (t3 - t2) * h * d1;
}
/* The value of the piece labelled `want` at x (extrapolated beyond its ends). */
static double PREFIX_in_piece(const double* x, const double* f, const double* d, const double* label, long n,
                              double want, double at) {
  long first = -1, last = -1, i;
  for (i = 0; i < n; ++i) {
    if (label[i] != want) continue;
    if (first < 0) first = i;
    last = i;
  }
  if (first < 0) return 0.0 / 0.0;
  if (first == last) return f[first] + d[first] * (at - x[first]);
  i = first;
  while (i + 2 <= last && at > x[i + 1]) ++i;
  return PREFIX_hermite(x[i], f[i], d[i], x[i + 1], f[i + 1], d[i + 1], at);
}
static double PREFIX_label_at(const double* x, const double* label, long n, double at) {
  long lo = 0, hi = n - 1;
  if (at <= x[0]) return label[0];
  if (at >= x[n - 1]) return label[n - 1];
  while (hi - lo > 1) {
    long mid = (lo + hi) / 2;
    if (x[mid] <= at) lo = mid; else hi = mid;
  }
  if (label[lo] == label[lo + 1]) return label[lo];
  return at < 0.5 * (x[lo] + x[lo + 1]) ? label[lo] : label[lo + 1];
}
static double PREFIX_curve(const double* x, const double* f, const double* d, const double* label, long n, double at) {
  long lo = 0, hi = n - 1;
  if (at > x[0] && at < x[n - 1]) {
    while (hi - lo > 1) {
      long mid = (lo + hi) / 2;
      if (x[mid] <= at) lo = mid; else hi = mid;
    }
  } else if (at >= x[n - 1]) {
    lo = n - 2;
  }
  if (label[lo] == label[lo + 1]) return PREFIX_hermite(x[lo], f[lo], d[lo], x[lo + 1], f[lo + 1], d[lo + 1], at);
  return PREFIX_in_piece(x, f, d, label, n, PREFIX_label_at(x, label, n, at), at);
}
)";

}  // namespace

// --- eps^N ---------------------------------------------------------------------------

double NormalTable::cor(double g) const {
  require_finite("velocity", g);
  if (g < g_min * (1 - 1e-12) || g > g_max * (1 + 1e-12)) {
    throw InvalidArgument("velocity", fmt::format("{:g}", g), fmt::format("{:g} <= g <= {:g} m/s (the table's range)", g_min, g_max));
  }
  if (sticking_velocity > 0.0 && g <= sticking_velocity) return 0.0;
  const double offset = sticking_velocity > 0.0 ? g - sticking_velocity : g;
  const double x = std::log(offset);
  if (x < curve.x.front()) {  // closer to v_s than the first node: eps^N ~ sqrt(g - v_s)
    return curve.f.front() * std::sqrt(offset / std::exp(curve.x.front()));
  }
  return curve(x);
}

dynamics::Outcome NormalTable::outcome(double g) const {
  if (sticking_velocity > 0.0 && g <= sticking_velocity) return dynamics::Outcome::stick;
  const double offset = sticking_velocity > 0.0 ? g - sticking_velocity : g;
  const double x = std::max(std::log(offset), curve.x.front());
  return curve.label_at(x) == 0 ? dynamics::Outcome::stick : dynamics::Outcome::bounce;
}

NormalTable build_normal_table(const Pair& pair, const models::ModelSpec& model, double g_min, double g_max,
                               const CollideOptions& options, const TableOptions& table) {
  check_range("velocity", g_min, g_max);
  require_positive("bound", table.bound, "an interpolation error bound > 0");
  NormalTable t;
  t.description = describe(pair, model);
  t.g_min = g_min;
  t.g_max = g_max;
  t.bound = table.bound;
  if (models::model_info(model.name).adhesive) {
    CollideOptions o = options;
    const StickingVelocity v = sticking_velocity(pair, model, o, 1e-13);
    if (v.upper > g_min) t.sticking_velocity = v.upper;  // the smallest speed found to bounce
  }
  std::size_t done = 0;
  const std::size_t estimate = 2000;
  auto tick = [&] {
    if (table.progress && ++done % 50 == 0) table.progress(done, std::max(estimate, done + 1));
  };
  const double vs = t.sticking_velocity;
  Function f = [&](double x) {
    const double g = vs > 0.0 ? vs + std::exp(x) : std::exp(x);
    const auto out = collide(pair, model, g, options);
    return Sample{out.cor, out.outcome == dynamics::Outcome::bounce ? 1L : 0L};
  };
  // With sticking: from 1e-12 v_s above the threshold (eps^N ~ 1e-6 there) up to g_max.
  const double lo = vs > 0.0 ? std::log(1e-12 * vs) : std::log(g_min);
  const double hi = std::log(g_max - vs);
  CurveBuilder builder(f, table.bound, tick);
  t.curve = builder.build(lo, hi, std::max(8, static_cast<int>(std::ceil(2.0 * (hi - lo)))));
  if (table.progress) table.progress(done, done);
  return t;
}

std::string NormalTable::to_json() const {
  nlohmann::json j;
  j["kind"] = "bounce normal restitution table";
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
    if (j.at("kind") != "bounce normal restitution table") throw InvalidArgument("table", "kind", "a normal table");
    NormalTable t;
    t.description = j.at("description").get<std::string>();
    t.g_min = j.at("g_min").get<double>();
    t.g_max = j.at("g_max").get<double>();
    t.sticking_velocity = j.at("sticking_velocity").get<double>();
    t.bound = j.at("bound").get<double>();
    t.curve = curve_from_json(j.at("nodes"));
    return t;
  } catch (const nlohmann::json::exception& e) {
    throw InvalidArgument("table", "(malformed)", fmt::format("a table written by bounce table ({})", e.what()));
  }
}

std::string NormalTable::to_csv() const {
  std::string s = "velocity,x,cor,slope,outcome\n";
  for (std::size_t i = 0; i < curve.x.size(); ++i) {
    const double g = (sticking_velocity > 0.0 ? sticking_velocity : 0.0) + std::exp(curve.x[i]);
    s += fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{}\n", g, curve.x[i], curve.f[i], curve.slope[i],
                     curve.label[i] ? "bounce" : "stick");
  }
  return s;
}

std::string NormalTable::to_c_header(const std::string& prefix) const {
  check_prefix(prefix);
  std::vector<double> labels(curve.label.begin(), curve.label.end());
  std::string s = fmt::format(
      "/* eps^N(g) written by bounce table: {}.\n"
      " * g in [{:g}, {:g}] m/s; below the sticking velocity {:.17g} m/s the grains stick (eps^N = 0).\n"
      " * Interpolation error <= {:g}. Self-contained C99: include it once per program. */\n"
      "#ifndef {}_H\n#define {}_H\n#include <math.h>\n",
      description, g_min, g_max, sticking_velocity, bound, prefix, prefix);
  s += fmt::format("static const double {}_g_min = {:.17g}, {}_g_max = {:.17g}, {}_sticking_velocity = {:.17g};\n",
                   prefix, g_min, prefix, g_max, prefix, sticking_velocity);
  s += fmt::format("static const long {}_n = {};\n", prefix, curve.x.size());
  s += c_array("double", prefix + "_x", curve.x) + c_array("double", prefix + "_f", curve.f) +
       c_array("double", prefix + "_d", curve.slope) + c_array("double", prefix + "_label", labels);
  s += with_prefix(c_piecewise, prefix);
  s += with_prefix(R"(
/* 1 if grains meeting at g [m/s] stick. */
static int PREFIX_sticks(double g) {
  double offset = PREFIX_sticking_velocity > 0 ? g - PREFIX_sticking_velocity : g;
  double x;
  if (PREFIX_sticking_velocity > 0 && g <= PREFIX_sticking_velocity) return 1;
  x = log(offset);
  if (x < PREFIX_x[0]) x = PREFIX_x[0];
  return PREFIX_label_at(PREFIX_x, PREFIX_label, PREFIX_n, x) == 0;
}
/* eps^N at g [m/s]; NaN outside [g_min, g_max]. */
static double PREFIX_cor(double g) {
  double offset, x;
  if (!(g >= PREFIX_g_min * (1 - 1e-12) && g <= PREFIX_g_max * (1 + 1e-12))) return 0.0 / 0.0;
  if (PREFIX_sticking_velocity > 0 && g <= PREFIX_sticking_velocity) return 0.0;
  offset = PREFIX_sticking_velocity > 0 ? g - PREFIX_sticking_velocity : g;
  x = log(offset);
  if (x < PREFIX_x[0]) return PREFIX_f[0] * sqrt(offset / exp(PREFIX_x[0]));
  return PREFIX_curve(PREFIX_x, PREFIX_f, PREFIX_d, PREFIX_label, PREFIX_n, x);
}
#endif
)",
                   prefix);
  return s;
}

}  // namespace bounce
