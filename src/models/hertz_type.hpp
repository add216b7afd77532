#pragma once
// Private: what the Hertz-type models (hertz, viscoelastic, viscoelastic-shifted,
// adhesive-viscoelastic) share: their dissipative constant, viscous time, geometry.

#include <string>
#include <string_view>

#include "bounce/contact/convex.hpp"
#include "bounce/contact/hertz.hpp"
#include "bounce/models/dem_law.hpp"
#include "bounce/models/krijt.hpp"
#include "bounce/models/model.hpp"
#include "bounce/models/model_parameters.hpp"
#include "bounce/models/normal_force.hpp"
#include "bounce/pair/mixing.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce::models::detail {

/// The elastic part of the Hertz-type force laws: F_el = C0 xi^{3/2}, U = (2/5) C0 xi^{5/2},
/// a^2 = R xi, xi0 of BP04 (8.65) with alpha = 3/2. Each law adds its total force.
class HertzTypeForce : public NormalForceModel {
 public:
  explicit HertzTypeForce(const HertzGeometry& g) : g_(g) {}
  double elastic_force(double xi) const override;
  double elastic_energy(double xi) const override;
  double contact_radius(double xi) const override;
  double reference_overlap(double speed) const override;

 protected:
  HertzGeometry g_;
};

/// A Hertz-type law as a DEM law (dem_law.hpp): `Law(C0, A, xi, xi')` with C0 = rho
/// of BP04 (8.24) from the contact's R_eff, and the Hertz potential.
template <double (*Law)(double, double, double, double)>
class HertzTypeContact final : public DemLaw {
 public:
  HertzTypeContact(double modulus, double a) : modulus_(modulus), a_(a) {}
  double force(const ContactGeometry& g, double xi, double rate) const override {
    return Law(hertz_constant(modulus_, g.effective_radius), a_, xi, rate);
  }
  double energy(const ContactGeometry& g, double xi) const override {
    return contact::hertz::elastic_energy(hertz_constant(modulus_, g.effective_radius), xi);
  }

 private:
  double modulus_, a_;
};

/// The longest viscous time a model takes, in units of the shortest elastic contact time: the
/// Hertz time at the sound speed, t_H(c_t) (BSHP96 (A13) at g = c_t). Beyond it the time is
/// more than ~1e4 contact times at every speed down to 1e-6 m/s (t_H grows as g^{-1/5}): no
/// viscous model describes that collision (they need A, T_vis << t_c, BSHP96 (B12)), and the
/// engines failed there (A = 1e300 s: RODAS step underflow, non-finite states). docs/models.md.
inline constexpr double longest_viscous_time_ratio = 1e6;
/// t_H(c_t) of the pair [s].
double shortest_contact_time(const Pair& pair);
/// `value` (A or T_vis, named `name` as the user types it) unless it exceeds
/// longest_viscous_time_ratio t_H(c_t): then InvalidArgument naming it.
double require_short_viscous_time(const Pair& pair, double value, const std::string& name, const std::string& what);

/// A [s]: given, from eta1 and eta2 (BP04 (8.38), bodies of one material), or T_vis / nu^2
/// (K13 after (18)); exactly one of these is given (the parameter table's rule).
double dissipative_constant(const Pair& pair, const ViscousParameters& p);

/// The viscous relaxation time that must be << t_c (BSHP96 (B12), BP04 (8.26)): with
/// viscosities, BSHP96 (B13) tau_i = eta_i / E_i; otherwise A (for eta2/E2 = eta1/E1 = tau,
/// (8.38) gives exactly A = tau).
double viscous_time(const Pair& pair, const ViscousParameters& p, double a);

/// C0, the equivalent radius (a^2 = R xi) and m_eff: spheres and walls (rho of BP04
/// (8.24)), or convex bodies (C0 of (8.21), the equal-area circle).
HertzGeometry hertz_geometry(const Pair& pair, const std::optional<contact::convex::Curvatures>& shape);

/// The pair's gamma, which adhesive models need > 0.
double adhesive_surface_energy(const Pair& pair, std::string_view model);

/// The adhesive pair of a contact model: gamma (> 0), A (given, or T_vis / nu^2 by K13 after
/// (18)), z0; a given T_vis or A is checked short against the contact time.
AdhesivePair adhesive_pair(const Pair& pair, const ContactModelParameters& p, std::string_view model);
/// krijt's: the adhesive pair, T_vis and k.
KrijtParameters krijt_parameters(const Pair& pair, const CrackModelParameters& p);
/// A contact model's physics with that pair and its normal interaction (A, viscous time, z0 set).
template <class Kind>
Made<Kind> contact_model(const AdhesivePair& k, const ContactModelParameters& p, Kind normal) {
  Made<Kind> m;
  m.normal = std::move(normal);
  m.dissipative_constant = k.dissipative_constant;
  m.dissipative_constant_from_tvis = !p.dissipative_constant.has_value();  // adhesive_pair: then T_vis / nu^2
  m.viscous_time = p.relaxation_time.value_or(k.dissipative_constant);
  m.z0 = k.z0;
  return m;
}
/// Where a contact held on its adhesive branch breaks, by the end rule (pull-off, else the fold).
AdhesiveRelease adhesive_release(EndRule rule);

}  // namespace bounce::models::detail
