/* The contact law of each pair of atom types in pair_style bounce (docs/lammps.md, Mixing and
   Restarts): what pair_coeff I J was given, as typed, and the law bounce's front door made of it;
   the law of unlike types from those of I I and J J by bounce's own rule for two materials; and
   the coefficients as text for a restart file. Nothing of LAMMPS here: the pair style reports
   what these throw. */

#ifndef BOUNCE_LAMMPS_TYPE_LAWS_H
#define BOUNCE_LAMMPS_TYPE_LAWS_H

#include <map>
#include <memory>
#include <stdexcept>
#include <string>

#include "bounce/models/dem_law.hpp"

namespace bounce::lammps {

/// pair_coeff's model (key "model") and its key value pairs, as typed, in key order.
using Coeffs = std::map<std::string, std::string>;

struct TypeLaw {
  /// As typed, with the asperity form named where the law takes the default (make_type_law).
  Coeffs coeffs;
  models::DemModel law;
  bool snaps = false;   ///< its contacts form before touching (Maugis-Dugdale's zone)
  bool beyond = false;  ///< its contacts hold beyond touching (an adhesive neck)
};

/// The law of `coeffs` by bounce's front door (throws its errors, naming the input). Where it uses
/// the asperity law without naming its form, its coefficients name the form it took (so a restart
/// file always names it: restart_type_law).
std::shared_ptr<const TypeLaw> make_type_law(const Coeffs& coeffs);

/// True where `law` uses the asperity law and its coefficients do not name the form (the default).
bool takes_default_asperity_form(const models::DemModel& law, bool form_named);

/// The form a restart written before bounce made passive the default (issue 40) meant where it
/// named none: BSHP96's published form, whose springs (the extension s) its contacts hold.
inline constexpr const char* form_before_passive_default = "published";

/// The law of coefficients read from a restart file. Files written since issue 40 name the
/// asperity form (make_type_law); one that uses the asperity law without naming it was written
/// before, when the default was the published form: it keeps that form (`asperity_form
/// published` added, `kept_published` set) rather than read its springs as the passive form's.
std::shared_ptr<const TypeLaw> restart_type_law(const Coeffs& coeffs, bool& kept_published);

/// Why two types cannot be mixed (the message names the key, the two values and the remedy).
struct CannotMix : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The law of types I and J from theirs with themselves, as bounce pairs two materials (the CLI's
/// --material and --material2): body 1 of I's material (material, E, nu, gamma), body 2 of J's
/// (as material2, E2, nu2, gamma2), the model and its other keys being the same for both (else
/// CannotMix). The same materials give I I's law itself.
std::shared_ptr<const TypeLaw> mix(const TypeLaw& ii, const TypeLaw& jj, int i, int j);

/// The coefficients as one line of text and back (for restart files): key=value separated by
/// spaces (LAMMPS's words have no spaces).
std::string to_text(const Coeffs& coeffs);
Coeffs from_text(const std::string& text);

}  // namespace bounce::lammps

#endif
