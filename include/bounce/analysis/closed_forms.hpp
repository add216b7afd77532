#pragma once
// The closed-form estimates beside a collision at one speed: K13 (22), (24)-(27),
// (28)-(29), (33), (11) and BP04 (8.95), (8.98). The CLI's --closed-forms columns, the
// Python closed_forms() and the K13 figures all read this one struct.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bounce/models/model.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce::analysis {

struct ClosedForms {
  double hertz_time_k13_22 = 0.0;                   ///< K13 (22) [s]
  // With a surface energy (the pair has gamma > 0):
  std::optional<double> sticking_velocity_jkr;      ///< exact elastic JKR v_c [m/s]
  std::optional<double> sticking_velocity_k13_25;   ///< K13 (25) as printed [m/s]
  std::optional<double> e_jkr;                      ///< K13 (24)
  std::optional<double> tabor_parameter;            ///< K13 (11) with the model's z0
  // With a dissipative constant A (e_d and e_i absent, while A is present, where (26) fails
  // its condition 5.57 A / t_H <= 1: first order in A / t_H, it would leave [0, 1]):
  std::optional<double> dissipative_constant;       ///< A [s]
  std::optional<double> e_d;                        ///< K13 (26) as printed
  std::optional<double> e_i;                        ///< K13 (27) (with gamma too)
  // BP04's weak-adhesion estimate (adhesive-viscoelastic):
  std::optional<double> tensile_work_bp04_8_95;     ///< W0 [J]
  std::optional<double> e_ad_bp04_8_98;
  // With a yield strength:
  std::optional<double> yield_velocity;             ///< K13 (28) [m/s]
  std::optional<double> e_plastic;                  ///< K13 (29)
  std::optional<double> plastic_length_scale;       ///< K13 (33) [m]
  std::vector<std::string> warnings;                 ///< why a closed form that applies is null
};

/// The closed forms that apply to `model` at impact speed `velocity` [m/s].
ClosedForms closed_forms(const Pair& pair, const models::Model& model, double velocity);

/// The closed forms that apply, by the field names above (the keys of the CLI's "closed_forms"
/// JSON and of Python's closed_forms()); std::nullopt for one that applies but lies outside its
/// validity (e_d, e_i; `warnings` says why): null in JSON, an empty CSV field, None in Python.
std::vector<std::pair<std::string, std::optional<double>>> named_values(const ClosedForms& forms);

}  // namespace bounce::analysis
