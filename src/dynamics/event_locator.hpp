#pragma once
// Private: event location, one code for both engines of bounce (the explicit dopri5 of
// event_integrator.hpp and the Rosenbrock engine of rodas_integrator.cpp; CVODE has its own).
//
// An event is a scalar function g(t, y) of the state; it fires where g crosses zero in its
// direction (-1 falling, +1 rising, 0 either). Within a step [t0, t1] the crossing is
// located on the engine's dense output by TOMS 748 to the last bit; an event may also
// "graze": fire where a smooth extremum of g just reaches zero inside the step without a
// sign change at its ends (an asperity loaded exactly up to its limit at the top of its load,
// docs/tables.md).

#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>

namespace bounce::dynamics::detail {

/// Does g cross zero from ga to gb in `direction`?
inline bool crosses(double ga, double gb, int direction) {
  const bool falls = ga > 0.0 && gb <= 0.0, rises = ga < 0.0 && gb >= 0.0;
  return (direction <= 0 && falls) || (direction >= 0 && rises);
}

/// The bracket [lo, hi] of the zero of g in [a, b], ga = g(a) and gb = g(b) of opposite
/// signs, narrowed by TOMS 748 to the last bits (gb == 0: the end itself; b <= a, a grazing
/// minimum found at the window's start within round-off: that point).
template <class G>
std::pair<double, double> crossing(const G& g, double a, double b, double ga, double gb) {
  if (gb == 0.0 || !(a < b)) return {b, b};
  std::uintmax_t iterations = 100;
  return boost::math::tools::toms748_solve(g, a, b, ga, gb, boost::math::tools::eps_tolerance<double>(52), iterations);
}

/// The first point in [lo, hi] where g touches zero from the side `direction` leaves
/// (-1: g > 0 at both ends), or NaN when it does not. A parabola through the ends and
/// the midpoint says whether g has an interior extremum; only then is it located
/// (Brent) and, when it reaches zero, the root before it (TOMS 748).
template <class G>
double grazing_root(const G& g, double lo, double hi, double g_lo, double g_hi, int direction) {
  const double s = direction < 0 ? 1.0 : -1.0;  // minimise s g
  const double h = hi - lo, a = s * g_lo, b = s * g_hi, m = s * g(lo + 0.5 * h);
  const double curvature = 2.0 * (a - 2.0 * m + b) / (h * h), slope = (4.0 * m - 3.0 * a - b) / h;
  if (!(curvature > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  const double vertex = -slope / (2.0 * curvature);
  if (!(vertex > 0.0 && vertex < h)) return std::numeric_limits<double>::quiet_NaN();
  std::uintmax_t iterations = 100;
  const auto [t_min, g_min] =
      boost::math::tools::brent_find_minima([&](double t) { return s * g(t); }, lo, hi, 40, iterations);
  if (g_min > 0.0) return std::numeric_limits<double>::quiet_NaN();
  const auto bracket = crossing([&](double t) { return s * g(t); }, lo, t_min, a, g_min);
  return 0.5 * (bracket.first + bracket.second);
}

/// Where an event fires inside [lo, hi] (the window it has been armed in, within the
/// step), given g at both ends and g on the dense output: the bracket of its crossing, or
/// of its grazing point; empty (NaN) when it does not fire there.
template <class G>
std::pair<double, double> locate(const G& g, double lo, double hi, double g_lo, double g_hi, int direction,
                                 bool graze) {
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  if (crosses(g_lo, g_hi, direction)) return crossing(g, lo, hi, g_lo, g_hi);
  const bool same_side = direction < 0 ? g_lo > 0.0 && g_hi > 0.0 : g_lo < 0.0 && g_hi < 0.0;
  if (!graze || direction == 0 || !same_side) return {none, none};
  const double root = grazing_root(g, lo, hi, g_lo, g_hi, direction);
  return {root, root};
}

}  // namespace bounce::dynamics::detail
