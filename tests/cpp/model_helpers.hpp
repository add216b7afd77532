#pragma once
// Tests' shorthand: a registry model for a pair from named parameters, as every front end
// makes one (models/registry.hpp).

#include <string_view>

#include "bounce/analysis/collide.hpp"
#include "bounce/core/parameters.hpp"
#include "bounce/models/registry.hpp"

namespace bounce::testing {

inline models::Model model(const Pair& pair, std::string_view name, const ParameterInputs& parameters = {}) {
  return models::make_model(pair, name, parameters);
}

/// The viscoelastic model with dissipative constant A [s] and an end rule.
inline models::Model viscoelastic(const Pair& pair, double a, const char* contact_end = "overlap") {
  return model(pair, "viscoelastic", {{"A", a}, {"contact_end", std::string(contact_end)}});
}

}  // namespace bounce::testing
