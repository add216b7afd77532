#pragma once
// Private: a contact held on its adhesive branch (models/adhesive_geometry.hpp) as a DEM contact
// law, for jkr-viscoelastic and maugis-viscoelastic: the same geometry as their collision engine,
// made for each contact's R_eff.

#include <utility>

#include "bounce/models/adhesive_geometry.hpp"
#include "bounce/models/dem_law.hpp"

namespace bounce::models::detail {

/// F = F_E(delta) + 2 A E* a(delta) delta' (K13 (2) or the branch's own force, and K13 (19)), the
/// branch's energy; the contact forms at the branch's snap overlap and holds down to its release.
/// `At` makes (or finds) the geometry at a contact's R_eff: at(R) is an AdhesiveGeometry.
template <class At>
class AdhesiveBranchContact final : public DemLaw {
 public:
  AdhesiveBranchContact(At at, double effective_modulus, double dissipative_constant, AdhesiveRelease release)
      : at_(std::move(at)), damping_(2.0 * dissipative_constant * effective_modulus), release_(release) {}
  double force(const ContactGeometry& g, double delta, double rate) const override {
    const AdhesiveGeometry::State s = geometry(g).state(delta);
    return s.force + damping_ * s.contact_radius * rate;  // K13 (19): F_D = 2 A E* a delta'
  }
  double energy(const ContactGeometry& g, double delta) const override { return geometry(g).energy(delta); }
  double release_overlap(const ContactGeometry& g) const override { return geometry(g).release_overlap(release_); }
  double snap_overlap(const ContactGeometry& g) const override { return geometry(g).snap_overlap(); }

 private:
  decltype(auto) geometry(const ContactGeometry& g) const { return at_(g.effective_radius); }
  At at_;
  double damping_;  // 2 A E* [kg/(m s)]
  AdhesiveRelease release_;
};

template <class At>
std::shared_ptr<const DemLaw> adhesive_branch_contact(At at, double effective_modulus, double dissipative_constant,
                                                          AdhesiveRelease release) {
  return std::make_shared<AdhesiveBranchContact<At>>(std::move(at), effective_modulus, dissipative_constant, release);
}

}  // namespace bounce::models::detail
