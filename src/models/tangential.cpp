#include "bounce/models/tangential.hpp"

#include <string>

#include <fmt/format.h>

#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"

namespace bounce::models {

std::string_view to_string(TangentialLaw law) { return law == TangentialLaw::asperity ? "asperity" : "step"; }
std::string_view to_string(AsperityForm form) { return form == AsperityForm::published ? "published" : "passive"; }

TangentialLaw parse_tangential_law(std::string_view text) {
  if (text == "asperity") return TangentialLaw::asperity;
  if (text == "step") return TangentialLaw::step;
  throw InvalidArgument("tangential_law", std::string(text), "asperity (BSHP96 (35)) or step (BSHP96 (39))");
}

AsperityForm parse_asperity_form(std::string_view text) {
  if (text == "published") return AsperityForm::published;
  if (text == "passive") return AsperityForm::passive;
  throw InvalidArgument("asperity_form", std::string(text), "published or passive");
}

void validate(const TangentialModel& m) {
  require_non_negative("friction", m.friction, "friction coefficient mu");
  if (!(m.dense_breaks > 0.0)) {  // +inf resolves every break
    throw InvalidArgument("dense_breaks", fmt::format("{:g}", m.dense_breaks), "breaks per time unit > 0 (or inf)");
  }
  require_positive("kappa", m.kappa, "tangential mass factor kappa of BSHP96 (8)");
  if (m.kappa > 1.0) throw InvalidArgument("kappa", fmt::format("{:g}", m.kappa), "0 < kappa <= 1 (BSHP96 (8))");
  if (m.law == TangentialLaw::asperity) {
    require_positive("asperity", m.asperity_size, "asperity size zeta0 [m] (BSHP96 (32))");
  } else {
    require_non_negative("shear_damping", m.shear_damping, "shear damping gamma_s [1/s] (BSHP96 (39))");
  }
}

}  // namespace bounce::models
