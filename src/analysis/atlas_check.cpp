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

// Held-out points per round, by kind: on the nodes (z alone), on rows of y nodes (x and z),
// on columns of x nodes (y and z), anywhere; and sticking velocities (a bisection each).
constexpr int z_points = 100, x_points = 150, y_points = 150, full_points = 600;
constexpr int threshold_points = 12;
constexpr int max_level_x = 5, max_level_y = 4, max_level_z = 4;

struct Probe {
  std::array<double, 2> radii;
  double v = 0.0;   ///< 0: a sticking velocity
  int kind = 0;     ///< 0 z, 1 x, 2 y, 3 full
};

}  // namespace

void AtlasBuild::check_collision(const Atlas& a, const std::array<double, 2>& radii, double v, double& worst,
                                 AtlasCheck& c) {
  const AtlasCollision direct = collision(radii, v);
  const AtlasValue got = a.at({radii[0], radii[1], v});
  ++c.points;
  if (got.sticks != direct.sticks) {
    // Only inside the band of the interpolated v_s: counted as its error.
    const double band = std::isfinite(got.v_stick) ? std::abs(v / got.v_stick - 1.0) : 1.0;
    c.vs_full = std::max(c.vs_full, band);
    return;
  }
  if (direct.sticks) return;
  worst = std::max(worst, std::abs(got.cor - direct.cor));
  c.contact_time = std::max(c.contact_time, std::abs(*got.contact_time / direct.contact_time - 1.0));
  c.energy = std::max({c.energy, std::abs(*got.bulk_fraction - direct.bulk_fraction),
                       std::abs(*got.crack_fraction - direct.crack_fraction)});
}

void AtlasBuild::check_threshold(const Atlas& a, const std::array<double, 2>& radii, double& worst) {
  const AtlasThreshold direct = threshold(radii);
  // v_s is held to its error inside the table's speeds; above them, the atlas need only say
  // that the grains stick at all of them (docs/atlas.md).
  const double got = a.v_stick(radii[0], radii[1]);
  const double v_max = request_.velocity_max;
  if (!direct.defined || direct.velocity > v_max) {
    if (got < v_max) worst = std::max(worst, direct.defined ? std::abs(got / direct.velocity - 1.0) : 1.0);
    return;
  }
  worst = std::max(worst, std::isinf(got) ? 1.0 : std::abs(got / direct.velocity - 1.0));
}

AtlasCheck AtlasBuild::check(const Atlas& a, int round) {
  std::mt19937_64 rng(0x61746c6173ULL + static_cast<unsigned>(round));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double lx = std::log(request_.radius_min), hx = std::log(request_.radius_max);
  const double lv = std::log(request_.velocity_min), hv = std::log(request_.velocity_max);
  const auto random_x = [&] { return std::exp(lx + (hx - lx) * unit(rng)); };
  const auto random_y = [&] { return std::exp(a.y.start + (a.y.end() - a.y.start) * unit(rng)); };
  const auto node_of = [&](const AtlasAxis& axis) {
    std::uniform_int_distribution<std::size_t> pick(0, axis.count - 1);
    return std::exp(axis.value(pick(rng)));
  };
  const auto node_x = [&] { return node_of(a.x); };
  const auto node_y = [&] { return node_of(a.y); };
  const auto random_v = [&] { return std::exp(lv + (hv - lv) * unit(rng)); };
  std::vector<Probe> probes;
  const auto add = [&](int kind, int count, auto x, auto y, bool speeds) {
    for (int i = 0; i < count; ++i) {
      const double r = x(), rho = y();
      probes.push_back({radii_for(r, std::clamp(rho, density_[0], density_[1]), m1_.density, m2_.density),
                        speeds ? random_v() : 0.0, kind});
    }
  };
  add(0, z_points, node_x, node_y, true);
  add(1, x_points, random_x, node_y, true);
  add(2, y_points, node_x, random_y, true);
  add(3, full_points, random_x, random_y, true);
  if (can_stick_) {
    add(1, threshold_points, random_x, node_y, false);
    add(2, threshold_points, node_x, random_y, false);
    add(3, threshold_points, random_x, random_y, false);
  }
  run_jobs(probes.size(), [&](std::size_t i) {
    const Probe& p = probes[i];
    if (p.v > 0.0) collision(p.radii, p.v);
    else threshold(p.radii);
  });
  AtlasCheck c;
  for (const Probe& p : probes) {
    if (p.v > 0.0) {
      double& worst = p.kind == 0 ? c.z : p.kind == 1 ? c.x : p.kind == 2 ? c.y : c.full;
      check_collision(a, p.radii, p.v, worst, c);
    } else {
      double& worst = p.kind == 1 ? c.vs_x : p.kind == 2 ? c.vs_y : c.vs_full;
      check_threshold(a, p.radii, worst);
      ++c.thresholds;
    }
  }
  return c;
}

// Which axes to refine (false: done). The eps target is tolerance / 2 (the stated bound is
// twice the largest error found), v_s's v_stick_target.
bool AtlasBuild::refine(AtlasLevels& levels, const AtlasCheck& c) const {
  const double target = request_.tolerance / 2.0;
  bool rz = c.z > target / 2.0;
  bool rx = (c.x > target / 2.0 && c.x > 2.0 * c.z) || c.vs_x > v_stick_target;
  bool ry = (c.y > target / 2.0 && c.y > 2.0 * c.z) || c.vs_y > v_stick_target;
  const bool failing = c.cor() > target || c.v_stick() > v_stick_target;
  if (!failing && !rz && !rx && !ry) return false;
  if (!rz && !rx && !ry) {  // only the points anywhere fail: the axis with the larger error
    (std::max(c.x, c.vs_x / v_stick_target * target) >= std::max(c.y, c.vs_y / v_stick_target * target) ? rx : ry) = true;
  }
  const auto beyond = [&](bool want, int& level, int max) {
    if (!want) return false;
    if (level >= max) return true;
    ++level;
    return false;
  };
  if (beyond(rx, levels.x, max_level_x) | beyond(ry, levels.y, max_level_y) | beyond(rz, levels.z, max_level_z)) {
    throw InvalidArgument("tol", fmt::format("{}", request_.tolerance),
                          fmt::format("a tolerance the atlas reaches within its finest grid: there its largest eps "
                                      "error is {:.3g} and v_s's {:.3g} (a larger --tol, or a smaller range)",
                                      c.cor(), c.v_stick()));
  }
  return true;
}

Atlas AtlasBuild::run() {
  initial_grid();
  AtlasLevels levels;
  for (int round = 0;; ++round) {
    compute_nodes(levels);
    Atlas a = assemble(levels);
    a.prepare("atlas");
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
