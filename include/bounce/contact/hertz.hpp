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

// The scales of an elastic collision at impact speed g (every layer takes them from here).
/// BP04 (8.65): xi0 = (5 m_eff g^2 / (4 rho))^{2/5}, its maximum overlap.
double reference_overlap(double hertz_constant, double effective_mass, double speed);
/// Its duration in units of xi0 / g: 2 int_0^1 (1 - x^{5/2})^{-1/2} dx = (4/5) sqrt(pi)
/// Gamma(2/5) / Gamma(9/10) = 2.943275... (BSHP96 (A13)'s 2.94, K13 (22)'s 2.87 with its own scale).
double scaled_collision_time();
/// Its duration t_c = scaled_collision_time() xi0 / g = 2.943275 (5 m_eff / (4 rho))^{2/5} g^{-1/5}.
double collision_time(double hertz_constant, double effective_mass, double speed);

}  // namespace bounce::contact::hertz
