// Uses the installed bounce library: JKR pull-off of two 1 um water-ice spheres.
#include <cmath>
#include <cstdio>
#include <numbers>

#include <bounce/contact/jkr.hpp>
#include <bounce/pair/materials_table.hpp>
#include <bounce/pair/pair.hpp>

int main() {
  const bounce::Material ice = bounce::MaterialTable::builtin().at("water-ice");
  const bounce::Pair pair = bounce::Pair::identical(ice, 1e-6);
  const bounce::contact::jkr::Parameters p{pair.effective_radius(), pair.effective_modulus(),
                                  *pair.surface_energy()};
  const double pull_off = bounce::contact::jkr::pull_off_force(p);
  const double expected = -1.5 * std::numbers::pi * 0.37 * 0.5e-6;
  std::printf("JKR pull-off of two 1 um water-ice spheres: %.6g N\n", pull_off);
  return std::abs(pull_off / expected - 1.0) < 1e-12 ? 0 : 1;
}
