#pragma once
// Closed forms for adhesive and plastic collisions: K13 (22)-(33) and appendix A,
// BP04 (8.94)-(8.101). R = R_eff, m = m_eff, E* the pair modulus; SI units.

namespace bounce::analytic {

// --- elastic JKR collisions (K13 §3.3) ---------------------------------------------
/// Energy lost in an elastic JKR collision (snap-on at delta = 0, release at the
/// fold delta_c): U(a_c, delta_c) - U(a_snap, 0) on the JKR curve. Exactly
/// 7.09220 (gamma^5 R^4 / E*^2)^{1/3}; K13 (25) writes 14.18/2 = 7.09.
double jkr_collision_loss(double effective_radius, double effective_modulus, double gamma);
/// The exact constant 7.0921959718… of jkr_collision_loss.
double jkr_collision_loss_constant();
/// K13 (25) as printed: v_c = (14.18/m)^{1/2} (gamma^5 R^4 / E*^2)^{1/6}.
double sticking_velocity_k13(double effective_mass, double effective_radius, double effective_modulus,
                             double gamma);
/// The exact elastic JKR sticking velocity, sqrt(2 W / m) with W = jkr_collision_loss.
double sticking_velocity_jkr(double effective_mass, double effective_radius, double effective_modulus,
                             double gamma);
/// K13 (24): e_JKR = sqrt(1 - (v_c/v)^2) for v > v_c, 0 below.
double cor_jkr(double velocity, double sticking_velocity);
/// K13 (26) as printed: e_D = 1 - 5.57 A / t_H.
double cor_viscous_k13(double dissipative_constant, double hertz_time);
/// The exact first-order constant of (26): 2 b (15/8) t0 = 5.5679… (t0 = 2.943275).
double cor_viscous_constant();
/// K13 (27): e_I = sqrt(e_JKR^2 + e_D^2 - 1) (0 if the radicand is negative).
double cor_independent(double cor_jkr, double cor_viscous);

// --- plastic losses (K13 §3.4) -------------------------------------------------------
/// K13 (28): v_y^2 = 10.2 R^3 p_y^5 / (m E*^4) with p_y = 1.6 Y.
double yield_velocity(double effective_radius, double effective_mass, double effective_modulus,
                      double yield_strength);
/// The exact constant of (28): pi^5 / 30 = 10.2007 (central Hertz pressure p_y at the maximal overlap).
double yield_velocity_constant();
/// K13 (29), Thornton & Ning: e_P(v) with vhat = v_y / v (1 for v <= v_y).
double cor_thornton_ning(double velocity, double yield_velocity);
/// K13 (30): e = sqrt(e_A^2 + e_P^2 - 1); negative radicand: the grains stick (returns 0).
double cor_with_plastic(double cor_adhesive, double cor_plastic);
/// K13 (33): l = (15 m v^2 R^2 / (16 E*))^{1/5}, the maximal Hertz contact radius.
double plastic_length_scale(double effective_mass, double velocity, double effective_radius,
                            double effective_modulus);
/// K13 (32): Hall-Petch Y = Y0 + k l^{-n} (n = 0.5 classically).
double hall_petch_yield(double macroscopic_yield, double coefficient, double length, double exponent = 0.5);

// --- K13 appendix A: where viscous effects become negligible -------------------------
/// (A.2): bulk dissipation is negligible when T_vis < 1e-2 nu^2 t_c; returns that bound [s].
double bulk_quasi_static_limit(double poisson_ratio, double contact_time);
/// (A.4): adhesion hysteresis is negligible when T_vis < 1e-3 (z0/a)(2 E* z0 / gamma) t_c; the bound [s].
double crack_quasi_static_limit(double z0, double contact_radius, double effective_modulus, double gamma,
                                double contact_time);

// --- BP04's quasi-static estimate (§8.3.4) -------------------------------------------
/// BP04 (8.96): q0 = (1/10)(3 2^{1/3} - 1) 3^{2/3}.
double tensile_work_constant();
/// BP04 (8.95): W0 = q0 (pi^5 gamma^5 D^2 R^4)^{1/3}, the work of the tensile force from
/// a0 to a_sep, with BP04's R = 2 R_eff (formulas for identical spheres).
double tensile_work(double effective_radius, double effective_modulus, double gamma);
/// BP04 (8.98): e_ad = sqrt(e^2 g^2 - 2 W0/m) / g (0 when the radicand is negative).
double cor_adhesive_bp04(double cor_viscoelastic, double velocity, double tensile_work, double effective_mass);
/// BP04 (8.101): g_st = sqrt(2 W0/m) [1 + C1 A kappa^{2/5} (2 W0/m)^{1/10}], leading order in A,
/// with kappa of (8.73) (here (3/2)^{5/2} C0 / m).
double sticking_velocity_bp04_leading(double tensile_work, double effective_mass, double dissipative_constant,
                                      double force_constant);

}  // namespace bounce::analytic
