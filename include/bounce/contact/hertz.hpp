#pragma once
// Hertz contact of two elastic spheres (no adhesion).
// BP04 (8.23)-(8.24), K13 (4)-(5), BSHP96 (14).

namespace bounce::contact::hertz {

/// BP04 (8.24): F = rho xi^{3/2}, rho = (4/3) E* sqrt(R_eff). Zero for xi <= 0.
double force(double hertz_constant, double overlap);
/// Inverse of (8.24): xi = (F / rho)^{2/3}, F >= 0.
double overlap_from_force(double hertz_constant, double force);
/// BP04 (8.23), K13 (4): a^2 = R_eff xi.
double contact_radius(double effective_radius, double overlap);
/// K13 (5): F = 4 E* a^3 / (3 R).
double force_from_contact_radius(double effective_modulus, double effective_radius,
                                 double contact_radius);
/// Elastic energy stored at overlap xi: U = (2/5) rho xi^{5/2} (integral of (8.24)).
double elastic_energy(double hertz_constant, double overlap);
/// Central pressure p0 = 3F / (2 pi a^2) (BP04 (8.10) at x = y = 0, a = b).
double max_pressure(double force, double contact_radius);

}  // namespace bounce::contact::hertz
