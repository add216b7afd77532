#include "bounce/dynamics/outcome.hpp"

#include <string>

#include "bounce/core/error.hpp"

namespace bounce::dynamics {

std::string_view to_string(Outcome outcome) {
  return outcome == Outcome::bounce ? "bounce" : "stick";
}

}  // namespace bounce::dynamics
