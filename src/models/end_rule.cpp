#include "bounce/models/end_rule.hpp"

#include <string>

#include "bounce/core/error.hpp"

namespace bounce::models {

std::string_view to_string(EndRule rule) { return rule == EndRule::overlap ? "overlap" : "force"; }

EndRule parse_end_rule(std::string_view text) {
  if (text == "overlap") return EndRule::overlap;
  if (text == "force") return EndRule::force;
  throw InvalidArgument("contact_end", std::string(text), "overlap or force");
}

}  // namespace bounce::models
