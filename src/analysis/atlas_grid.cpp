// The atlas's geometry (atlas_grid.hpp).
#include "atlas_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>

#include "bounce/core/error.hpp"

namespace bounce::analysis::detail {

namespace {

// rho_eff of the ratio t = R1/R2 (t = 0: a wall, t = inf: body 1 infinitely large).
double density_of_ratio(double t, double density1, double density2) {
  if (std::isinf(t)) return density2;
  return effective_density(density1, density2, t, 1.0);
}

// log10 t from -12 to 12: the ratios scanned for the range and for a bracket.
constexpr int scan_points = 2401;
double scan_ratio(int k) { return std::pow(10.0, -12.0 + 24.0 * k / (scan_points - 1)); }

}  // namespace

namespace {

// The ratio t* where rho_eff is largest (0 when it is largest at a wall, inf at body 1's side).
double ratio_of_maximum(double density1, double density2) {
  int best = 0;
  double hi = -1.0;
  for (int k = 0; k < scan_points; ++k) {
    const double f = density_of_ratio(scan_ratio(k), density1, density2);
    if (f > hi) {
      hi = f;
      best = k;
    }
  }
  if (best == 0) return density1 >= density2 ? 0.0 : std::numeric_limits<double>::infinity();
  if (best + 1 == scan_points) return std::numeric_limits<double>::infinity();
  const auto minus = [&](double s) { return -density_of_ratio(std::exp(s), density1, density2); };
  return std::exp(boost::math::tools::brent_find_minima(minus, std::log(scan_ratio(best - 1)),
                                                        std::log(scan_ratio(best + 1)), 52)
                      .first);
}

}  // namespace

std::array<double, 2> density_range(double density1, double density2) {
  double lo = std::min(density1, density2);
  for (int k = 0; k < scan_points; ++k) lo = std::min(lo, density_of_ratio(scan_ratio(k), density1, density2));
  const double t = ratio_of_maximum(density1, density2);
  return {lo, std::max({density1, density2, density_of_ratio(t, density1, density2)})};
}

std::array<double, 2> radii_for(double r, double rho, double density1, double density2) {
  const double inf = std::numeric_limits<double>::infinity();
  const auto radii = [&](double t) -> std::array<double, 2> {
    if (t == 0.0) return {r, inf};
    return {r * (1.0 + t), r * (1.0 + t) / t};
  };
  if (std::abs(rho - density1) <= 1e-14 * density1) return radii(0.0);
  // rho_eff rises from density1 (t = 0) to its largest at t*, then falls to density2 (t = inf,
  // reached within 1e-12 at t = 1e12): one side of t* holds rho.
  const double peak = ratio_of_maximum(density1, density2);
  const double t_peak = std::isinf(peak) ? 1e12 : peak;
  const auto gap = [&](double t) { return density_of_ratio(t, density1, density2) - rho; };
  if (std::abs(gap(t_peak)) <= 1e-12 * rho) return radii(t_peak);
  const bool rising_side = (gap(0.0) < 0.0) != (gap(t_peak) < 0.0);
  const double a = rising_side ? 0.0 : t_peak, b = rising_side ? t_peak : 1e12;
  if ((gap(a) < 0.0) == (gap(b) < 0.0)) {
    if (std::abs(gap(b)) <= 1e-9 * rho) return radii(b);
    throw std::logic_error("atlas: no pair of radii has this effective density");  // the range says otherwise
  }
  boost::uintmax_t iterations = 200;
  const auto root = boost::math::tools::toms748_solve(gap, a, b, gap(a), gap(b),
                                                      boost::math::tools::eps_tolerance<double>(52), iterations);
  return radii(0.5 * (root.first + root.second));
}

Pair atlas_pair(const Material& m1, const Material& m2, const std::array<double, 2>& radii) {
  if (std::isinf(radii[1])) return Pair(sphere(m1, radii[0]), wall(m2));
  return Pair(sphere(m1, radii[0]), sphere(m2, radii[1]));
}

AtlasAxis AtlasGridBase::x_at(const AtlasLevels& l) const {
  AtlasAxis a;
  const double unit = std::ldexp(x.step, -x_key_depth);  // exact: a key's coordinate never changes
  for (long k : l.x) a.nodes.push_back(x.start + static_cast<double>(k) * unit);
  a.count = a.nodes.size();
  a.start = a.nodes.front();
  a.step = unit;
  return a;
}

std::vector<long> AtlasGridBase::first_x_keys() const {
  std::vector<long> keys;
  for (std::size_t i = 0; i < x.count; ++i) keys.push_back(static_cast<long>(i) << x_key_depth);
  return keys;
}

bool split_x_cells(std::vector<long>& keys, const std::vector<std::size_t>& cells) {
  std::vector<long> added;
  for (std::size_t c : cells) {
    if (c + 1 < keys.size() && keys[c + 1] - keys[c] >= 2) added.push_back((keys[c] + keys[c + 1]) / 2);
  }
  if (added.empty()) return false;
  keys.insert(keys.end(), added.begin(), added.end());
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  for (bool graded = false; !graded;) {  // 2:1 balance between neighbouring cells
    graded = true;
    for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
      const long w = keys[i + 1] - keys[i];
      const long left = i > 0 ? keys[i] - keys[i - 1] : w, right = i + 2 < keys.size() ? keys[i + 2] - keys[i + 1] : w;
      if (w > 2 * std::min(left, right) && w >= 2) {
        keys.insert(keys.begin() + static_cast<long>(i) + 1, (keys[i] + keys[i + 1]) / 2);
        graded = false;
        break;
      }
    }
  }
  return true;
}

AtlasAxis AtlasGridBase::at(const AtlasAxis& base, int level) const {
  const double scale = std::ldexp(1.0, -level);  // exact: coarse nodes keep their coordinates
  return AtlasAxis{base.start, base.step * scale, ((base.count - 1) << level) + 1, {}};
}

}  // namespace bounce::analysis::detail
