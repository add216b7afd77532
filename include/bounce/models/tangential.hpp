#pragma once
// The tangential force laws of an oblique collision as values (BSHP96 §II B): which law,
// its constants and kappa of the pair. The equations and their integration are in
// dynamics/tangential.hpp; the values live here because the model registry configures them.

#include <string_view>

namespace bounce::models {

enum class TangentialLaw { asperity, step };
enum class AsperityForm { published, passive };
std::string_view to_string(TangentialLaw law);
std::string_view to_string(AsperityForm form);
TangentialLaw parse_tangential_law(std::string_view text);  ///< "asperity" | "step"
AsperityForm parse_asperity_form(std::string_view text);    ///< "published" | "passive"

struct TangentialModel {
  TangentialLaw law = TangentialLaw::asperity;
  AsperityForm form = AsperityForm::published;
  double friction = 0.0;       ///< mu, BSHP96 (35)-(36)
  double asperity_size = 0.0;  ///< zeta0 [m], BSHP96 (32) (asperity law)
  double shear_damping = 0.0;  ///< gamma_s [1/s], BSHP96 (39) (step law)
  double kappa = 2.0 / 7.0;    ///< BSHP96 (8): 2/7 for homogeneous spheres
  /// Asperity breaks per time unit xi0/g^N above which the sawtooth is averaged (back
  /// below a tenth of it); +inf resolves every break.
  double dense_breaks = 1e3;
};

/// Checks the parameters (mu >= 0; zeta0 > 0 for the asperity law, gamma_s >= 0 for the
/// step law; 0 < kappa <= 1); InvalidArgument names the offending one.
void validate(const TangentialModel& model);

}  // namespace bounce::models
