#pragma once
// Static contact laws behind one interface, for front ends and sweeps.
//
// Registry: one keyword <-> one row of `contact_laws()` <-> one class <-> one file.
// To add a law: implement ContactLaw in src/contact/<law>.cpp, declare its
// factory below, and add a row (with the parameters it takes) to the table in
// src/contact/law.cpp.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bounce/contact/convex.hpp"
#include "bounce/core/parameters.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce::contact {

/// One equilibrium state of the contact (SI units).
struct ContactPoint {
  double contact_radius = 0.0;  ///< a [m]
  double overlap = 0.0;         ///< delta (mutual approach) [m]; negative = apart but touching
  double force = 0.0;           ///< total normal force [N]; positive = repulsive
};

/// What an adhesive law says about pull-off and zero load.
struct AdhesionSummary {
  double pull_off_force = 0.0;            ///< most tensile force sustained, force control [N]
  double pull_off_contact_radius = 0.0;   ///< a at pull-off, force control [m]
  double zero_load_contact_radius = 0.0;  ///< a at F = 0 [m]
  double zero_load_overlap = 0.0;         ///< delta at F = 0 [m]
  double separation_overlap = 0.0;        ///< most negative delta still in contact [m]
  double separation_contact_radius = 0.0; ///< a there (displacement control) [m]
};

/// The fields of an AdhesionSummary by name (the keys of `bounce contact --json` and of
/// Python's ContactLaw.adhesion).
std::vector<std::pair<std::string, double>> named_values(const AdhesionSummary& summary);

class ContactLaw {
 public:
  virtual ~ContactLaw() = default;
  virtual std::string_view name() const = 0;
  /// Stable state under force control. InvalidArgument("force", …) outside the range.
  virtual ContactPoint at_force(double force) const = 0;
  /// Stable state under displacement control. InvalidArgument("overlap", …) outside the range.
  virtual ContactPoint at_overlap(double overlap) const = 0;
  /// The point of the law's curve with contact radius a >= 0 (stable or not):
  /// the natural parametrisation of the whole force-overlap curve.
  virtual ContactPoint at_contact_radius(double contact_radius) const = 0;
  /// Pull-off and zero-load quantities; empty for non-adhesive laws.
  virtual std::optional<AdhesionSummary> adhesion() const = 0;
  /// The shape of the contact at a point, by name, where it is not a circle (the contact
  /// ellipse of convex bodies: semi-axes, x0, B1, B2, N(x0), M(x0), C0); empty for spheres.
  virtual std::vector<std::pair<std::string, double>> shape(const ContactPoint& point) const {
    (void)point;
    return {};
  }
};

/// One row of the registry of contact laws.
struct LawRow {
  std::string name;
  bool needs_surface_energy = false;
  std::string summary;
  std::string references;
  std::vector<ParameterSpec> parameters;  ///< z0 of the adhesive laws, curvature radii of hertz
  std::function<std::unique_ptr<ContactLaw>(const Pair&, const Parameters&)> factory;
};

/// The registry table (src/contact/law.cpp).
const std::vector<LawRow>& contact_laws();
/// The row of `name`; InvalidArgument("law", name, "one of …") if unknown.
const LawRow& contact_law(std::string_view name);

/// The law called `name` for `pair` with its parameters (bound to its row);
/// InvalidArgument("gamma", …) if it needs a surface energy the pair lacks.
std::unique_ptr<ContactLaw> make_contact_law(std::string_view name, const Pair& pair, const Parameters& parameters);
/// The same from unchecked inputs (a name the law does not take is an InvalidArgument).
std::unique_ptr<ContactLaw> make_contact_law(std::string_view name, const Pair& pair,
                                             const ParameterInputs& inputs = {});

// Factories, one per law (defined beside each law's equations).
std::unique_ptr<ContactLaw> make_hertz_law(const Pair& pair);
std::unique_ptr<ContactLaw> make_jkr_law(const Pair& pair);
std::unique_ptr<ContactLaw> make_dmt_law(const Pair& pair);
std::unique_ptr<ContactLaw> make_maugis_law(const Pair& pair, double z0);
/// Hertz for general convex bodies (BP04 (8.6)-(8.21)): F = C0 xi^{3/2}, the contact an ellipse
/// whose equal-area circle gives the contact radius; no contact-radius parametrisation.
std::unique_ptr<ContactLaw> make_convex_hertz_law(const Pair& pair, const convex::Curvatures& curvatures);

}  // namespace bounce::contact
