#pragma once
// A material: elastic constants, density and surface energy (SI units).

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace bounce {

struct Material {
  std::string name;                 ///< table name, e.g. "water-ice"; empty if given explicitly
  double youngs_modulus = 0.0;      ///< E [Pa]
  double poisson_ratio = 0.0;       ///< nu [-], -1 < nu < 0.5
  double density = 0.0;             ///< [kg/m^3]
  /// Work of adhesion of two like surfaces, gamma_L [J/m^2] (twice the surface
  /// free energy; BP04 after (8.45), K13 footnote 8). Empty when unknown.
  std::optional<double> surface_energy;
  /// When only a range is known (K13 table 2, ceramics: 0.04-5 J/m^2).
  std::optional<std::array<double, 2>> surface_energy_range;
  std::string source;               ///< where the values come from
};

/// Young's moduli of grain materials, from soft gels and rubbers (~1e4-1e6 Pa) to diamond
/// (1.2e12 Pa): a value outside [1e3, 1.5e12] Pa is most likely in the wrong unit (MPa or GPa
/// typed as a number of Pa). Any E > 0 is valid; this only decides when to ask.
inline constexpr double plausible_youngs_modulus_min = 1e3;   ///< [Pa]
inline constexpr double plausible_youngs_modulus_max = 1.5e12;  ///< [Pa]
bool plausible_youngs_modulus(double youngs_modulus);
/// "E = 70 Pa is outside 1e3-1.5e12 Pa, ...: is it in the unit [Pa] (70 GPa would be 7e+10 Pa)?"
/// for an implausible E, naming it `name` ("E", "E2"); "" for a plausible one.
std::string youngs_modulus_unit_question(std::string_view name, double youngs_modulus);

/// Maps a field name ("E", "nu", "density", "gamma") to the name the user knows
/// it by (an option such as "--nu2", or "water-ice.poisson_ratio" in a file).
using FieldNamer = std::function<std::string(std::string_view field)>;

/// Throws InvalidArgument unless E > 0, -1 < nu < 0.5, density > 0, gamma >= 0
/// (if given), all finite.
void validate(const Material& material, const FieldNamer& name_of);
void validate(const Material& material);

}  // namespace bounce
