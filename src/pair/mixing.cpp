#include "bounce/pair/mixing.hpp"

#include <cmath>
#include <numbers>

namespace bounce {

double effective_radius(double radius1, double radius2) {  // BSHP96 (6)
  if (std::isinf(radius2)) return radius1;
  if (std::isinf(radius1)) return radius2;
  return radius1 * radius2 / (radius1 + radius2);
}

double effective_mass(double mass1, double mass2) {  // BSHP96 (5)
  if (std::isinf(mass2)) return mass1;
  if (std::isinf(mass1)) return mass2;
  return mass1 * mass2 / (mass1 + mass2);
}

double effective_modulus(double youngs1, double poisson1, double youngs2,
                         double poisson2) {  // K13 after (1)
  const double compliance1 = (1.0 - poisson1 * poisson1) / youngs1;
  const double compliance2 = std::isinf(youngs2) ? 0.0 : (1.0 - poisson2 * poisson2) / youngs2;
  return 1.0 / (compliance1 + compliance2);
}

double hertz_compliance_d(double effective_modulus) {  // BP04 (8.14)
  return 3.0 / (4.0 * effective_modulus);
}

double hertz_constant(double effective_modulus, double effective_radius) {  // BP04 (8.24)
  return 4.0 / 3.0 * effective_modulus * std::sqrt(effective_radius);
}

double combined_surface_energy(double gamma1, double gamma2) {  // K13 footnote 8, docs/decisions.md D2
  const double product = gamma1 * gamma2;
  // sqrt(gamma1) sqrt(gamma2) where the product under- or overflows (gamma = 1e-300 gave 0).
  if (product != 0.0 && std::isnormal(product)) return std::sqrt(product);
  return std::sqrt(gamma1) * std::sqrt(gamma2);
}

double sphere_mass(double radius, double density) {
  return 4.0 / 3.0 * std::numbers::pi * radius * radius * radius * density;
}

double tangential_mass_factor(double mass1, double inertia_factor1, double mass2,
                              double inertia_factor2) {  // BSHP96 (8)
  if (std::isinf(mass2)) return 1.0 / (1.0 + 1.0 / inertia_factor1);
  if (std::isinf(mass1)) return 1.0 / (1.0 + 1.0 / inertia_factor2);
  const double inverse =
      1.0 + (mass1 * inertia_factor1 + mass2 * inertia_factor2) /
                (inertia_factor1 * inertia_factor2 * (mass1 + mass2));
  return 1.0 / inverse;
}

double transversal_sound_speed(double e, double nu, double density) {  // BSHP96 (B3)
  return std::sqrt(e / (2.0 * density * (1.0 + nu)));
}

double shear_modulus(double youngs_modulus, double poisson_ratio) {  // isotropic elasticity
  return youngs_modulus / (2.0 * (1.0 + poisson_ratio));
}

double effective_shear_modulus(double shear1, double poisson1, double shear2, double poisson2) {  // W07 §2.2
  const double compliance2 = std::isinf(shear2) ? 0.0 : (2.0 - poisson2) / shear2;
  return 1.0 / ((2.0 - poisson1) / shear1 + compliance2);
}

}  // namespace bounce
