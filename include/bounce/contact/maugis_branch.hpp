#pragma once
// The whole Maugis-Dugdale equilibrium curve of one lambda, as a colliding pair meets it
// (docs/contact.md, "Maugis-Dugdale along a collision"; the non-dimensional units of maugis.hpp:
// A = a/l, C = c/l, P = F/(pi w R), Delta = delta R/l^2, energies in pi w l^2).
//
// Two parts, one curve, parameterised by tau in [0, 2):
//  * before contact (tau <= 1): the Dugdale zone alone, of radius C = tau C0, pulls the
//    surfaces together while their gap at the centre is still open. With a uniform tension
//    sigma0 over r < c (displacement of the two surfaces (4 sigma0 c/(pi E*)) E(r/c)) and the
//    gap h0 = w/sigma0 at r = c:
//        P = -(pi lambda / 2) C^2,   Delta = C^2/2 - (8 lambda/(3 pi)) C - 2/(pi lambda);
//    it starts at the range of the attraction, Delta = -h0 = -2/(pi lambda), C = 0, and reaches
//    the centre's touching at C0, the root of (pi lambda/4) C^2 + (2/3)(pi - 2) lambda^2 C = 1,
//    which is (MD1) at A = 0: there it joins
//  * contact (1 < tau < 2): (MD1)-(MD3) of maugis.hpp at zone parameter s = sqrt(m^2 - 1) =
//    tan((2 - tau) pi/2), from s = inf (A = 0) to s = 0 (A = inf); (MD1) is a quadratic in A at
//    given s, so every point is explicit.
// Under displacement control the curve's states are stable where Delta rises along it (tau
// > tau_fold: the fold is Delta's one minimum, the Maugis jump-off). An approaching pair is
// separated (no force) until Delta = -h0, where the zone's start is unstable (Delta falls as C
// grows): it jumps onto the stable part there (the snap-on). A separating pair follows the stable
// part down to the fold and jumps off, out of the attraction's range. Each jump dissipates the
// energy difference at its overlap; in the JKR limit they are JKR's snap-on at Delta = 0 and
// its fold, in the DMT limit (lambda -> 0) they vanish (the curve is stable nearly everywhere).
//
// The energy of a state (elastic plus adhesive, 0 when separated) is the work of the force along
// the curve from its start, U(tau) = int_0^tau P dDelta: closed form before contact; in contact,
// over x = ln s, a table of the integral at nodes 0.05 apart (one 15-point Gauss-Kronrod rule a
// cell, made with the curve) plus the rule over the part of a cell. The adhesive part alone, U_S = -C^2 + lambda dU/dlambda at fixed Delta (the Dugdale
// potential -w + sigma0 h for h < h0 is linear in sigma0 at fixed fields, and U is stationary in
// them), by a central difference in lambda.

#include <mutex>
#include <vector>

namespace bounce::contact::maugis {

struct BranchPoint {
  double contact_radius = 0.0;  ///< A (0 before contact)
  double zone_radius = 0.0;     ///< C
  double force = 0.0;           ///< P
  double overlap = 0.0;         ///< Delta
};

/// A state on the curve: before contact, by its zone radius C; in contact, by theta = atan s
/// (s = sqrt(m^2 - 1), which falls from inf at A = 0 to 0 as A grows; theta keeps s's relative
/// precision where s is small, i.e. for large contacts).
struct Place {
  bool contact = false;
  double value = 0.0;  ///< C, or theta in (0, pi/2)
};

class Branch {
 public:
  /// lambda > 0 (Maugis' parameter, contact::surface::maugis_parameter).
  explicit Branch(double lambda);
  double lambda() const noexcept { return lambda_; }

  BranchPoint at(const Place& place) const;
  /// The curve parameter tau in [0, 2) of the header (before contact C/C0, in contact 2 - 2 theta/pi):
  /// for ordering states along the curve.
  double order(const Place& place) const;
  /// The place tau of the header (for tests and sampling: theta loses digits near tau = 2).
  Place place(double tau) const;

  /// The stable state at overlap Delta (the last place along the curve with that Delta);
  /// Delta <= fold().overlap gives the fold.
  Place place_at_overlap(double overlap) const;
  BranchPoint at_overlap(double overlap) const { return at(place_at_overlap(overlap)); }

  /// Where the pair snaps on: Delta = -h0 = -2/(pi lambda), the start of the curve.
  double snap_overlap() const noexcept { return snap_overlap_; }
  /// The fold (the least Delta along the curve): where the contact jumps off.
  const BranchPoint& fold() const noexcept { return fold_; }
  const Place& fold_place() const noexcept { return fold_place_; }
  /// The least force along the stable part (the pull-off force under force control).
  const BranchPoint& pull_off() const noexcept { return pull_off_; }
  const Place& pull_off_place() const noexcept { return pull_off_place_; }

  /// The overlap of the stable state without force (P = 0: in contact, beyond the pull-off).
  double zero_force_overlap() const;

  /// U: the energy of the state, in pi w l^2 (0 at the curve's start).
  double energy(const Place& place) const;
  double energy_at_overlap(double overlap) const { return energy(place_at_overlap(overlap)); }
  /// U_S of the stable state at overlap Delta, in pi w l^2, from the curves at lambda (1 -+
  /// lambda_step) (made once by their caller: a Branch costs two minimum searches).
  double surface_energy_at_overlap(double overlap, const Branch& down, const Branch& up) const;
  static constexpr double lambda_step = 1e-5;

 private:
  double lambda_;
  double zone_at_touch_;  // C0
  double snap_overlap_;
  Place fold_place_, pull_off_place_;
  BranchPoint fold_, pull_off_;
  // int from x_i to the top node of -P dDelta/dx, x_i = top - i spacing: made at the first
  // energy asked for (a DEM law asks for forces only), once whatever the threads.
  const std::vector<double>& work() const;
  mutable std::once_flag work_made_;
  mutable std::vector<double> work_;
};

}  // namespace bounce::contact::maugis
