#pragma once
// The contact of two elastic spheres described by contact radius a and mutual
// approach delta as independent variables (K13 §2.1, (1)-(3), (14)). Hertz and
// JKR are the special relations a(delta) that minimise U_E and U_E + U_S.

namespace bounce::contact::independent {

struct Geometry {
  double effective_radius = 0.0;   ///< R [m]
  double effective_modulus = 0.0;  ///< E* [Pa]
};

/// K13 (1): p(r) = E*/(pi R) (a^2 - 2 r^2 + R delta) / sqrt(a^2 - r^2), 0 <= r < a [Pa].
double pressure(const Geometry& g, double contact_radius, double approach, double r);
/// K13 (2): F_E = (2 E* / 3R) (3 a delta R - a^3) [N].
double elastic_force(const Geometry& g, double contact_radius, double approach);
/// K13 (3): U_E = E* a^3/(3R) [delta (3 delta R/a^2 - 1) - a^2/(5R) (5 delta R/a^2 - 3)] [J].
double elastic_energy(const Geometry& g, double contact_radius, double approach);
/// K13 (14): G_eff = E* (a^2 - delta R)^2 / (2 pi a R^2) [J/m^2]; from (12)-(13),
/// dU_E/da = 2 pi a G_eff.
double effective_surface_energy(const Geometry& g, double contact_radius, double approach);
/// K13 (6): U_S = -pi a^2 gamma [J].
double surface_energy(double contact_radius, double gamma);

}  // namespace bounce::contact::independent
