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
AsperityForm parse_asperity_form(std::string_view text);    ///< "passive" | "published"

struct TangentialModel {
  TangentialLaw law = TangentialLaw::asperity;
  AsperityForm form = AsperityForm::passive;  ///< passive by default: the published form can gain energy (D12)
  double friction = 0.0;       ///< mu, BSHP96 (35)-(36)
  double asperity_size = 0.0;  ///< zeta0 [m], BSHP96 (32) (asperity law)
  double shear_damping = 0.0;  ///< gamma_s [1/s], BSHP96 (39) (step law)
  double kappa = 2.0 / 7.0;    ///< BSHP96 (8): 2/7 for homogeneous spheres
  /// Asperity breaks per time unit xi0/g^N above which the sawtooth is averaged (back
  /// below a tenth of it); +inf resolves every break.
  double dense_breaks = 1e3;
};

/// BSHP96's tangential laws over one step of a DEM code (LAMMPS's pair_style bounce), in three
/// dimensions, with three numbers of history per contact (in the tangent plane; the caller
/// rotates them with the contact). `normal_force` is the total normal force, taken as 0 where
/// it is attractive; `sliding` the relative tangential velocity of the contact points.
///  * asperity law, published form, BSHP96 (35)-(36): the history is the spring's extension s,
///    F^T = -k s with k = mu F^N / zeta0; s grows by sliding * dt, and an asperity breaks when
///    |s| reaches zeta0: the spring restarts with the rest of the step's sliding.
///  * passive form: the history is w = sqrt(k) s', which keeps the stored energy |w|^2/2 when
///    k changes: w grows by sqrt(k) sliding dt with the step's mean sqrt(k) (from
///    `previous_normal_force`, the force a step ago: second order), F^T = -sqrt(k) w, breaks at
///    |F^T| = mu F^N.
///  * step law, BSHP96 (39): F^T = -min(gamma_s m_eff |v|, mu F^N) v/|v|; no history.
/// With update = false (LAMMPS's setup) the history is left as it is. Writes F^T into `force`.
void tangential_step(const TangentialModel& model, double normal_force, double previous_normal_force,
                     double effective_mass, const double sliding[3], double dt, bool update, double history[3],
                     double force[3]);

/// Checks the parameters (mu >= 0; zeta0 > 0 for the asperity law, gamma_s >= 0 for the
/// step law; 0 < kappa <= 1); InvalidArgument names the offending one.
void validate(const TangentialModel& model);

}  // namespace bounce::models
