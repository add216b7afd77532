#include "bounce/dynamics/outcome.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "bounce/core/error.hpp"

namespace bounce::dynamics {

void EnergyBudget::close() {
  closure_error = initial_kinetic - final_kinetic - bulk_dissipated - crack_dissipated - plastic_dissipated -
                  elastic_remaining - surface_remaining;
}

std::vector<std::pair<std::string, double>> named_values(const EnergyBudget& e) {
  return {{"initial_kinetic", e.initial_kinetic},     {"final_kinetic", e.final_kinetic},
          {"bulk_dissipated", e.bulk_dissipated},     {"crack_dissipated", e.crack_dissipated},
          {"plastic_dissipated", e.plastic_dissipated}, {"elastic_remaining", e.elastic_remaining},
          {"surface_remaining", e.surface_remaining}, {"closure_error", e.closure_error}};
}

std::vector<std::pair<std::string, double>> named_values(const TangentialOutcome& t) {
  return {{"cor", t.cor},
          {"initial_kinetic", t.initial_kinetic},
          {"final_kinetic", t.final_kinetic},
          {"asperity_dissipated", t.asperity_dissipated},
          {"stored_at_end", t.stored_at_end},
          {"stiffness_work", t.stiffness_work},
          {"averaged_time", t.averaged_time}};
}

namespace {

// Keeps the first row and each row at least `spacing` after the last one kept.
void keep_spaced(std::vector<TrajectorySample>& rows, double spacing) {
  std::size_t kept = 1;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    if (rows[i].time - rows[kept - 1].time >= spacing) rows[kept++] = rows[i];
  }
  rows.resize(kept);
}

// At most half of max_rows left: the least spacing doubled from what the span asks for until
// the rows fit. Rows all at one time (no span to thin) lose every other one instead.
void thin_rows(std::vector<TrajectorySample>& rows, double& thinning, std::size_t max_rows) {
  const std::size_t target = std::max<std::size_t>(max_rows / 2, 2);
  if (rows.size() <= target) return;
  const double span = rows.back().time - rows.front().time;
  double spacing = std::max(thinning, span / static_cast<double>(target));
  if (!(spacing > 0.0) || !std::isfinite(spacing)) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < rows.size(); i += 2) rows[kept++] = rows[i];
    rows.resize(kept);
    return;
  }
  for (keep_spaced(rows, spacing); rows.size() > target; keep_spaced(rows, spacing)) spacing *= 2.0;
  thinning = spacing;
}

}  // namespace

TrajectoryRecorder::TrajectoryRecorder(std::vector<TrajectorySample>& rows, double& thinning, std::size_t max_rows)
    : rows_(&rows), thinning_(&thinning), max_rows_(std::max<std::size_t>(max_rows, 4)) {}

void TrajectoryRecorder::add(const TrajectorySample& sample) {
  std::vector<TrajectorySample>& rows = *rows_;
  if (!rows.empty() && *thinning_ > 0.0 && sample.time - rows.back().time < *thinning_) return;
  rows.push_back(sample);
  if (rows.size() >= max_rows_) thin();
}

void TrajectoryRecorder::add_end(const TrajectorySample& sample) {
  if (rows_->size() >= max_rows_) thin();
  rows_->push_back(sample);
}

double TrajectoryRecorder::step(double wanted, double time_unit) const {
  return std::max(wanted, *thinning_ / time_unit);
}

void TrajectoryRecorder::thin() { thin_rows(*rows_, *thinning_, max_rows_); }

void limit_trajectory(std::vector<TrajectorySample>& rows, double& thinning, std::size_t max_rows) {
  if (rows.size() <= max_rows) return;
  const TrajectorySample last = rows.back();
  rows.pop_back();
  thin_rows(rows, thinning, max_rows);
  rows.push_back(last);
}

std::string_view to_string(Outcome outcome) {
  return outcome == Outcome::bounce ? "bounce" : "stick";
}

}  // namespace bounce::dynamics
