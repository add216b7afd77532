#pragma once
// When does the contact of a collision end? A model parameter (`contact_end`) that the
// engines (dynamics) and the master curves (analytic) both read, so it lives here, the
// lowest layer that needs it.

#include <string_view>

namespace bounce::models {

enum class EndRule {
  overlap,  ///< when the overlap returns to zero (BP04's series describe this)
  force,    ///< when the total normal force first vanishes (no attraction between non-adhesive grains)
  fold,     ///< JKR contacts: at the fold delta_c, d delta/da = 0 (K13 (25); jkr-viscoelastic's `overlap`)
  pull_off, ///< JKR contacts: at the pull-off point, F = -(3/2) pi gamma R (LAMMPS's pair granular jkr)
};
std::string_view to_string(EndRule rule);
/// "overlap" | "force" | "fold" | "pull-off"; InvalidArgument("contact_end", …) otherwise
/// (which models take which rule: models::make_model).
EndRule parse_end_rule(std::string_view text);

}  // namespace bounce::models
