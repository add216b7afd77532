#pragma once
// Normal force laws F(xi, d xi/dt) between two colliding bodies (SI units).
//
// One class per law, each in its own file with its registry factory (registry.hpp):
//   hertz                 F = C0 xi^{3/2}                               BP04 (8.21), (8.24)
//   viscoelastic          F = C0 (xi^{3/2} + (3/2) A sqrt(xi) xi')      BP04 (8.37), (8.42); BSHP96 (24)
//   viscoelastic-shifted  F = C0 max(xi + A xi', 0)^{3/2}               BSHP96 (25), clamped at zero
//   power-law             F = m_eff (D1 xi^alpha + D2 xi^gamma xi'^beta)  BP04 (8.63)
// C0 is the Hertz constant rho = (4/3) E* sqrt(R_eff) for spheres, or the
// constant of BP04 (8.21) for general convex bodies.

#include <memory>
#include <string_view>

namespace bounce::models {

class NormalForceModel {
 public:
  virtual ~NormalForceModel() = default;
  virtual std::string_view name() const = 0;
  /// Total normal force [N] (positive = repulsive); zero out of contact (overlap <= 0).
  virtual double force(double overlap, double rate) const = 0;
  /// Conservative part of the force [N].
  virtual double elastic_force(double overlap) const = 0;
  /// Its potential U(xi) [J], U(0) = 0.
  virtual double elastic_energy(double overlap) const = 0;
  /// The adhesive part of that potential [J] (<= 0; 0 for laws without adhesion): an energy
  /// budget reports it as surface_remaining and the rest as elastic_remaining.
  virtual double adhesive_energy(double overlap) const {
    (void)overlap;
    return 0.0;
  }
  /// A continuous function with the sign of the total force while in contact,
  /// smooth where the force vanishes (used to locate F = 0 for the `force` end
  /// rule). It must not jump at overlap = 0: event location assumes continuity.
  virtual double force_sign(double overlap, double rate) const { return force(overlap, rate); }
  /// Contact radius [m] at this overlap (Hertz geometry; equal-area circle for ellipses).
  virtual double contact_radius(double overlap) const = 0;
  /// BP04 (8.65): the maximal overlap xi0 of an elastic collision at impact speed g [m].
  virtual double reference_overlap(double speed) const = 0;
  /// Adhesive laws have a negative potential near contact; the engine then also
  /// stops when U_K + U(xi) < 0 (the grains can never separate: they stick).
  virtual bool adhesive() const { return false; }
  /// Overlap [m] at which the contact starts and ends: 0, or a small cutoff for a
  /// force that is singular at xi = 0 (BP04 footnote 2).
  virtual double cutoff_overlap(double speed) const { (void)speed; return 0.0; }
  /// Refuses an impact speed g at which the law cannot be integrated (an InvalidArgument naming
  /// the parameter to change); every g by default.
  virtual void check_speed(double speed) const { (void)speed; }
};

/// BP04 (8.65) for an elastic force m D1 xi^alpha: the maximal overlap at impact speed g,
/// xi0 = ((1 + alpha) / (2 D1))^{1/(1+alpha)} g^{2/(1+alpha)}.
double power_law_reference_overlap(double d1, double alpha, double speed);

/// Geometry and inertia shared by the Hertz-type laws.
struct HertzGeometry {
  double force_constant = 0.0;      ///< C0 [N/m^{3/2}] (rho for spheres)
  double equivalent_radius = 0.0;   ///< R with a^2 = R xi (R_eff for spheres) [m]
  double effective_mass = 0.0;      ///< m_eff [kg]
};

/// BP04 (8.42) / BSHP96 (24) with dissipative constant A [s] (A = 0: Hertz).
std::unique_ptr<NormalForceModel> make_viscoelastic_force(const HertzGeometry& geometry,
                                                          double dissipative_constant,
                                                          std::string_view name = "viscoelastic");
/// BSHP96 (25): the elastic law at the shifted overlap xi + A xi', clamped at zero force.
std::unique_ptr<NormalForceModel> make_shifted_viscoelastic_force(const HertzGeometry& geometry,
                                                                  double dissipative_constant);

/// BP04 (8.63): F = m_eff (D1 xi^alpha + D2 xi^gamma sgn(xi') |xi'|^beta).
struct PowerLawParameters {
  double d1 = 0.0;     ///< D1 [m^{1-alpha}/s^2]
  double alpha = 1.5;  ///< elastic exponent
  double d2 = 0.0;     ///< D2 [m^{1-gamma-beta} s^{beta-2}]
  double beta = 1.0;   ///< rate exponent
  double gamma = 0.5;  ///< overlap exponent of the dissipative term
};
std::unique_ptr<NormalForceModel> make_power_law_force(const PowerLawParameters& parameters,
                                                       double effective_mass,
                                                       double equivalent_radius);

/// BP04's quasi-static estimate for adhesive viscoelastic spheres (§8.2.3):
///   F_el  = rho xi^{3/2} - C xi^{3/4},  C = sqrt(6 pi gamma / D) R_eff^{3/4}        (8.56)
///   F_dis = (3/2) A rho sqrt(xi) xi' + (3/4) B C xi' xi^{-1/4}                       (8.57)
/// with B of (8.58) as corrected in docs/decisions.md D7. The xi^{-1/4} term is integrable but
/// singular: the contact starts and ends at xi = cutoff_fraction * xi0 (footnote 2).
struct AdhesiveViscoelasticParameters {
  double rho = 0.0;              ///< Hertz constant [N/m^{3/2}]
  double adhesion = 0.0;         ///< C of (8.56) [N/m^{3/4}]
  double a = 0.0;                ///< A [s]
  double b = 0.0;                ///< B [s]
  double effective_mass = 0.0;
  double effective_radius = 0.0;
  double cutoff_fraction = 1e-12;
};
std::unique_ptr<NormalForceModel> make_adhesive_viscoelastic_force(const AdhesiveViscoelasticParameters& p);

}  // namespace bounce::models
