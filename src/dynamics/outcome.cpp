#include "bounce/dynamics/outcome.hpp"

#include <string>

#include "bounce/core/error.hpp"

namespace bounce::dynamics {

void EnergyBudget::close() {
  closure_error = initial_kinetic - final_kinetic - bulk_dissipated - crack_dissipated - plastic_dissipated -
                  elastic_remaining - surface_remaining;
}

std::vector<std::pair<std::string, double>> named_values(const EnergyBudget& e) {
  return {{"initial_kinetic", e.initial_kinetic},     {"final_kinetic", e.final_kinetic},
          {"bulk_dissipated", e.bulk_dissipated},     {"crack_dissipated", e.crack_dissipated},
          {"plastic_dissipated", e.plastic_dissipated}, {"elastic_remaining", e.elastic_remaining},
          {"surface_remaining", e.surface_remaining}, {"closure_error", e.closure_error}};
}

std::vector<std::pair<std::string, double>> named_values(const TangentialOutcome& t) {
  return {{"cor", t.cor},
          {"initial_kinetic", t.initial_kinetic},
          {"final_kinetic", t.final_kinetic},
          {"asperity_dissipated", t.asperity_dissipated},
          {"stored_at_end", t.stored_at_end},
          {"stiffness_work", t.stiffness_work},
          {"averaged_time", t.averaged_time}};
}

std::string_view to_string(Outcome outcome) {
  return outcome == Outcome::bounce ? "bounce" : "stick";
}

}  // namespace bounce::dynamics
