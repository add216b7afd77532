#pragma once
// Closed forms of the viscoelastic collision (BP04 §8.3.2-8.3.3, BSHP96 (A13), K13 (22)).
//
// Notation: C0 is the force constant (rho = (4/3) E* sqrt(R_eff) for spheres,
// BP04 (8.21) for convex bodies), A the dissipative constant [s], m = m_eff,
// g the impact speed, kappa the dimensionless damping of BP04 (8.70), and
// q = (g/g*)^{1/5} = 2 b kappa the expansion variable of BP04 (8.87)-(8.89).

#include <array>
#include <vector>

namespace bounce::analytic {

/// BP04 (8.81): b = int_0^1 sqrt(x) sqrt(1 - x^{5/2}) dx = sqrt(pi) Gamma(3/5) / (5 Gamma(21/10)).
double b_constant();
/// BP04 (8.70): kappa = (3/2) (5/4)^{3/5} A (C0/m)^{2/5} g^{1/5} (with BP04's misprinted
/// (rho^eff/m)^{2/5} read as (C0/m_eff)^{2/5}).
double kappa(double dissipative_constant, double force_constant, double effective_mass, double speed);
/// Inverse of (8.70): the impact speed at which kappa is reached.
double speed_for_kappa(double kappa, double dissipative_constant, double force_constant,
                       double effective_mass);
/// BP04 (8.88): the characteristic velocity g* [m/s]; kappa = (g/g*)^{1/5} / (2b) (8.87).
double characteristic_velocity(double dissipative_constant, double force_constant, double effective_mass);
/// q = (g/g*)^{1/5} = 2 b kappa (8.87).
double expansion_variable(double kappa);

/// BP04 (8.85): the root of e + 2 kappa b e^{3/5} = 1 (the approximate implicit law).
double cor_implicit(double kappa);
/// BP04 (8.86): e^-1 = 1 + 2 kappa b (1 + 2 kappa b (1 + …)^{2/5})^{2/5}, `depth` levels.
double cor_continued_fraction(double kappa, int depth = 64);

/// Coefficients a_k of BP04 (8.89), e = 1 - a1 q + a2 q^2 - a3 q^3 + a4 q^4 -+ …
struct IntegerSeries {
  std::vector<double> a;            ///< a_1, a_2, … (a.size() terms)
  std::vector<double> uncertainty;  ///< one per a_k (0 where exact)
};
/// BP04's simple derivation: a1 = 1, a2 = 3/5, a3 = 6/25, a4 = 7/125.
IntegerSeries bp04_simple_series();
/// BP04's quoted "rigorous" values: a1 = 1, a2 = 3/5, a3 = 0.315, a4 = 0.161.
IntegerSeries bp04_rigorous_series();
/// bounce's coefficients for the overlap end rule, fitted at build time to the
/// long-double master curve (with uncertainties; docs/viscoelastic.md).
IntegerSeries master_series_overlap();
/// (8.89) truncated after a.size() terms.
double cor_series(double q, const IntegerSeries& series);

/// The force end rule adds half-integer powers: e_force = e_overlap +
/// kappa^{5/2} (d0 + d1 kappa + d2 kappa^2 + …), d0 = 32/(75 sqrt 5) exactly
/// (the work of the attractive tail the overlap rule integrates through).
struct ForceRuleCorrection {
  std::vector<double> d;
  std::vector<double> uncertainty;
};
ForceRuleCorrection master_series_force_correction();
/// e under the force rule from the series: cor_series(q, overlap) + correction.
double cor_series_force(double kappa, const IntegerSeries& overlap, const ForceRuleCorrection& correction);

/// BP04 (8.92)-(8.93): the 1-4 Pade approximant in q with d_k from a2, a3, a4 (a1 = 1).
struct PadeCoefficients {
  double d0, d1, d2, d3, d4, d5;
};
PadeCoefficients pade_coefficients(double a2, double a3, double a4);
PadeCoefficients pade_coefficients(const IntegerSeries& series);
/// BP04 (8.93) as printed: d1..d5 = 2.583, 3.583, 2.983, 1.148, 0.326 (d0 = -0.029); the
/// curve of BP04 Fig 8.2 (docs/viscoelastic.md compares them with (8.93) applied to a_k).
PadeCoefficients bp04_printed_pade();
/// BP04 (8.92): e = (1 + d1 q) / (1 + d2 q + d3 q^2 + d4 q^3 + d5 q^4).
double cor_pade(double q, const PadeCoefficients& d);

/// BP04 (8.91): C1 = sqrt(pi) Gamma(3/5) / (2^{1/5} 5^{2/5} Gamma(21/10)); C_i = a_i C1^i (8.90).
double c1_constant();

// --- Hertz contact times ---------------------------------------------------------
// The exact Hertz contact time and its constant are contact::hertz::collision_time and
// scaled_collision_time (2.943275…).
/// BSHP96 (A13) as printed: 2.94 (m/k)^{2/5} g^{-1/5}, k = (4/5) C0.
double hertz_contact_time_bshp96(double force_constant, double effective_mass, double speed);
/// K13 (22) as printed: t_H = 2.87 (m^2 / (R E*^2 v))^{1/5}.
double hertz_contact_time_k13(double effective_mass, double effective_radius, double effective_modulus,
                              double speed);
/// The exact constant of K13 (22): 2.943275 (15/16)^{2/5} = 2.8683…
double hertz_contact_time_k13_constant();

// --- power-law forces, BP04 (8.63)-(8.69) -----------------------------------------
/// BP04 (8.68): kappa = D2 ((1+alpha)/(2 D1))^{(1+gamma)/(1+alpha)} g^{2(gamma-alpha)/(1+alpha)+beta}.
double power_law_kappa(double d1, double alpha, double d2, double beta, double gamma, double speed);
/// BP04 (8.69): the exponent of g in (8.68); the COR is independent of g iff it is zero.
double power_law_velocity_exponent(double alpha, double beta, double gamma);

}  // namespace bounce::analytic
