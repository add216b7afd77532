#pragma once
// A model's normal law as a DEM law: the same physics as the law its collision engine
// integrates (normal_force.hpp, K13's JKR branch for jkr-viscoelastic, the crack law for krijt)
// with the two bodies' radii and masses given per contact, as a DEM code (LAMMPS's pair_style
// bounce, docs/lammps.md) has grains of many sizes, instead of fixed by a Pair. The model's
// factory makes it beside that law (model.hpp), once per pair of materials; a DEM step
// (bounce::dem) evaluates it per contact.
//
// Each law's formula is written once, as a function of the force constant and the geometry,
// and both forms call it.

#include <memory>
#include <optional>
#include <string>

#include "bounce/contact/resistance.hpp"
#include "bounce/models/end_rule.hpp"
#include "bounce/models/tangential.hpp"

namespace bounce::models {

/// What changes from contact to contact.
struct ContactGeometry {
  double effective_radius = 0.0;  ///< R_eff = R1 R2 / (R1 + R2) (R1 against a flat wall) [m]
  double effective_mass = 0.0;    ///< m_eff = m1 m2 / (m1 + m2) (m1 against a wall) [kg]
};

class DemLaw {
 public:
  virtual ~DemLaw() = default;
  /// Total normal force [N] (positive = repulsive) at overlap xi and rate xi' of a contact
  /// that exists (for adhesive laws, down to release_overlap()).
  virtual double force(const ContactGeometry& g, double overlap, double rate) const = 0;
  /// Energy stored in the contact [J] (elastic, plus surface energy for adhesive laws),
  /// 0 where it forms: for energy tallies.
  virtual double energy(const ContactGeometry& g, double overlap) const = 0;
  /// The overlap (<= 0) down to which an established contact holds: 0 for laws without a
  /// neck; JKR's fold delta_c or its pull-off point.
  virtual double release_overlap(const ContactGeometry& g) const {
    (void)g;
    return 0.0;
  }
  /// The overlap (<= 0) at which an approaching pair's contact forms: 0 (touching), or before,
  /// where an attraction of finite range pulls the surfaces together (Maugis-Dugdale's h0).
  virtual double snap_overlap(const ContactGeometry& g) const {
    (void)g;
    return 0.0;
  }
};

/// What a contact whose radius is a variable of its own (DemCrackLaw) carries from step to
/// step.
struct CrackState {
  double contact_radius = 0.0;   ///< a [m]
  double previous_radius = 0.0;  ///< a one step before [m]: for a second-order update
  double previous_step = 0.0;    ///< that step's length [s] (0: none)
  double older_radius = 0.0;     ///< a two steps before, if that step was as long [m] (0: none)
};

/// What a step did to such a contact.
struct CrackAdvance {
  double dissipated = 0.0;  ///< energy the crack's motion released [J] (>= 0)
  bool broken = false;      ///< the contact ended inside the step
};

/// How DemCrackLaw::advance may divide a step in which the crack moves fast.
enum class Refinement {
  none,           ///< not at all: the caller divides the step already
  full,           ///< where its error estimate asks for it, and where one step breaks the contact
  unless_broken,  ///< as `full`, but a step that one step breaks is returned broken, undivided:
                  ///< the caller divides it (a DEM's breaking step, which it times itself)
};

/// A contact law whose contact radius a is independent of the overlap and moves by a crack law
/// (K13's): its force depends on (a, xi, xi'), and a DEM keeps a per contact between steps.
class DemCrackLaw {
 public:
  virtual ~DemCrackLaw() = default;
  /// The state where the contact forms, at overlap 0; `dissipated` the energy the formation
  /// released (K13 appendix B).
  virtual CrackState form(const ContactGeometry& g, double& dissipated) const = 0;
  /// Moves the contact radius over a step dt, in which the overlap went from `before` to
  /// `overlap`, to the step's end; stable for any dt, and of second order in dt along steps of
  /// about one length. The energy it released is that of the
  /// change of a at fixed overlap, averaged over the step's two overlaps, so that the rest of
  /// the change of the contact's energy is the trapezoidal work of its elastic force (the energy
  /// budget of a DEM closes to second order in dt).
  /// `refine`: whether a step in which the crack moves fast may be taken as several.
  virtual CrackAdvance advance(const ContactGeometry& g, double before, double overlap, double dt, CrackState& s,
                               Refinement refine = Refinement::full) const = 0;
  /// The elastic force [N] (positive: repulsive) and the bulk force's coefficient D [kg/s]:
  /// the total force is elastic + D xi'.
  struct Force {
    double elastic = 0.0;
    double damping = 0.0;
  };
  virtual Force force(const ContactGeometry& g, double overlap, const CrackState& s) const = 0;
  /// The elastic and the surface energy of the contact [J] (each 0 where a = 0).
  virtual double elastic_energy(const ContactGeometry& g, double overlap, const CrackState& s) const = 0;
  virtual double surface_energy(const ContactGeometry& g, const CrackState& s) const = 0;
  /// An overlap (< 0) below which no contact holds, whatever its radius: how far a DEM's
  /// neighbour search must reach beyond touching.
  virtual double release_overlap(const ContactGeometry& g) const = 0;
};

/// Rolling, sliding and twisting of the contact (Dominik & Tielens, W07; contact/resistance.hpp,
/// docs/resistance.md), each turned on by itself: springs on the contact pointers and twist, with
/// constants from each contact's R_eff.
struct ResistanceModel {
  contact::resistance::Materials materials;
  double xi_crit = contact::resistance::standard_critical_rolling;  ///< [m]
  bool rolling = false, sliding = false, twisting = false;
};

/// A model as a DEM contact law for one pair of materials (models::make_dem_model): its
/// normal law is `normal`, or `crack` for a law with a contact radius of its own (krijt).
struct DemModel {
  std::string name;                            ///< the registry keyword
  std::shared_ptr<const DemLaw> normal;
  std::shared_ptr<const DemCrackLaw> crack;
  /// The overlap (<= 0) below which no contact of this law holds (its normal or crack law's).
  double release_overlap(const ContactGeometry& g) const {
    return crack ? crack->release_overlap(g) : normal->release_overlap(g);
  }
  /// The overlap (<= 0) at which an approaching pair's contact forms (a crack law's: touching).
  double snap_overlap(const ContactGeometry& g) const { return crack ? 0.0 : normal->snap_overlap(g); }
  EndRule end_rule = EndRule::overlap;         ///< force: the force is never attractive
  std::optional<TangentialModel> tangential;   ///< with a friction coefficient
  std::optional<ResistanceModel> resistance;   ///< with rolling, sliding or twisting
};

}  // namespace bounce::models
