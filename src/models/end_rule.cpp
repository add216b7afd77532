#include "bounce/models/end_rule.hpp"

#include <string>

#include "bounce/core/error.hpp"

namespace bounce::models {

std::string_view to_string(EndRule rule) {
  switch (rule) {
    case EndRule::overlap: return "overlap";
    case EndRule::force: return "force";
    case EndRule::fold: return "fold";
    case EndRule::pull_off: return "pull-off";
  }
  return "overlap";
}

EndRule parse_end_rule(std::string_view text) {
  for (EndRule rule : {EndRule::overlap, EndRule::force, EndRule::fold, EndRule::pull_off}) {
    if (text == to_string(rule)) return rule;
  }
  throw InvalidArgument("contact_end", std::string(text), "overlap, force, fold or pull-off");
}

}  // namespace bounce::models
