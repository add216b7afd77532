// The two adhesive geometries of models/adhesive_geometry.hpp: JKR's branch (K13 notation) and
// Maugis-Dugdale's (contact/maugis_branch.hpp, in SI).
#include "bounce/models/adhesive_geometry.hpp"

#include <algorithm>

#include "bounce/contact/independent.hpp"
#include "bounce/contact/jkr.hpp"
#include "bounce/contact/maugis.hpp"
#include "bounce/contact/maugis_branch.hpp"
#include "bounce/contact/surface_forces.hpp"

namespace bounce::models {

namespace {

// JKR: a on the branch of K13 (8) stable under displacement control, the force K13 (2) at that
// (a, delta) (K13 (9) there), the energies K13 (3) and (6).
class JkrGeometry final : public AdhesiveGeometry {
 public:
  JkrGeometry(double r, double e, double gamma) : p_{r, e, gamma}, branch_(p_) {}
  std::string_view name() const override { return "jkr"; }
  State state(double delta) const override {
    const double a = branch_.radius(delta);
    return {a, contact::independent::elastic_force({p_.effective_radius, p_.effective_modulus}, a, delta)};
  }
  double elastic_energy(double delta) const override {
    return contact::independent::elastic_energy({p_.effective_radius, p_.effective_modulus}, branch_.radius(delta), delta);
  }
  double surface_energy(double delta) const override {
    return contact::independent::surface_energy(branch_.radius(delta), p_.surface_energy);
  }
  double snap_overlap() const override { return 0.0; }
  double release_overlap(AdhesiveRelease release) const override {
    return release == AdhesiveRelease::pull_off ? contact::jkr::pull_off_overlap(p_) : contact::jkr::separation_overlap(p_);
  }

 private:
  contact::jkr::Parameters p_;
  contact::jkr::DisplacementBranch branch_;
};

// Past lambda = 1e6 the Maugis-Dugdale curve is JKR's within 1e-12 in the force (the difference
// falls as lambda^-2, contact/maugis.cpp) while its stable part shrinks to s ~ 1/lambda, near the
// end of the energy's table: the curve is taken at min(lambda, 1e6).
constexpr double jkr_limit_lambda = 1e6;

// Maugis-Dugdale: the stable part of contact::maugis::Branch at the pair's lambda, in SI with the
// scales of maugis.hpp (a = A l, F = P pi w R, delta = Delta l^2/R, U = U~ pi w l^2).
class MaugisGeometry final : public AdhesiveGeometry {
 public:
  MaugisGeometry(double r, double e, double gamma, double lambda)
      : branch_(lambda), down_(lambda * (1.0 - contact::maugis::Branch::lambda_step)),
        up_(lambda * (1.0 + contact::maugis::Branch::lambda_step)), scales_(contact::maugis::scales(r, e, gamma)),
        energy_unit_(scales_.force * scales_.length * scales_.length / r) {}
  std::string_view name() const override { return "maugis-dugdale"; }
  State state(double delta) const override {
    const contact::maugis::BranchPoint p = branch_.at_overlap(delta / scales_.overlap);
    return {p.contact_radius * scales_.length, p.force * scales_.force};
  }
  double energy(double delta) const override { return branch_.energy_at_overlap(delta / scales_.overlap) * energy_unit_; }
  double surface_energy(double delta) const override {
    return branch_.surface_energy_at_overlap(delta / scales_.overlap, down_, up_) * energy_unit_;
  }
  double elastic_energy(double delta) const override { return energy(delta) - surface_energy(delta); }
  double snap_overlap() const override { return branch_.snap_overlap() * scales_.overlap; }
  double release_overlap(AdhesiveRelease release) const override {
    const contact::maugis::BranchPoint& p = release == AdhesiveRelease::pull_off ? branch_.pull_off() : branch_.fold();
    return p.overlap * scales_.overlap;
  }

 private:
  contact::maugis::Branch branch_, down_, up_;
  contact::maugis::Scales scales_;
  double energy_unit_;  // pi w l^2 = (pi w R) l^2 / R
};

}  // namespace

std::shared_ptr<const AdhesiveGeometry> jkr_geometry(double r, double e, double gamma) {
  return std::make_shared<JkrGeometry>(r, e, gamma);
}

std::shared_ptr<const AdhesiveGeometry> maugis_geometry(double r, double e, double gamma, double z0) {
  const double lambda = contact::surface::maugis_parameter(r, e, gamma, z0);
  return std::make_shared<MaugisGeometry>(r, e, gamma, std::min(lambda, jkr_limit_lambda));
}

}  // namespace bounce::models
