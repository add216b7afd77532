#pragma once
// Vector arithmetic and the first touch of two spheres, one moving on a straight line, for the
// ballistic growth (docs/aggregates.md, "The first touch").

#include <cmath>
#include <limits>

#include "bounce/aggregate/aggregate.hpp"

namespace bounce::aggregate::detail {

inline Vector operator+(const Vector& a, const Vector& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vector operator-(const Vector& a, const Vector& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vector operator*(double s, const Vector& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline double dot(const Vector& a, const Vector& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vector cross(const Vector& a, const Vector& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// The path parameter s at which a sphere at a + s u (|u| = 1), coming from s = -inf, first
/// touches a sphere at x, centres `contact` apart (2r): the smaller root of |a + s u - x| = contact,
/// s = -w.u - sqrt(contact^2 - h^2) with w = a - x and h = |w - (w.u) u| the line's distance from x
/// (the ray-sphere intersection, Ericson 2005, Real-Time Collision Detection, 5.3.2). +inf: missed.
inline double first_touch(const Vector& a, const Vector& u, const Vector& x, double contact) {
  const Vector w = a - x;
  const double along = dot(w, u);
  const Vector perpendicular = w - along * u;
  const double gap = contact * contact - dot(perpendicular, perpendicular);
  if (gap < 0.0) return std::numeric_limits<double>::infinity();
  return -along - std::sqrt(gap);
}

/// Two unit vectors that complete u to a right-handed orthonormal basis (no trigonometry:
/// u x the coordinate axis least along u).
inline void plane_basis(const Vector& u, Vector& e1, Vector& e2) {
  const double ax = std::abs(u[0]), ay = std::abs(u[1]), az = std::abs(u[2]);
  const Vector axis = ax <= ay && ax <= az ? Vector{1, 0, 0} : ay <= az ? Vector{0, 1, 0} : Vector{0, 0, 1};
  const Vector c = cross(u, axis);
  e1 = (1.0 / std::sqrt(dot(c, c))) * c;
  e2 = cross(u, e1);
}

}  // namespace bounce::aggregate::detail
