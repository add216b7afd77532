#include "bounce/pair/material.hpp"

#include <fmt/format.h>

#include "bounce/core/checks.hpp"

namespace bounce {

void validate(const Material& m, const FieldNamer& name_of) {
  require_positive(name_of("E"), m.youngs_modulus, "Young's modulus E [Pa]");
  require_open_interval(name_of("nu"), m.poisson_ratio, -1.0, 0.5, "Poisson ratio nu");
  require_positive(name_of("density"), m.density, "density [kg/m^3]");
  if (m.surface_energy) {
    require_non_negative(name_of("gamma"), *m.surface_energy, "surface energy gamma [J/m^2]");
    if (*m.surface_energy > 1e3) {  // the bound of --gamma (pair_parameters.cpp): W0 overflows far above it
      throw InvalidArgument(name_of("gamma"), format_value(*m.surface_energy), "0 <= surface energy gamma [J/m^2] <= 1000");
    }
  }
}

bool plausible_youngs_modulus(double e) {
  return e >= plausible_youngs_modulus_min && e <= plausible_youngs_modulus_max;
}

std::string youngs_modulus_unit_question(std::string_view name, double e) {
  if (plausible_youngs_modulus(e)) return "";
  // Below the range, a modulus typed in GPa is the likely slip (70 for 70 GPa).
  const std::string hint = e < plausible_youngs_modulus_min ? fmt::format(" ({:g} GPa would be {:g} Pa)", e, e * 1e9) : "";
  return fmt::format("{} = {:g} Pa is outside {:g}-{:g} Pa, the range of grain materials from soft gels to diamond: "
                     "is it in the unit [Pa]{}?",
                     name, e, plausible_youngs_modulus_min, plausible_youngs_modulus_max, hint);
}

void validate(const Material& m) {
  const std::string prefix = m.name.empty() ? std::string("material.") : m.name + ".";
  validate(m, [&](std::string_view field) { return prefix + std::string(field); });
}

}  // namespace bounce
