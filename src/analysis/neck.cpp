#include "neck.hpp"

#include <cmath>

#include <fmt/format.h>

#include "bounce/analytic/adhesive.hpp"

namespace bounce::analysis::detail {

void add_neck_work(dynamics::CollisionOutcome& out, const Pair& pair) {  // BP04 (8.94)-(8.98), (8.100)
  if (out.outcome == dynamics::Outcome::stick) return;
  const double w0 = analytic::tensile_work(pair.effective_radius(), pair.effective_modulus(), *pair.surface_energy());
  dynamics::EnergyBudget& e = out.energy;
  const double left = e.final_kinetic - w0;  // (8.97)
  if (left > 0.0) {
    e.crack_dissipated += w0;
    e.final_kinetic = left;
    out.cor = std::sqrt(left / e.initial_kinetic);  // (8.98)
    out.notes.push_back(fmt::format("BP04 (8.97): the neck's tensile work W0 = {:.6g} J (8.95) is taken from the "
                                    "rebound (in crack_dissipated)", w0));
  } else {
    out.notes.push_back(fmt::format("BP04 (8.100): the rebound's kinetic energy {:.6g} J is below the neck's tensile "
                                    "work W0 = {:.6g} J (8.95): the grains stick", e.final_kinetic, w0));
    e.crack_dissipated += e.final_kinetic;
    e.final_kinetic = 0.0;
    out.cor = 0.0;
    out.outcome = dynamics::Outcome::stick;
  }
  e.close();
}

}  // namespace bounce::analysis::detail
