#pragma once
// JKR adhesive contact of elastic spheres.
//
// Two notations, both kept because both papers are used:
//  * K13 (6)-(10), written with the reduced radius R = R_eff and E*;
//  * BP04 (8.46)-(8.52), written for identical spheres of radius R with
//    D = 3/(4E*); for a general pair BP04 says to substitute R -> 2 R_eff.
// Tests check that the two agree for unlike pairs.

namespace bounce::contact::jkr {

struct Parameters {
  double effective_radius = 0.0;   ///< R_eff [m]
  double effective_modulus = 0.0;  ///< E* [Pa]
  double surface_energy = 0.0;     ///< gamma, work of adhesion [J/m^2]
};

// --- K13 notation --------------------------------------------------------------
/// K13 (8): delta = a^2/R - sqrt(2 pi gamma a / E*).
double overlap(const Parameters& p, double contact_radius);
/// K13 (9): F = 4 E* a^3/(3R) - sqrt(8 pi gamma E* a^3).
double force(const Parameters& p, double contact_radius);
/// K13 (10): a_eq = (9 pi gamma R^2 / (2 E*))^{1/3}, the radius at zero force.
double equilibrium_contact_radius(const Parameters& p);
/// K13 after (10): F_c = -(3/2) pi gamma R, the pull-off force under force control.
double pull_off_force(const Parameters& p);
/// Contact radius at pull-off under force control, dF/da = 0: a_eq / 4^{1/3} (BP04 (8.52)).
double pull_off_contact_radius(const Parameters& p);
/// Contact radius where the contact breaks under displacement control (and in a
/// free collision): d delta/da = 0, a_eq / 6^{2/3}.
double separation_contact_radius(const Parameters& p);
/// The overlap there, delta_c = -(3/4) (pi^2 gamma^2 R / E*^2)^{1/3}: the most
/// negative overlap at which the spheres still touch.
double separation_overlap(const Parameters& p);
/// The overlap at pull-off, K13 (8) at the pull-off radius: where LAMMPS's pair granular jkr
/// ends a contact (contact_end pull-off), before the fold delta_c.
double pull_off_overlap(const Parameters& p);
/// Inverse of (9) on the stable branch: BP04 (8.47) in K13 notation,
/// a^3 = (3R/4E*) (F + 3 pi gamma R + sqrt(6 pi gamma R F + (3 pi gamma R)^2)), F >= F_c.
double contact_radius_from_force(const Parameters& p, double force);
/// Inverse of (8) on the branch stable under displacement control (d delta/da > 0),
/// delta >= delta_c.
double contact_radius_from_overlap(const Parameters& p, double overlap);
/// The same inverse, fast: the JKR branch stable under displacement control as the collision
/// engine (jkr-viscoelastic) and the DEM contact law evaluate it at every step. With u = sqrt(a),
/// K13 (8) is u^4 - c R u - R delta = 0, c = sqrt(2 pi gamma / E*); Newton from above converges
/// monotonically (the quartic is convex for u > u_c). Overlaps below delta_c give a_c.
class DisplacementBranch {
 public:
  explicit DisplacementBranch(const Parameters& p);
  double radius(double overlap) const;

 private:
  double r_, c_, u_fold_;
};
/// Elastic plus surface energy on the JKR curve, U_E(a, delta(a)) - pi a^2 gamma, K13 (3)+(6).
double total_energy(const Parameters& p, double contact_radius);
/// Snap-on radius at first touch (delta = 0): a = (2 pi gamma R^2 / E*)^{1/3} (K13 (8) with delta = 0).
double snap_on_contact_radius(const Parameters& p);

// --- BP04 notation (identical spheres of radius R_sphere; general pair: 2 R_eff) ---
namespace bp04 {
/// BP04 (8.46): F_B = -2 pi a^2 sqrt(3 gamma / (2 pi D a)).
double boussinesq_force(double d, double gamma, double contact_radius);
/// BP04 (8.47): contact radius for total force F.
double contact_radius(double d, double gamma, double radius, double force);
/// BP04 (8.48): xi = 2 a^2/R - sqrt(8 pi gamma D a / 3).
double compression(double d, double gamma, double radius, double contact_radius);
/// BP04 (8.49): F(a) = 2 a^3/(D R) - sqrt(6 pi gamma / D) a^{3/2}.
double force(double d, double gamma, double radius, double contact_radius);
/// BP04 (8.50): a0^3 = (3/2) D pi gamma R^2.
double zero_load_contact_radius(double d, double gamma, double radius);
/// BP04 (8.51): F_sep = -(3/4) pi gamma R.
double separation_force(double gamma, double radius);
/// BP04 (8.52): a_sep^3 = (3/8) D pi gamma R^2 = a0^3/4.
double separation_contact_radius(double d, double gamma, double radius);
}  // namespace bp04

}  // namespace bounce::contact::jkr
