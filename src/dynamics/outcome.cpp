#include "bounce/dynamics/outcome.hpp"

#include <string>

#include "bounce/core/error.hpp"

namespace bounce::dynamics {

std::string_view to_string(EndRule rule) { return rule == EndRule::overlap ? "overlap" : "force"; }

EndRule parse_end_rule(std::string_view text) {
  if (text == "overlap") return EndRule::overlap;
  if (text == "force") return EndRule::force;
  throw InvalidArgument("contact_end", std::string(text), "overlap or force");
}

std::string_view to_string(Outcome outcome) {
  return outcome == Outcome::bounce ? "bounce" : "stick";
}

}  // namespace bounce::dynamics
