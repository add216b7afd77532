#pragma once
// Random numbers that are the same on every platform: std::mt19937_64's integers (their
// sequence is fixed by the C++ standard) turned into doubles by +, *, / and sqrt alone, which
// IEEE 754 rounds exactly (no std::*_distribution, whose algorithms are the library's choice,
// and no sin/cos, whose last bit is libm's). The file is compiled with -ffp-contract=off.

#include <cmath>
#include <cstdint>
#include <random>

#include "bounce/aggregate/aggregate.hpp"

namespace bounce::aggregate::detail {

/// A rotation as a 3x3 matrix (rows).
using Rotation = std::array<Vector, 3>;

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}

  /// Uniform in [0, 1): the top 53 bits of one integer, times 2^-53.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  /// Uniform in (-1, 1).
  double symmetric() {
    double x = 0.0;
    do x = 2.0 * uniform() - 1.0;
    while (x == -1.0);
    return x;
  }

  /// A point uniform in the unit disk (rejection from the square), and its |p|^2.
  void disk(double& x, double& y, double& s) {
    do {
      x = symmetric();
      y = symmetric();
      s = x * x + y * y;
    } while (s >= 1.0);
  }

  /// A direction uniform on the unit sphere: Marsaglia (1972), Ann. Math. Stat. 43, 645, eq. (4).
  Vector direction() {
    double x = 0.0, y = 0.0, s = 0.0;
    do disk(x, y, s);
    while (s == 0.0);
    const double f = 2.0 * std::sqrt(1.0 - s);
    return {x * f, y * f, 1.0 - 2.0 * s};
  }

  /// A rotation uniform in SO(3): a unit quaternion uniform on S^3 by Marsaglia (1972) eq. (5)
  /// (two points in the unit disk), turned into its matrix (Shoemake 1985, SIGGRAPH 19, 245).
  Rotation rotation() {
    double a = 0.0, b = 0.0, s1 = 0.0, c = 0.0, d = 0.0, s2 = 0.0;
    disk(a, b, s1);
    do disk(c, d, s2);
    while (s2 == 0.0);
    const double f = std::sqrt((1.0 - s1) / s2);
    const double w = a, x = b, y = c * f, z = d * f;
    return {Vector{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
            Vector{2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
            Vector{2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace bounce::aggregate::detail
