#pragma once
// Contact of two smooth convex bodies with principal radii of curvature
// (BP04 §8.2.1, (8.6)-(8.21)). The contact area is an ellipse with semi-axes
// a (along the B1 direction) and b; F = C0 xi^{3/2} for every convex pair.
//
// Correction (found while implementing; see docs/contact.md): (8.21) as printed,
// C0 = (pi/D) (M/(B1 x0 N))^{1/2}, is not consistent with (8.19)-(8.20) and
// misses Hertz by a factor pi for spheres. Eliminating b from (8.19)-(8.20)
// gives C0 = (pi/D) (M(x0) / (B1 x0 N(x0)^3))^{1/2}, which reproduces (8.24).

#include <optional>
#include <span>

#include "bounce/core/parameters.hpp"

namespace bounce::contact::convex {

/// Principal radii of curvature of both bodies at the contact point [m], and
/// the angle phi [rad] between the planes of R1 and R1'. A flat direction has
/// an infinite radius (a wall has R1' = R2' = inf).
struct Curvatures {
  double radius1 = 0.0;        ///< R1 of body 1 [m]
  double radius2 = 0.0;        ///< R2 of body 1 [m]
  double radius1_prime = 0.0;  ///< R1' of body 2 [m]
  double radius2_prime = 0.0;  ///< R2' of body 2 [m]
  double angle = 0.0;          ///< phi [rad]
};

/// The geometric constants B1 >= B2 of BP04 (8.7) [1/m].
struct QuadraticForm {
  double b1 = 0.0;
  double b2 = 0.0;
};

/// BP04 (8.7). Throws InvalidArgument if a radius is <= 0 or if B2 = 0 (no
/// point contact: e.g. two parallel cylinders).
QuadraticForm quadratic_form(const Curvatures& curvatures);

/// BP04 (8.15): N(x) = int_0^inf dt / sqrt((1 + x t)(1 + t) t) = 2 R_F(0, x, 1).
double n_function(double x);
/// BP04 (8.16): M(x) = int_0^inf dt / ((1 + t) sqrt((1 + t)(1 + x t) t))
///            = (2/3) x R_D(0, 1, x)   (Carlson's symmetric integrals).
double m_function(double x);
/// Right-hand side of BP04 (8.18): sqrt(x) M(1/x) / M(x).
double axis_ratio_function(double x);
/// BP04 (8.18): the root x0 = a^2/b^2 of B2/B1 = sqrt(x) M(1/x)/M(x); x0 <= 1.
double axis_ratio_squared(const QuadraticForm& form);

/// Everything BP04 (8.19)-(8.21) gives for a pair of convex bodies.
struct ConvexContact {
  QuadraticForm form;
  double x0 = 1.0;             ///< a^2/b^2
  double n_x0 = 0.0;           ///< N(x0)
  double m_x0 = 0.0;           ///< M(x0)
  double force_constant = 0.0; ///< C0 [N/m^{3/2}], F = C0 xi^{3/2} (corrected (8.21))
};

/// D = 3/(4 E*) of BP04 (8.14).
ConvexContact solve(const Curvatures& curvatures, double hertz_compliance_d);

/// F = C0 xi^{3/2}, BP04 (8.21).
double force(const ConvexContact& contact, double overlap);

/// The contact ellipse at overlap xi: BP04 (8.19) gives b = F D N(x0)/(pi xi), a = sqrt(x0) b.
struct Ellipse {
  double semi_axis_a = 0.0;  ///< along the B1 direction [m]
  double semi_axis_b = 0.0;  ///< [m]
};
Ellipse ellipse(const ConvexContact& contact, double hertz_compliance_d, double overlap);

/// The shape as parameters: curvature_radii "R1,R2" of body 1, curvature_radii2 of body 2,
/// angle phi (shared by the hertz contact law and the collision models of convex bodies).
std::span<const ParameterSpec> shape_parameters();
/// The curvatures given, if any (InvalidArgument without curvature_radii): body 2 is shaped
/// like body 1 unless given, or flat when it is a wall.
std::optional<Curvatures> curvatures_from(const Parameters& parameters, bool body2_is_wall);

}  // namespace bounce::contact::convex
