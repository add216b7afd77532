#pragma once
// A Value as JSON text: the one writer of every front end that prints JSON (the CLI's --json,
// the browser explorer's downloads), so that both print the same bytes for the same Record.

#include <ostream>
#include <string>

#include "bounce/core/record.hpp"

namespace bounce::api {

/// `value` as JSON in nlohmann's dump(2) layout (2-space indent, keys sorted; numbers, strings
/// and literals as nlohmann writes them), its first line unindented and the rest indented for
/// nesting at `depth`. The caller has checked that every number is finite (non_finite_at).
void write_json(std::ostream& out, const Value& value, int depth = 0);

/// Where `value` holds a number that is not finite: "contact_time = inf" (a Table's cell as
/// "trajectory[3].overlap = nan"), or "" when every number is finite.
std::string non_finite_at(const Value& value);

}  // namespace bounce::api
