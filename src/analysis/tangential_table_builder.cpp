// Building eps^T(g^N, g^T) tables (docs/tables.md): rows of the contact's fundamental
// solutions, refined (nodes per row, then rows) until the lookup agrees with direct
// integration at random check points.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <fmt/format.h>

#include "bounce/analysis/collide.hpp"
#include "bounce/analysis/tables.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/dynamics/normal_collision.hpp"
#include "bounce/dynamics/tangential.hpp"
#include "table_common.hpp"
#include "tangential_core.hpp"

namespace bounce::analysis {

namespace {

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

// A random (g^N, g^T) with eps^T from direct integration.
struct CheckPoint {
  double gn, gt, direct;
};

// The checks of build_tangential_table: a non-adhesive force law with the published
// asperity law, and g^T below where the direct integration averages dense breaks.
const models::TangentialModel& tabulable(const models::Model& model, double gn_min, double gn_max, double gt_max) {
  if (!model.force_law() || model.traits.adhesive) {
    throw InvalidArgument("model", model.name,
                          "a non-adhesive force-law model for an eps^T table (hertz, viscoelastic, "
                          "viscoelastic-shifted, power-law; docs/tables.md)");
  }
  if (!model.tangential) {
    throw InvalidArgument("friction", "(not given)", "a friction coefficient mu >= 0 (BSHP96 (36))");
  }
  const models::TangentialModel& tangential = *model.tangential;
  if (tangential.law != models::TangentialLaw::asperity) {
    throw InvalidArgument("tangential_law", std::string(models::to_string(tangential.law)),
                          "asperity for an eps^T table (the step law is not tabulated; docs/tables.md)");
  }
  // The default form is passive (D12): a table of the default is refused with what to type.
  if (tangential.form != models::AsperityForm::published) {
    throw InvalidArgument("asperity_form", std::string(models::to_string(tangential.form)),
                          "published for an eps^T table (a table holds BSHP96's published asperity form only; "
                          "passive, the default, is not tabulated): add --asperity-form published "
                          "(Python: asperity_form=\"published\"; docs/tables.md, Limits)");
  }
  // The direct integration averages the sawtooth where asperities break more than
  // dense_breaks times per time unit; the table resolves every break, so its range must
  // stay clear of that (with a factor 2 for speeds above g^T, published form).
  for (const double gn : {gn_min, gn_max}) {
    const double time_unit = model.force_law()->reference_overlap(gn) / gn;
    const double limit = 0.5 * tangential.dense_breaks * tangential.asperity_size / time_unit;
    if (gt_max > limit) {
      throw InvalidArgument("tangential_velocity_max", fmt::format("{:g}", gt_max),
                            fmt::format("<= {:.3g} m/s: faster, asperities break so densely at g^N = {:g} m/s that "
                                        "the direct integration averages them (docs/tangential.md)",
                                        limit, gn));
    }
  }
  return tangential;
}

class Builder {
 public:
  Builder(const Pair& pair, const models::Model& model, const CollideOptions& options, const TableOptions& table)
      : pair_(pair), model_(model), options_(options), table_(table) {}

  TangentialTable build(double gn_min, double gn_max, double gt_min, double gt_max);

 private:
  void fill();
  void fill_row(std::size_t r);
  double direct_cor(double gn, double gt);
  double worst(const std::vector<CheckPoint>& points) const;
  double random_gt() { return t_.gt_min * std::pow(t_.gt_max / t_.gt_min, unit_(random_)); }
  void refine_nodes(const std::vector<CheckPoint>& on_rows);
  void refine_rows(const std::vector<CheckPoint>& between);
  void tick() {
    if (table_.progress && ++done_ % 50 == 0) table_.progress(done_, 0);  // adaptive: no total known
  }

