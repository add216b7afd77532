#pragma once
// Bodies and the colliding pair. Body 1 is a sphere; body 2 is a sphere or a
// flat wall (infinite radius and mass). A wall is elastic and of body 2's
// material (which defaults to body 1's); an ideally rigid wall is an explicit
// choice (docs/decisions.md D1).

#include <algorithm>
#include <optional>
#include <string>

#include "bounce/pair/material.hpp"

namespace bounce {

struct Body {
  Material material;
  double radius = 0.0;          ///< [m]; +inf for a wall
  bool rigid = false;           ///< ideally rigid (no compliance): only for walls
  double inertia_factor = 0.4;  ///< J / (m R^2), BSHP96 (4); 2/5 for a solid sphere

  bool is_wall() const;
  double mass() const;          ///< [kg]; +inf for a wall
};

/// A homogeneous solid sphere.
Body sphere(Material material, double radius);
/// A flat elastic wall of `material`.
Body wall(Material material);
/// A flat, ideally rigid wall (its material only supplies the surface energy).
Body rigid_wall(Material material);

/// A pair of bodies with every pair quantity computed once by the mixing rules.
class Pair {
 public:
  /// Validates both bodies; throws InvalidArgument naming "body1.radius",
  /// "body2.E" etc. (front ends rename these to their own option names).
  Pair(Body body1, Body body2);
  /// Two identical spheres.
  static Pair identical(Material material, double radius);

  const Body& body1() const noexcept { return body1_; }
  const Body& body2() const noexcept { return body2_; }

  double effective_radius() const noexcept { return effective_radius_; }    ///< R_eff [m]
  double effective_mass() const noexcept { return effective_mass_; }        ///< m_eff [kg]
  double effective_modulus() const noexcept { return effective_modulus_; }  ///< E* [Pa]
  double hertz_compliance_d() const noexcept;                               ///< D = 3/(4E*) [1/Pa]
  double hertz_constant() const noexcept;                                   ///< rho [N/m^{3/2}]
  double tangential_mass_factor() const noexcept { return kappa_; }         ///< kappa, BSHP96 (8)
  /// E_soft [Pa], the smaller Young's modulus of the two bodies (a rigid wall's is not): K13
  /// Fig 7 (b) normalises the yield strength by it.
  double soft_modulus() const noexcept {
    return body2_.rigid ? body1_.material.youngs_modulus
                        : std::min(body1_.material.youngs_modulus, body2_.material.youngs_modulus);
  }
  /// Combined work of adhesion gamma [J/m^2], if both materials have one.
  std::optional<double> surface_energy() const noexcept { return surface_energy_; }
  /// gamma, or InvalidArgument("gamma", "(not given)", …) naming `law` as the
  /// one that needs it.
  double require_surface_energy(const std::string& law) const;
  /// The smaller transversal sound speed of the deforming bodies (BSHP96 (B3)) [m/s]: the
  /// quasi-static models hold for impact speeds well below it (BSHP96 (B11)).
  double transversal_sound_speed() const;

 private:
  Body body1_;
  Body body2_;
  double effective_radius_;
  double effective_mass_;
  double effective_modulus_;
  double kappa_;
  std::optional<double> surface_energy_;
};

}  // namespace bounce
