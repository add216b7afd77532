// The atlas build (docs/atlas.md, "Error control"): sticking velocities and collisions on the
// grid's nodes, held-out checks against direct collisions, and refinement of the axis whose
// checks fail, until the interpolant's error is at most tolerance / 2.
#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

#include <fmt/format.h>

#include "atlas_checks.hpp"
#include "bounce/analysis/sticking.hpp"
#include "bounce/analytic/adhesive.hpp"
#include "bounce/core/error.hpp"
#include "bounce/core/version.hpp"
#include "bounce/models/registry.hpp"
#include "bounce/pair/pair_parameters.hpp"
#include "parallel.hpp"

namespace bounce::analysis {

namespace detail {

AtlasBuild::AtlasBuild(const AtlasRequest& request, const AtlasRunner& runner)
    : request_(request), runner_(runner) {
  const Pair probe = make_pair(request.pair_parameters, 1e-6);
  m1_ = probe.body1().material;
  m2_ = probe.body2().material;
  model_ = models::make_model(probe, request.model, request.model_parameters);
  can_stick_ = model_.traits.adhesive;
  c_t_ = probe.transversal_sound_speed();
  density_ = density_range(m1_.density, m2_.density);
  if (can_stick_) {
    // v_ref: JKR's threshold K13 (25) scales as R_eff^(-5/6) rho_eff^(-1/2) at fixed materials.
    const double r = std::sqrt(request.radius_min * request.radius_max), rho = std::sqrt(density_[0] * density_[1]);
    const Pair mid = atlas_pair(m1_, m2_, radii_for(r, rho, m1_.density, m2_.density));
    ln_v_reference_ = std::log(analytic::sticking_velocity_jkr(mid.effective_mass(), r, mid.effective_modulus(),
                                                               *mid.surface_energy())) +
                      5.0 / 6.0 * std::log(r) + 0.5 * std::log(rho);
  }
  std::exception_ptr error;  // a cache that cannot be read or written: every process learns it
  try {
    memo_.emplace(runner.cache_path, fingerprint(), !runner.cache_path.empty() && runner.writes_cache);
  } catch (...) {
    error = std::current_exception();
    memo_.emplace(std::string(), fingerprint(), false);
  }
  if (runner_.share) {
    memo_->merge(runner_.share(memo_->take_new(), error));  // the cache's results on every process
  } else if (error) {
    std::rethrow_exception(error);
  }
}

std::uint64_t AtlasBuild::fingerprint() const {
  std::string text = fmt::format("{}|{}|", bounce::version(), request_.model);
  for (const auto& p : model_parameters(request_)) text += fmt::format("{}={}|", p.name, p.value);
  for (const Material* m : {&m1_, &m2_}) {
    text += fmt::format("{}:{:a},{:a},{:a},{:a}|", m->name, m->youngs_modulus, m->poisson_ratio, m->density,
                        m->surface_energy.value_or(-1.0));
  }
  const CollideOptions& o = request_.options;
  text += fmt::format("{}|{:a}|{:a}|{}", static_cast<int>(o.method), o.integration.relative_tolerance,
                      o.adhesive_tolerance, static_cast<int>(o.stiff_engine));
  return fnv1a(text);
}

AtlasCollision AtlasBuild::collision(const std::array<double, 2>& radii, double v) {
  const AtlasMemo::Key key{radii[0], radii[1], v};
  if (auto known = memo_->collision(key)) return *known;
  const Pair pair = atlas_pair(m1_, m2_, radii);
  const models::Model model = models::make_model(pair, request_.model, request_.model_parameters);
  const dynamics::CollisionOutcome out = analysis::collide(pair, model, v, request_.options);
  AtlasCollision c;
  c.sticks = out.outcome == dynamics::Outcome::stick;
  c.cor = c.sticks ? 0.0 : out.cor;
  const double e0 = out.energy.initial_kinetic;
  c.contact_time = c.sticks ? 1.0 : out.contact_time;
  c.bulk_fraction = c.sticks ? 0.0 : out.energy.bulk_dissipated / e0;
  c.crack_fraction = c.sticks ? 0.0 : out.energy.crack_dissipated / e0;
  memo_->put(key, c, out.warnings);
  report("collisions");
  return c;
}

AtlasThreshold AtlasBuild::threshold(const std::array<double, 2>& radii) {
  if (!can_stick_) return {true, 0.0};
  const AtlasMemo::Key key{radii[0], radii[1], 0.0};
  if (auto known = memo_->threshold(key)) return *known;
  const Pair pair = atlas_pair(m1_, m2_, radii);
  const models::Model model = models::make_model(pair, request_.model, request_.model_parameters);
  // 1e-10: far below the 1e-6 the interpolated v_s is held to, and the first z point
  // (threshold_margin >= 1e-9 above v_s) bounces for sure.
  const StickingVelocity s = sticking_velocity(pair, model, request_.options, 1e-10);
  AtlasThreshold t{!s.sticks_up_to_sound_speed, s.sticks_up_to_sound_speed ? 0.0 : s.velocity};
  if (t.defined && t.velocity + request_.velocity_min > c_t_) t.defined = false;  // no bounce to tabulate
  memo_->put(key, t);
  report("sticking velocities");
  return t;
}

void AtlasBuild::report(const char* stage) {
  if (!runner_.progress) return;
  const std::lock_guard lock(progress_mutex_);
  runner_.progress(memo_->computed(), stage);
}

void AtlasBuild::run_jobs(std::size_t count, const std::function<void(std::size_t)>& job) {
  if (runner_.distribute) {
    runner_.distribute(count, job);
  } else {
    parallel_for(count, request_.threads, [&](std::size_t i, unsigned) { job(i); });
  }
  if (runner_.share) memo_->merge(runner_.share(memo_->take_new(), nullptr));
}

std::array<double, 2> AtlasBuild::node_radii(const AtlasAxis& x, const AtlasAxis& y, std::size_t ix,
                                             std::size_t iy) const {
  return radii_for(std::exp(x.value(ix)), std::exp(y.value(iy)), m1_.density, m2_.density);
}

// The z points of a node, (index, speed): from threshold_margin v_s above its sticking velocity
// to v_max, never above the sound speed; none where v_s lies above column_cap v_max.
std::vector<std::pair<std::size_t, double>> AtlasBuild::column_speeds(const AtlasThreshold& t,
                                                                      const AtlasAxis& z) const {
  std::vector<std::pair<std::size_t, double>> speeds;
  if (!has_column(t)) return speeds;
  for (std::size_t k = 0; k < z.count; ++k) {
    const double gap = std::exp(z.value(k));
    if (can_stick_ && gap < threshold_margin(request_.tolerance) * t.velocity) continue;
    const double v = t.velocity + gap;
    if (v > c_t_) break;
    speeds.emplace_back(k, v);
  }
  return speeds;
}

bool AtlasBuild::has_column(const AtlasThreshold& t) const {
  return t.defined && t.velocity <= column_cap * request_.velocity_max;
}

void AtlasBuild::compute_nodes(const AtlasLevels& levels) {
  const AtlasAxis x = base_.x_at(levels), y = base_.y_at(levels);
  const std::size_t n = x.count * y.count;
  run_jobs(n, [&](std::size_t i) { threshold(node_radii(x, y, i / y.count, i % y.count)); });
  if (!z_fixed_) fix_z_axis(x, y);  // the z axis starts below the first grid's smallest v_s
  const AtlasAxis z = base_.z_at(levels);
  run_jobs(n, [&](std::size_t i) {
    const auto radii = node_radii(x, y, i / y.count, i % y.count);
    for (const auto& [k, v] : column_speeds(threshold(radii), z)) collision(radii, v);
  });
}

// The z axis's start: threshold_margin(tol) times the smallest v_s of the first grid, over 4 (finer
// grids meet smaller ones between its nodes); ln v_min for models that cannot stick.
void AtlasBuild::fix_z_axis(const AtlasAxis& x, const AtlasAxis& y) {
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t ix = 0; ix < x.count; ++ix) {
    for (std::size_t iy = 0; iy < y.count; ++iy) {
      const AtlasThreshold t = threshold(node_radii(x, y, ix, iy));
      if (t.defined) smallest = std::min(smallest, t.velocity);
    }
  }
  const double lo = can_stick_ && std::isfinite(smallest)
                        ? std::min(std::log(threshold_margin(request_.tolerance) * smallest / 4.0), std::log(request_.velocity_min))
                        : std::log(request_.velocity_min);
  const double hi = std::log(request_.velocity_max);
  const double step0 = std::log(request_.velocity_max / request_.velocity_min) /
                       static_cast<double>(request_.velocity_nodes - 1);
  const auto count = static_cast<std::size_t>(std::ceil((hi - lo) / step0 * (1 - 1e-12))) + 1;
  base_.z = AtlasAxis{lo, step0, std::max<std::size_t>(count, 4), {}};
  z_fixed_ = true;
}

}  // namespace detail

Atlas build_atlas(const AtlasRequest& request, const AtlasRunner& runner) {
  detail::AtlasBuild build(request, runner);
  return build.run();
}

}  // namespace bounce::analysis
