#pragma once
// DMT adhesive contact: Hertz profile, adhesion acting in a ring outside the
// contact (BP04 after (8.52)). F = rho xi^{3/2} - 2 pi gamma R_eff, a^2 = R_eff xi.

namespace bounce::contact::dmt {

struct Parameters {
  double effective_radius = 0.0;   ///< R_eff [m]
  double effective_modulus = 0.0;  ///< E* [Pa]
  double surface_energy = 0.0;     ///< gamma [J/m^2]
};

/// Hertz force minus the constant DMT adhesion 2 pi gamma R_eff (xi >= 0).
double force(const Parameters& p, double overlap);
/// BP04 after (8.52): F_sep = -2 pi gamma R_eff (reached as xi -> 0, a -> 0).
double pull_off_force(const Parameters& p);
/// Overlap at force F >= F_sep: xi = ((F + 2 pi gamma R)/rho)^{2/3}.
double overlap_from_force(const Parameters& p, double force);
/// a^2 = R_eff xi (Hertz, BP04 (8.23)).
double contact_radius(const Parameters& p, double overlap);

}  // namespace bounce::contact::dmt
