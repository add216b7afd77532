#pragma once
// The closed-form estimates beside an adhesive collision at one speed: K13 (22),
// (24)-(27), (28)-(29), (11) and BP04 (8.95), (8.98). The CLI's --closed-forms
// columns, the Python closed_forms() and the K13 figures all read this one struct.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bounce/models/registry.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce {

struct AdhesiveClosedForms {
  double sticking_velocity_jkr = 0.0;      ///< exact elastic JKR v_c [m/s]
  double sticking_velocity_k13_25 = 0.0;   ///< K13 (25) as printed [m/s]
  double e_jkr = 0.0;                      ///< K13 (24)
  double hertz_time_k13_22 = 0.0;          ///< K13 (22) [s]
  double tabor_parameter = 0.0;            ///< K13 (11) with the model's z0
  std::optional<double> dissipative_constant;  ///< A [s] (models with T_vis or A)
  std::optional<double> e_d;               ///< K13 (26) as printed
  std::optional<double> e_i;               ///< K13 (27)
  std::optional<double> tensile_work_bp04_8_95;  ///< W0 [J] (adhesive-viscoelastic)
  std::optional<double> e_ad_bp04_8_98;          ///< (adhesive-viscoelastic)
  std::optional<double> yield_velocity;          ///< K13 (28) [m/s] (with a yield strength)
  std::optional<double> e_plastic;               ///< K13 (29)
  std::optional<double> plastic_length_scale;    ///< K13 (33) [m]
};

/// The closed forms for an adhesive model at impact speed `velocity` [m/s];
/// InvalidArgument when the pair has no surface energy.
AdhesiveClosedForms adhesive_closed_forms(const Pair& pair, const models::ModelSpec& model, double velocity);

/// The values that are present, by the field names above (the keys of the CLI's
/// "closed_forms" JSON and of Python's closed_forms()).
std::vector<std::pair<std::string, double>> named_values(const AdhesiveClosedForms& forms);

}  // namespace bounce
