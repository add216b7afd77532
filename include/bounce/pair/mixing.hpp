#pragma once
// Mixing rules: every pair quantity as one named function, shared by all models
// (docs/decisions.md D1, D2). An infinite radius or mass stands for a wall; an infinite Young's
// modulus for an ideally rigid body.

namespace bounce {

/// R_eff = R1 R2 / (R1 + R2); wall (R2 = inf): R1.  BSHP96 (6), K13 after (1).
double effective_radius(double radius1, double radius2);

/// m_eff = m1 m2 / (m1 + m2); wall (m2 = inf): m1.  BSHP96 (5), BP04 (8.60).
double effective_mass(double mass1, double mass2);

/// E* = [(1 - nu1^2)/E1 + (1 - nu2^2)/E2]^-1; rigid body 2 (E2 = inf): E1/(1 - nu1^2).
/// K13 after (1); BP04 (8.8).
double effective_modulus(double youngs1, double poisson1, double youngs2, double poisson2);

/// BP04 (8.14): D = (3/4) [(1 - nu1^2)/E1 + (1 - nu2^2)/E2] = 3 / (4 E*).
double hertz_compliance_d(double effective_modulus);

/// Hertz force constant rho = (4/3) E* sqrt(R_eff): F = rho xi^{3/2}.
/// BP04 (8.24), BSHP96 (14), K13 (5) with a^2 = R delta.
double hertz_constant(double effective_modulus, double effective_radius);

/// Combined work of adhesion of two surfaces from the per-material table values:
/// gamma = sqrt(gamma_L1 gamma_L2) (K13 footnote 8: 2 sqrt(g1 g2) of free energies
/// g_i = gamma_Li / 2); like materials give gamma_L. docs/decisions.md D2.
double combined_surface_energy(double gamma1, double gamma2);

/// Mass of a homogeneous sphere, (4/3) pi R^3 density.
double sphere_mass(double radius, double density);

/// BSHP96 (8): kappa^-1 = 1 + (m1 J1 + m2 J2) / (J1 J2 (m1 + m2)), with the
/// dimensionless moments of inertia J_i = J_i / (m_i R_i^2) (BSHP96 (4)).
/// Identical solid spheres (J = 2/5): kappa = 2/7. Wall (m2 = inf): 1/(1 + 1/J1).
double tangential_mass_factor(double mass1, double inertia_factor1, double mass2,
                              double inertia_factor2);

/// G = E / (2 (1 + nu)), the shear modulus of an isotropic solid; E = inf (rigid): inf.
double shear_modulus(double youngs_modulus, double poisson_ratio);

/// Mindlin's tangential modulus G*: 1/G* = (2 - nu1)/G1 + (2 - nu2)/G2, so that a circular
/// contact of radius a has the tangential stiffness 8 a G* (W07 §2.2); rigid body 2
/// (G2 = inf): G1/(2 - nu1).
double effective_shear_modulus(double shear1, double poisson1, double shear2, double poisson2);

/// BSHP96 (B3): transversal speed of sound c_t = sqrt(E / (2 rho (1 + nu))) [m/s].
double transversal_sound_speed(double youngs_modulus, double poisson_ratio, double density);

}  // namespace bounce
