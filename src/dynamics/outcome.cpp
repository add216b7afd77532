#include "bounce/dynamics/outcome.hpp"

#include <string>

#include "bounce/core/error.hpp"

namespace bounce::dynamics {

void EnergyBudget::close() {
  closure_error = initial_kinetic - final_kinetic - bulk_dissipated - crack_dissipated - plastic_dissipated -
                  elastic_remaining - surface_remaining;
}

std::string_view to_string(Outcome outcome) {
  return outcome == Outcome::bounce ? "bounce" : "stick";
}

}  // namespace bounce::dynamics