  const Pair& pair_;
  const models::Model& model_;
  CollideOptions options_;
  const TableOptions& table_;
  TangentialTable t_;
  detail::WarningLog warnings_;
  double span_ = 0.0;
  std::size_t rows_ = 0;
  int nodes_ = first_nodes;
  std::size_t done_ = 0;
  std::mt19937_64 random_{20261123};
  std::uniform_real_distribution<double> unit_{0.0, 1.0};
};

// One row: the node values y1, y1', y2, y2', K, dK/ds at s - ds, s, s + ds (within [0, 1]:
// the dense output cannot repeat a time) of every node s = sqrt(tau / tau_end); tau_end is
// where F^N returns to 0 after the compression (beyond it F^T = 0: asperities carry no
// shear in tension), whatever rule ends the contact.
void Builder::fill_row(std::size_t r) {
  const models::NormalForceModel& force = *model_.force_law();
  const double mass = pair_.effective_mass(), gn = std::exp(t_.x0 + static_cast<double>(r) * t_.dx);
  const double time_unit = force.reference_overlap(gn) / gn;
  dynamics::NormalCollisionOptions o;
  o.end_rule = models::EndRule::force;
  o.integration.relative_tolerance = o.integration.absolute_tolerance = 1e-13;
  const double tau_end = dynamics::integrate_normal_collision(force, mass, gn, o).contact_time / time_unit;
  std::vector<double> at, times;
  std::vector<std::array<std::size_t, 3>> index;  // per node: left, own, right point in `at`
  for (const double sj : t_.s) {
    std::array<std::size_t, 3> k{};
    if (sj - derivative_step >= 0.0) at.push_back(sj - derivative_step);
    k[0] = at.size() - (sj - derivative_step >= 0.0 ? 1 : 0);
    k[1] = at.size();
    at.push_back(sj);
    if (sj + derivative_step <= 1.0) at.push_back(sj + derivative_step);
    k[2] = at.size() - 1;
    index.push_back(k);
  }
  for (const double a : at) times.push_back(tau_end * a * a);
  const auto y = dynamics::fundamental_solutions(force, mass, gn, *model_.tangential, times, node_tolerance);
  t_.rows[r * detail::tt_row_values] = tau_end;
  t_.rows[r * detail::tt_row_values + 1] = std::log(time_unit);
  double* node = t_.nodes.data() + r * t_.s.size() * detail::tt_node_values;
  for (std::size_t j = 0; j < t_.s.size(); ++j) {
    const auto [lo, own, hi] = index[j];
    const dynamics::FundamentalSample& c = y[own];
    const double values[detail::tt_node_values] = {c.y1, c.dy1, c.y2, c.dy2, c.stiffness,
                                                   (y[hi].stiffness - y[lo].stiffness) / (at[hi] - at[lo])};
    std::copy(values, values + detail::tt_node_values, node + j * detail::tt_node_values);
  }
}

void Builder::fill() {
  t_.s.resize(static_cast<std::size_t>(nodes_));
  for (int j = 0; j < nodes_; ++j) t_.s[static_cast<std::size_t>(j)] = static_cast<double>(j) / (nodes_ - 1);
  t_.dx = span_ / static_cast<double>(rows_ - 1);
  t_.rows.assign(rows_ * detail::tt_row_values, 0.0);
  t_.nodes.assign(rows_ * t_.s.size() * detail::tt_node_values, 0.0);
  for (std::size_t r = 0; r < rows_; ++r) {
    fill_row(r);
    tick();
  }
}

double Builder::direct_cor(double gn, double gt) {
  options_.tangential_velocity = gt;
  const auto out = collide(pair_, model_, gn, options_);
  warnings_.add(gn, out.warnings);
  tick();
  return out.tangential->cor;
}

double Builder::worst(const std::vector<CheckPoint>& points) const {
  const detail::tt_table v = detail::view(t_);
  double e = 0.0;
  for (const auto& p : points) {
    const double value = detail::tt_cor(&v, p.gn, p.gt, nullptr);
    e = std::isfinite(value) ? std::max(e, std::abs(value - p.direct)) : HUGE_VAL;
  }
  return e;
}

// Nodes per row, checked on the rows themselves (no interpolation across rows there).
void Builder::refine_nodes(const std::vector<CheckPoint>& on_rows) {
  for (fill(); worst(on_rows) > table_.bound / 8;) {
    if (nodes_ >= max_nodes) {
      throw NumericalError(
          fmt::format("tangential table: {} nodes per row do not reach {:g} at the rows", nodes_, table_.bound / 8));
    }
    nodes_ = 2 * nodes_ - 1;
    fill();
  }
}

// Rows, checked at random points between them.
void Builder::refine_rows(const std::vector<CheckPoint>& between) {
  for (double e = worst(between);; e = worst(between)) {
    t_.checked_error = e;
    if (e <= table_.bound / 4) break;
    if (rows_ >= max_rows) {
      throw NumericalError(
          fmt::format("tangential table: {} rows do not reach {:g} between the rows", rows_, table_.bound / 4));
    }
    rows_ = 2 * rows_ - 1;
    fill();
  }
}

TangentialTable Builder::build(double gn_min, double gn_max, double gt_min, double gt_max) {
  const models::TangentialModel& tangential = *model_.tangential;
  t_.description = detail::describe(pair_, model_) +
                   fmt::format(", asperity law (published), mu = {:g}, zeta0 = {:g} m, kappa = {:g}",
                               tangential.friction, tangential.asperity_size, tangential.kappa);
  t_.gn_min = gn_min;
  t_.gn_max = gn_max;
  t_.gt_min = gt_min;
  t_.gt_max = gt_max;
  t_.bound = table_.bound;
  t_.asperity_size = tangential.asperity_size;
  t_.order = stencil;
  t_.x0 = std::log(gn_min);
  span_ = std::log(gn_max) - t_.x0;
  rows_ = std::max<std::size_t>(stencil, static_cast<std::size_t>(std::ceil(span_ / first_row_step)) + 1);
  options_.method = Method::integrate;
  options_.record_trajectory = false;
  std::vector<CheckPoint> on_rows, between;
  for (int i = 0; i < 100; ++i) {
    const double x =
        t_.x0 + span_ * std::floor(unit_(random_) * static_cast<double>(rows_)) / static_cast<double>(rows_ - 1);
    const double gn = std::exp(std::min(x, t_.x0 + span_)), gt = random_gt();
    on_rows.push_back({gn, gt, direct_cor(gn, gt)});
  }
  refine_nodes(on_rows);
  for (int i = 0; i < 400; ++i) {
    const double gn = gn_min * std::pow(gn_max / gn_min, unit_(random_)), gt = random_gt();
    between.push_back({gn, gt, direct_cor(gn, gt)});
  }
  refine_rows(between);
  // Refused only for a TangentialModel with dense_breaks far above its default.
  detail::require_bounded_lookups(t_, "tangential_velocity_max", fmt::format("{:g}", gt_max), "");
  t_.checked_error = std::max(t_.checked_error, worst(on_rows));
  t_.check_points = static_cast<long>(on_rows.size() + between.size());
  t_.warnings = warnings_.list();
  if (table_.progress) table_.progress(done_, done_);
  return t_;
}

}  // namespace

TangentialTable build_tangential_table(const Pair& pair, const models::Model& model, double gn_min, double gn_max,
                                       double gt_min, double gt_max, const CollideOptions& options,
                                       const TableOptions& table) {
  detail::check_range("velocity", gn_min, gn_max);
  detail::check_range("tangential_velocity", gt_min, gt_max);
  require_positive("bound", table.bound, "an interpolation error bound");
  tabulable(model, gn_min, gn_max, gt_max);
  return Builder(pair, model, options, table).build(gn_min, gn_max, gt_min, gt_max);
}

}  // namespace bounce::analysis
