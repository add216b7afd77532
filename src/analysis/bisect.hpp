#pragma once
// Private: the one bisection of an outcome boundary (the sticking velocity, the stick/bounce
// boundaries of a curve, the jumps of an eps^N table).

#include <cmath>
#include <utility>

namespace bounce::analysis::detail {

/// Narrows a bracket [lo, hi] of a boundary, `below(lo)` true and `below(hi)` false, by
/// halving at `split(lo, hi)` until `narrow(lo, hi)`; returns the final bracket. `below` is
/// called once per halving (it may record what it computed at the point).
template <class Below, class Split, class Narrow>
std::pair<double, double> bisect(double lo, double hi, Below below, Split split, Narrow narrow) {
  while (!narrow(lo, hi)) {
    const double mid = split(lo, hi);
    (below(mid) ? lo : hi) = mid;
  }
  return {lo, hi};
}

/// The same for speeds: geometric midpoints, until hi - lo <= relative_width * hi.
template <class Below>
std::pair<double, double> bisect_speed(double lo, double hi, Below below, double relative_width) {
  return bisect(
      lo, hi, below, [](double a, double b) { return std::sqrt(a * b); },
      [relative_width](double a, double b) { return b - a <= relative_width * b; });
}

}  // namespace bounce::analysis::detail
