#pragma once
// Private: the two adhesive geometries of models/adhesive_geometry.hpp as classes, for the
// collision models (through the interface) and their DEM laws (one per contact's R_eff).

#include <memory>
#include <mutex>
#include <optional>

#include "bounce/contact/jkr.hpp"
#include "bounce/contact/maugis.hpp"
#include "bounce/contact/maugis_branch.hpp"
#include "bounce/models/adhesive_geometry.hpp"

namespace bounce::models::detail {

// JKR: a on the branch of K13 (8) stable under displacement control, the force K13 (2) at that
// (a, delta) (K13 (9) there), the energies K13 (3) and (6). Cheap to make: a DEM law makes one
// per contact and step.
class JkrGeometry final : public AdhesiveGeometry {
 public:
  JkrGeometry(double r, double e, double gamma) : p_{r, e, gamma}, branch_(p_) {}
  std::string_view name() const override { return "jkr"; }
  State state(double delta) const override;
  double elastic_energy(double delta) const override;
  double surface_energy(double delta) const override;
  double least_energy() const override;
  double equilibrium_overlap() const override;
  double snap_overlap() const override { return 0.0; }
  double release_overlap(AdhesiveRelease release) const override;

 private:
  contact::jkr::Parameters p_;
  contact::jkr::DisplacementBranch branch_;
};

// Past lambda = 1e6 the Maugis-Dugdale curve is JKR's within 1e-12 in the force (the difference
// falls as lambda^-2, contact/maugis.cpp) while its stable part shrinks to s ~ 1/lambda, near the
// end of the energy's table: the curve is taken at min(lambda, 1e6).
constexpr double jkr_limit_lambda = 1e6;

// Maugis-Dugdale: the stable part of contact::maugis::Branch at the pair's lambda, in SI with the
// scales of maugis.hpp (a = A l, F = P pi w R, delta = Delta l^2/R, U = U~ pi w l^2). The two
// curves at lambda (1 -+ 1e-5) that U_S needs are made at its first use.
class MaugisGeometry final : public AdhesiveGeometry {
 public:
  MaugisGeometry(double r, double e, double gamma, double lambda);
  std::string_view name() const override { return "maugis-dugdale"; }
  State state(double delta) const override;
  double energy(double delta) const override;
  double surface_energy(double delta) const override;
  double elastic_energy(double delta) const override { return energy(delta) - surface_energy(delta); }
  double least_energy() const override;
  double equilibrium_overlap() const override;
  double snap_overlap() const override { return branch_.snap_overlap() * scales_.overlap; }
  double release_overlap(AdhesiveRelease release) const override;

 private:
  contact::maugis::Branch branch_;
  contact::maugis::Scales scales_;
  double energy_unit_;  // pi w l^2 = (pi w R) l^2 / R
  mutable std::once_flag neighbours_made_;
  mutable std::unique_ptr<contact::maugis::Branch> down_, up_;
};

/// Maugis' lambda of a pair, as `bounce contact --law maugis` has it, capped at jkr_limit_lambda.
double maugis_lambda(double effective_radius, double effective_modulus, double surface_energy, double z0);

}  // namespace bounce::models::detail
