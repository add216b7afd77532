#include "bounce/contact/independent.hpp"

#include <cmath>
#include <numbers>

namespace bounce::contact::independent {

double pressure(const Geometry& g, double a, double delta, double r) {  // K13 (1)
  const double R = g.effective_radius;
  // (a - r)(a + r) rather than a^2 - r^2: exact near the edge, where p is singular.
  return g.effective_modulus / (std::numbers::pi * R) * (a * a - 2.0 * r * r + R * delta) /
         std::sqrt((a - r) * (a + r));
}

double elastic_force(const Geometry& g, double a, double delta) {  // K13 (2)
  const double R = g.effective_radius;
  return 2.0 * g.effective_modulus / (3.0 * R) * (3.0 * a * delta * R - a * a * a);
}

double elastic_energy(const Geometry& g, double a, double delta) {  // K13 (3)
  // Expanded form of (3), free of the 1/a^2 factors so that a -> 0 is regular:
  // U_E = E* [a delta^2 - 2 a^3 delta/(3R) + a^5/(5 R^2)].
  const double R = g.effective_radius;
  const double a3 = a * a * a;
  return g.effective_modulus *
         (a * delta * delta - 2.0 * a3 * delta / (3.0 * R) + a3 * a * a / (5.0 * R * R));
}

double effective_surface_energy(const Geometry& g, double a, double delta) {  // K13 (14)
  const double R = g.effective_radius;
  const double mismatch = a * a - delta * R;
  return g.effective_modulus * mismatch * mismatch / (2.0 * std::numbers::pi * a * R * R);
}

double surface_energy(double a, double gamma) {  // K13 (6)
  return -std::numbers::pi * a * a * gamma;
}

}  // namespace bounce::contact::independent
