#pragma once
// The geometry of an adhesive contact held on its equilibrium branch (a crack with no time of its
// own): JKR's (K13 (8), (9), (3) + (6)) or Maugis-Dugdale's (contact/maugis_branch.hpp). A
// strategy: the collision engine of the models that hold their contact there (dynamics,
// integrate_adhesive_collision) and their DEM laws (dem_law.hpp) ask it the same questions.
//
// On the branch stable under displacement control the state is a function of the overlap delta:
// contact radius, force, energies. An approaching pair jumps onto it at snap_overlap() (JKR: when
// the surfaces touch; Maugis-Dugdale: when they come within the attraction's range h0), a
// separating pair leaves it at the fold (the least overlap the branch reaches) or, as LAMMPS ends
// a JKR contact, at the pull-off point (the least force); each jump dissipates the contact's
// energy difference.

#include <memory>
#include <string_view>

namespace bounce::models {

/// Where a contact held on its branch breaks.
enum class AdhesiveRelease {
  fold,      ///< the least overlap of the branch (d delta/da = 0; JKR's delta_c, K13 (25))
  pull_off,  ///< the least force along it (JKR: -(3/2) pi gamma R; LAMMPS's pair granular jkr)
};

class AdhesiveGeometry {
 public:
  virtual ~AdhesiveGeometry() = default;
  virtual std::string_view name() const = 0;

  /// The state at overlap delta >= release_overlap(fold) (below it: the fold's).
  struct State {
    double contact_radius = 0.0;  ///< a [m] (0 where the surfaces do not touch yet)
    double force = 0.0;           ///< F_E [N], elastic and adhesive (positive: repulsive)
  };
  virtual State state(double overlap) const = 0;
  double contact_radius(double overlap) const { return state(overlap).contact_radius; }
  double force(double overlap) const { return state(overlap).force; }
  /// U_E [J], the elastic part of the contact's energy, and U_S [J] (<= 0), the adhesive part.
  virtual double elastic_energy(double overlap) const = 0;
  virtual double surface_energy(double overlap) const = 0;
  /// U_E + U_S [J], 0 for the separated pair.
  virtual double energy(double overlap) const { return elastic_energy(overlap) + surface_energy(overlap); }

  /// The least energy along the branch [J] (< 0), at its state of zero force: how much kinetic
  /// energy the attraction can give a collision beyond its impact energy.
  virtual double least_energy() const = 0;
  /// The overlap of that state [m]: where a sticking pair settles.
  virtual double equilibrium_overlap() const = 0;

  /// Where an approaching pair jumps onto the branch (<= 0).
  virtual double snap_overlap() const = 0;
  /// Where a separating pair leaves it.
  virtual double release_overlap(AdhesiveRelease release) const = 0;
};

/// JKR's branch of a pair: R_eff [m], E* [Pa], gamma [J/m^2] (work of adhesion).
std::shared_ptr<const AdhesiveGeometry> jkr_geometry(double effective_radius, double effective_modulus,
                                                     double surface_energy);
/// Maugis-Dugdale's, lambda from z0 [m] as `bounce contact --law maugis` has it
/// (contact::surface::maugis_parameter).
std::shared_ptr<const AdhesiveGeometry> maugis_geometry(double effective_radius, double effective_modulus,
                                                        double surface_energy, double z0);

}  // namespace bounce::models
