#pragma once
// A model's normal interaction as a DEM contact law: the same physics as the model's force
// (normal_force.hpp, and K13's JKR branch for jkr-viscoelastic) with the two bodies' radii and
// masses given per contact, as a DEM code (LAMMPS's pair_style bounce, docs/lammps.md) has
// grains of many sizes, instead of fixed by a Pair. A registry row's `contact_law` factory
// makes it once per pair of materials; a DEM step evaluates it per contact.
//
// Each law's formula is written once, as a function of the force constant and the geometry,
// and both the model's NormalForceModel and its ContactLaw call it.

#include <memory>
#include <optional>
#include <string>

#include "bounce/models/end_rule.hpp"
#include "bounce/models/tangential.hpp"

namespace bounce::models {

/// What changes from contact to contact.
struct ContactGeometry {
  double effective_radius = 0.0;  ///< R_eff = R1 R2 / (R1 + R2) (R1 against a flat wall) [m]
  double effective_mass = 0.0;    ///< m_eff = m1 m2 / (m1 + m2) (m1 against a wall) [kg]
};

class ContactLaw {
 public:
  virtual ~ContactLaw() = default;
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
};

/// A model as a DEM contact law for one pair of materials (models::make_contact_law).
struct DemModel {
  std::string name;                            ///< the registry keyword
  std::shared_ptr<const ContactLaw> normal;
  EndRule end_rule = EndRule::overlap;         ///< force: the force is never attractive
  std::optional<TangentialModel> tangential;   ///< with a friction coefficient
};

}  // namespace bounce::models
