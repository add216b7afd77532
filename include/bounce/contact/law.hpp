#pragma once
// Static contact laws behind one interface, for front ends and sweeps.
//
// Registry: one keyword <-> one row of `contact_laws()` <-> one class <-> one file.
// To add a law: implement ContactLaw in src/contact/<law>.cpp, declare its
// factory below, and add a row to the table in src/contact/law.cpp.

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

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
};

/// Options some laws need.
struct LawOptions {
  double z0 = 0.2e-9;  ///< equilibrium separation of the surfaces [m] (Maugis-Dugdale)
};

struct LawInfo {
  std::string name;
  bool needs_surface_energy;
  std::string summary;
  std::string references;
};

/// The registry table.
const std::vector<LawInfo>& contact_laws();

/// The law called `name` for `pair`; InvalidArgument("law", name, "one of …") if
/// unknown, InvalidArgument("gamma", …) if it needs a surface energy the pair lacks.
std::unique_ptr<ContactLaw> make_contact_law(std::string_view name, const Pair& pair,
                                             const LawOptions& options = {});

// Factories, one per law (defined beside each law's equations).
std::unique_ptr<ContactLaw> make_hertz_law(const Pair& pair);
std::unique_ptr<ContactLaw> make_jkr_law(const Pair& pair);
std::unique_ptr<ContactLaw> make_dmt_law(const Pair& pair);
std::unique_ptr<ContactLaw> make_maugis_law(const Pair& pair, double z0);

}  // namespace bounce::contact
