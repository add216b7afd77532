// The two adhesive geometries of models/adhesive_geometry.hpp: JKR's branch (K13 notation) and
// Maugis-Dugdale's (contact/maugis_branch.hpp, in SI).
#include "bounce/models/adhesive_geometry.hpp"

#include <algorithm>

#include "adhesive_geometries.hpp"
#include "bounce/contact/independent.hpp"
#include "bounce/contact/surface_forces.hpp"

namespace bounce::models {

namespace detail {

AdhesiveGeometry::State JkrGeometry::state(double delta) const {
  const double a = branch_.radius(delta);
  return {a, contact::independent::elastic_force({p_.effective_radius, p_.effective_modulus}, a, delta)};  // K13 (2)
}
double JkrGeometry::elastic_energy(double delta) const {  // K13 (3)
  return contact::independent::elastic_energy({p_.effective_radius, p_.effective_modulus}, branch_.radius(delta), delta);
}
double JkrGeometry::surface_energy(double delta) const {  // K13 (6)
  return contact::independent::surface_energy(branch_.radius(delta), p_.surface_energy);
}
double JkrGeometry::least_energy() const { return energy(equilibrium_overlap()); }
double JkrGeometry::equilibrium_overlap() const {  // at zero force: a_eq of K13 (10), delta of K13 (8)
  return contact::jkr::overlap(p_, contact::jkr::equilibrium_contact_radius(p_));
}
double JkrGeometry::release_overlap(AdhesiveRelease release) const {
  return release == AdhesiveRelease::pull_off ? contact::jkr::pull_off_overlap(p_) : contact::jkr::separation_overlap(p_);
}

MaugisGeometry::MaugisGeometry(double r, double e, double gamma, double lambda)
    : branch_(lambda), scales_(contact::maugis::scales(r, e, gamma)),
      energy_unit_(scales_.force * scales_.length * scales_.length / r) {}

AdhesiveGeometry::State MaugisGeometry::state(double delta) const {
  const contact::maugis::BranchPoint p = branch_.at_overlap(delta / scales_.overlap);
  return {p.contact_radius * scales_.length, p.force * scales_.force};
}
double MaugisGeometry::energy(double delta) const {
  return branch_.energy_at_overlap(delta / scales_.overlap) * energy_unit_;
}
double MaugisGeometry::surface_energy(double delta) const {
  std::call_once(neighbours_made_, [this] {
    const double step = contact::maugis::Branch::lambda_step;
    down_ = std::make_unique<contact::maugis::Branch>(branch_.lambda() * (1.0 - step));
    up_ = std::make_unique<contact::maugis::Branch>(branch_.lambda() * (1.0 + step));
  });
  return branch_.surface_energy_at_overlap(delta / scales_.overlap, *down_, *up_) * energy_unit_;
}
double MaugisGeometry::least_energy() const {
  return branch_.energy_at_overlap(branch_.zero_force_overlap()) * energy_unit_;
}
double MaugisGeometry::equilibrium_overlap() const { return branch_.zero_force_overlap() * scales_.overlap; }
double MaugisGeometry::release_overlap(AdhesiveRelease release) const {
  const contact::maugis::BranchPoint& p = release == AdhesiveRelease::pull_off ? branch_.pull_off() : branch_.fold();
  return p.overlap * scales_.overlap;
}

double maugis_lambda(double r, double e, double gamma, double z0) {
  return std::min(contact::surface::maugis_parameter(r, e, gamma, z0), jkr_limit_lambda);
}

}  // namespace detail

std::shared_ptr<const AdhesiveGeometry> jkr_geometry(double r, double e, double gamma) {
  return std::make_shared<detail::JkrGeometry>(r, e, gamma);
}

std::shared_ptr<const AdhesiveGeometry> maugis_geometry(double r, double e, double gamma, double z0) {
  return std::make_shared<detail::MaugisGeometry>(r, e, gamma, detail::maugis_lambda(r, e, gamma, z0));
}

}  // namespace bounce::models
