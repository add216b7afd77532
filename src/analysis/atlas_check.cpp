// The atlas build's held-out checks and its rounds of refinement (docs/atlas.md, "Error control").
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <fmt/format.h>

#include "atlas_checks.hpp"
#include "bounce/analysis/sticking.hpp"
#include "bounce/core/error.hpp"

namespace bounce::analysis::detail {

namespace {

// Held-out points per round, by kind: on the nodes (z alone), on rows of y nodes (x and z), on
// columns of x nodes (y and z, with two at the middle of every y cell), anywhere, and at the
// centre of every x cell (its sticking velocity and one collision); sticking velocities are
// bisections.
constexpr int z_points = 100, x_points = 150, y_points = 150, full_points = 600;
constexpr int threshold_points = 12;
constexpr int max_level_y = 4, max_level_z = 4;
constexpr std::size_t max_x_nodes = 8192;

}  // namespace

// |eps_atlas - eps_collide| at one point (0 where both stick); an outcome that differs counts
// as the relative distance to the interpolated v_s, in `band`.
double AtlasBuild::check_collision(const Atlas& a, const std::array<double, 2>& radii, double v, double& band,
                                   AtlasCheck& c) {
  const AtlasCollision direct = collision(radii, v);
  const AtlasValue got = a.at({radii[0], radii[1], v});
  ++c.points;
  if (got.sticks != direct.sticks) {
    band = std::isfinite(got.v_stick) ? std::abs(v / got.v_stick - 1.0) : 1.0;
    return 0.0;
  }
  if (direct.sticks) return 0.0;
  c.contact_time = std::max(c.contact_time, std::abs(*got.contact_time / direct.contact_time - 1.0));
  c.energy = std::max({c.energy, std::abs(*got.bulk_fraction - direct.bulk_fraction),
                       std::abs(*got.crack_fraction - direct.crack_fraction)});
  return std::abs(got.cor - direct.cor);
}

// The relative error of v_s; inside the table's speeds only: above them the atlas need only
// say that the grains stick at all of them (docs/atlas.md).
double AtlasBuild::check_threshold(const Atlas& a, const std::array<double, 2>& radii) {
  const AtlasThreshold direct = threshold(radii);
  const double got = a.v_stick(radii[0], radii[1]);
  const double v_max = request_.velocity_max;
  if (!direct.defined || direct.velocity > v_max) {
    return got < v_max ? (direct.defined ? std::abs(got / direct.velocity - 1.0) : 1.0) : 0.0;
  }
  return std::isinf(got) ? 1.0 : std::abs(got / direct.velocity - 1.0);
}

std::vector<Probe> AtlasBuild::probes(const Atlas& a, int round) const {
  std::mt19937_64 rng(0x61746c6173ULL + static_cast<unsigned>(round));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double lx = std::log(request_.radius_min), hx = std::log(request_.radius_max);
  const double lv = std::log(request_.velocity_min), hv = std::log(request_.velocity_max);
  const auto node_of = [&](const AtlasAxis& axis) {
    std::uniform_int_distribution<std::size_t> pick(0, axis.count - 1);
    return axis.value(pick(rng));
  };
  const auto random_x = [&] { return lx + (hx - lx) * unit(rng); };
  const auto random_y = [&] { return a.y.start + (a.y.end() - a.y.start) * unit(rng); };
  const auto node_x = [&] { return node_of(a.x); };
  const auto node_y = [&] { return node_of(a.y); };
  std::vector<Probe> out;
  const auto add = [&](Kind kind, double x, double y, bool speed) {
    const double v = speed ? std::exp(lv + (hv - lv) * unit(rng)) : 0.0;
    out.push_back({radii_for(std::exp(x), std::clamp(std::exp(y), density_[0], density_[1]), m1_.density, m2_.density),
                   v, kind, x});
  };
  for (const bool speed : {true, false}) {
    if (!speed && !can_stick_) break;
    const int scale = speed ? 1 : 0;
    for (int i = 0; i < (speed ? z_points : 0); ++i) add(on_nodes, node_x(), node_y(), true);
    for (int i = 0; i < scale * x_points + (1 - scale) * threshold_points; ++i) add(x_kind, random_x(), node_y(), speed);
    for (int i = 0; i < scale * y_points + (1 - scale) * threshold_points; ++i) add(y_kind, node_x(), random_y(), speed);
    for (int i = 0; i < scale * full_points + (1 - scale) * threshold_points; ++i) add(anywhere, random_x(), random_y(), speed);
    // Every x cell at the centre of a y cell: where the tensor cubic errs most (x's error and y's
    // add there; on a row of y nodes y's vanishes).
    for (std::size_t i = 0; i + 1 < a.x.count; ++i) {
      const std::size_t j = (i * 7 + static_cast<std::size_t>(round)) % (a.y.count - 1);
      add(x_middle, 0.5 * (a.x.value(i) + a.x.value(i + 1)), 0.5 * (a.y.value(j) + a.y.value(j + 1)), speed);
    }
    for (std::size_t j = 0; j + 1 < a.y.count; ++j) {  // y's worst places, at x nodes (denser where x needed it)
      for (int k = 0; k < 2; ++k) add(y_kind, node_x(), 0.5 * (a.y.value(j) + a.y.value(j + 1)), speed);
    }
  }
  return out;
}

AtlasCheck AtlasBuild::check(const Atlas& a, int round) {
  const std::vector<Probe> all = probes(a, round);
  run_jobs(all.size(), [&](std::size_t i) {
    if (all[i].v > 0.0) collision(all[i].radii, all[i].v);
    else threshold(all[i].radii);
  });
  AtlasCheck c;
  std::vector<std::pair<double, double>> eps_x, vs_x;  // (ln R, error) of the points x may explain
  for (const Probe& p : all) {
    if (p.v > 0.0) {
      double band = 0.0;
      const double e = check_collision(a, p.radii, p.v, band, c);
      double& worst = p.kind == on_nodes ? c.z : p.kind == y_kind ? c.y : p.kind == anywhere ? c.full : c.x;
      worst = std::max(worst, e);
      c.vs_full = std::max(c.vs_full, band);
      if (p.kind != on_nodes && p.kind != y_kind) eps_x.emplace_back(p.ln_r, e);
      if (band > 0.0) vs_x.emplace_back(p.ln_r, band);
    } else {
      const double e = check_threshold(a, p.radii);
      ++c.thresholds;
      double& worst = p.kind == y_kind ? c.vs_y : p.kind == anywhere ? c.vs_full : c.vs_x;
      worst = std::max(worst, e);
      if (p.kind != y_kind) vs_x.emplace_back(p.ln_r, e);
    }
  }
  // x cells to split: where a point fails by more than z's and y's errors explain.
  const double target = request_.tolerance / 2.0;
  for (const auto& [ln_r, e] : eps_x) {
    if (e > target / 2.0 && e > 2.0 * std::max(c.z, c.y)) c.x_failing.push_back(ln_r);
  }
  for (const auto& [ln_r, e] : vs_x) {
    if (e > v_stick_target && e > 2.0 * c.vs_y) c.x_failing.push_back(ln_r);
  }
  return c;
}

// What to refine (false: done): z and y as a whole, x where its points fail. The eps target is
// tolerance / 2 (the stated bound is twice the largest error found), v_s's v_stick_target.
bool AtlasBuild::refine(AtlasLevels& levels, const AtlasCheck& c) const {
  const double target = request_.tolerance / 2.0;
  const bool rz = c.z > target / 2.0;
  const bool ry = (c.y > target / 2.0 && c.y > 2.0 * c.z) || c.vs_y > v_stick_target;
  const bool failing = c.cor() > target || c.v_stick() > v_stick_target;
  if (!failing && !rz && !ry && c.x_failing.empty()) return false;
  std::vector<std::size_t> cells;
  const AtlasAxis x = base_.x_at(levels);
  for (double ln_r : c.x_failing) {
    const auto above = std::upper_bound(x.nodes.begin(), x.nodes.end(), ln_r);
    cells.push_back(static_cast<std::size_t>(std::clamp<long>(above - x.nodes.begin() - 1, 0, static_cast<long>(x.count) - 2)));
  }
  bool stuck = false;
  if (!cells.empty() && (!split_x_cells(levels.x, cells) || levels.x.size() > max_x_nodes)) stuck = true;
  if (rz) stuck |= ++levels.z > max_level_z;
  if (ry) stuck |= ++levels.y > max_level_y;
  if (!rz && !ry && cells.empty()) {  // only the points anywhere fail, and none explains it alone: y
    stuck |= ++levels.y > max_level_y;
  }
  if (stuck) {
    throw InvalidArgument("tol", fmt::format("{}", request_.tolerance),
                          fmt::format("a tolerance the atlas reaches within its finest grid ({} x {} x {} nodes): its "
                                      "checks still find eps errors of {:.3g} on the nodes, {:.3g} along x, {:.3g} "
                                      "along y (each held to tol/4) and {:.3g} anywhere (tol/2), and v_s's {:.3g} "
                                      "(5e-7) (a larger --tol, or a smaller range)",
                                      levels.x.size(), base_.y_at(levels).count, base_.z_at(levels).count, c.z, c.x,
                                      c.y, c.full, c.v_stick()));
  }
  return true;
}

Atlas AtlasBuild::run() {
  initial_grid();
  AtlasLevels levels;
  levels.x = base_.first_x_keys();
  for (int round = 0;; ++round) {
    compute_nodes(levels);
    Atlas a = assemble(levels);
    a.prepare("(the atlas being built)");
    const AtlasCheck c = check(a, round);
    if (refine(levels, c)) continue;
    a.errors.cor_measured = c.cor();
    a.errors.cor = 2.0 * c.cor();
    a.errors.v_stick_measured = c.v_stick();
    a.errors.v_stick = std::max(2.0 * c.v_stick(), 1e-9);  // the bisections' own width is 1e-10
    a.errors.contact_time = c.contact_time;
    a.errors.energy = c.energy;
    a.errors.check_points = c.points;
    a.errors.v_stick_points = c.thresholds;
    a.warnings = memo_->warnings();
    return a;
  }
}

}  // namespace bounce::analysis::detail
