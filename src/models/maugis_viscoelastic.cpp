// `maugis-viscoelastic`: the JKR-DMT transition (Tabor mu < 5, where krijt and jkr-viscoelastic
// warn that JKR may not apply). The contact is held on the Maugis-Dugdale branch of the pair's
// lambda (from z0, as `bounce contact --law maugis`; models/adhesive_geometry.hpp,
// contact/maugis_branch.hpp) with BSHP96's bulk damping in K13's form (19), F_D = 2 A E* a xi':
// it snaps on where the surfaces come within the attraction's range h0 = gamma/sigma0, holds
// down to the Maugis jump-off (the fold), and sticks where the mechanical energy falls below the
// contact's energy there. docs/adhesive.md, "Maugis-Dugdale collisions".
#include <map>
#include <memory>
#include <mutex>

#include <fmt/format.h>

#include "adhesive_dem_law.hpp"
#include "bounce/contact/surface_forces.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "adhesive_geometries.hpp"
#include "factories.hpp"
#include "hertz_type.hpp"

namespace bounce::models {

namespace {

// The branch at each contact's R_eff (lambda ~ R^{1/3}), made once per radius: a DEM's radii
// are few (per type pair) or, polydisperse, many but each met again and again. Beyond 4096
// radii a law makes the branch at every call (correct, slower: two minimum searches).
class BranchesByRadius {
 public:
  BranchesByRadius(double e, double gamma, double z0) : e_(e), gamma_(gamma), z0_(z0) {}
  BranchesByRadius(const BranchesByRadius& o) : e_(o.e_), gamma_(o.gamma_), z0_(o.z0_) {}
  std::shared_ptr<const detail::MaugisGeometry> at(double r) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (const auto it = made_.find(r); it != made_.end()) return it->second;
    auto g = std::make_shared<const detail::MaugisGeometry>(r, e_, gamma_, detail::maugis_lambda(r, e_, gamma_, z0_));
    if (made_.size() < max_radii) made_.emplace(r, g);
    return g;
  }

 private:
  static constexpr std::size_t max_radii = 4096;
  double e_, gamma_, z0_;
  mutable std::mutex mutex_;
  mutable std::map<double, std::shared_ptr<const detail::MaugisGeometry>> made_;
};

}  // namespace

// The zone's gap h0 = gamma/sigma0 (sigma0 of the Lennard-Jones law, maugis.hpp) is the range of
// the attraction; Maugis-Dugdale's half-space picture (the gap r^2/(2R) of two paraboloids) needs
// it small against R_eff. Beyond R_eff/10 the collision is refused (there the zone reaches across
// the grain; slow impacts of 10 nm grains at z0 = 100 nm also ran out of the step budget).
void check_zone_range(const AdhesivePair& k) {
  const double h0 = k.surface_energy / contact::surface::lennard_jones_max_tension(k.surface_energy, k.z0);
  if (h0 <= 0.1 * k.effective_radius) return;
  const double largest = k.z0 * 0.1 * k.effective_radius / h0;
  throw InvalidArgument("z0", format_value(k.z0),
                        fmt::format("z0 <= {:.6g} m for maugis-viscoelastic at R_eff = {:g} m (the attraction's "
                                    "range h0 = gamma/sigma0 = {:.3g} z0 must stay below R_eff/10)",
                                    largest, k.effective_radius, h0 / k.z0));
}

// Toward DMT (lambda -> 0) the Maugis-Dugdale branch is DMT's to 2 lambda^1.5 (docs/contact.md),
// and its search failed below lambda ~ 1e-25 (gamma = 1e-40 J/m^2 for 1 um ice: toms748 "do not
// bracket the root", exit 4). Below 1e-12 (DMT's to 2e-18) the model is refused, naming gamma.
constexpr double least_lambda = 1e-12;
void check_dmt_end(const AdhesivePair& k) {
  const double lambda = contact::surface::maugis_parameter(k.effective_radius, k.effective_modulus, k.surface_energy, k.z0);
  if (lambda >= least_lambda) return;
  throw InvalidArgument("gamma", format_value(k.surface_energy),
                        fmt::format("a Maugis parameter lambda >= {:g} for maugis-viscoelastic (lambda = {:.3g} from "
                                    "gamma, R_eff = {:g} m, E* = {:.3g} Pa, z0 = {:g} m): below it the contact is "
                                    "DMT's to 2 lambda^1.5 and its adhesion negligible (use viscoelastic)",
                                    least_lambda, lambda, k.effective_radius, k.effective_modulus, k.z0));
}

// The branch for the pair, and per DEM contact the branch at its R_eff, held by a cache.
Made<AdhesiveContact> make_maugis_viscoelastic(const Pair& pair, const ContactModelParameters& p, const Context& c) {
  const AdhesivePair k = detail::adhesive_pair(pair, p, "maugis-viscoelastic");
  check_zone_range(k);
  check_dmt_end(k);
  auto branches = std::make_shared<const BranchesByRadius>(k.effective_modulus, k.surface_energy, k.z0);
  const auto at = [branches](double r) -> const AdhesiveGeometry& {
    // The geometry outlives the call: the cache keeps it (or, past its size, this thread's last).
    thread_local std::shared_ptr<const detail::MaugisGeometry> held;
    held = branches->at(r);
    return *held;
  };
  auto dem = detail::adhesive_branch_contact(at, k.effective_modulus, k.dissipative_constant,
                                             detail::adhesive_release(c.end_rule));
  return detail::contact_model(
      k, p,
      AdhesiveContact{k, maugis_geometry(k.effective_radius, k.effective_modulus, k.surface_energy, k.z0), std::move(dem)});
}

}  // namespace bounce::models
