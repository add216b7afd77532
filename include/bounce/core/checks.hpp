#pragma once
// Input checks shared by every layer. Each throws InvalidArgument naming the
// parameter, its value and the allowed range; none lets a NaN or an infinity
// through.

#include <string>
#include <string_view>
#include <vector>

#include "bounce/core/error.hpp"
#include "bounce/core/suggest.hpp"

namespace bounce {

/// Shortest round-trip text of a double ("1e-09", "0.25", "nan", "inf").
std::string format_value(double value);

/// A message without its numbers ("impact velocity 1e+03 m/s is ..." -> "impact velocity  m/s
/// is ..."): warnings of one kind from many collisions are reported once.
std::string message_kind(std::string_view message);

/// value must be finite.
double require_finite(std::string_view parameter, double value);
/// value must be finite and > 0. `what` names the quantity and unit for the message.
double require_positive(std::string_view parameter, double value, std::string_view what);
/// value must be finite and >= 0.
double require_non_negative(std::string_view parameter, double value, std::string_view what);
/// value must be finite and >= lowest; the message says so in words, `before` lowest
/// `after` ("force >= the JKR pull-off force " -1.2e-06 " N"). The words are joined only
/// when the check fails: the contact laws call this once per evaluation (bench_contact).
double require_at_least(std::string_view parameter, double value, double lowest, std::string_view before,
                        std::string_view after);
/// value must be finite and lo < value < hi.
double require_open_interval(std::string_view parameter, double value, double lo, double hi,
                             std::string_view what);

/// The whole text of the file at `path` (a data file, a manifest, a materials table); an
/// empty path, a directory or a file that cannot be read is InvalidArgument(parameter, path,
/// what), with ", not a directory" for a directory.
std::string read_text_file(std::string_view parameter, const std::string& path, std::string_view what);

/// "a, b, c": the names allowed, for a message.
std::string one_of(const std::vector<std::string>& names);

/// A JSON reader's error (nlohmann's exception id and what()) in our words: "not JSON (a syntax
/// error at line 1, column 2)" for a parse error, "a field missing or of the wrong type" for
/// the rest; never the library's own text.
std::string json_error_words(int id, std::string_view what);

/// The row of `rows` (anything with a `name`) called `name`; InvalidArgument(parameter, name,
/// "one of …", with the likely name when `name` looks like a typo of one) when there is none.
/// The registries' lookup (models, contact laws, commands).
template <class Rows>
const auto& find_named(const Rows& rows, std::string_view name, const char* parameter) {
  std::vector<std::string> names;
  for (const auto& row : rows) {
    if (row.name == name) return row;
    names.push_back(row.name);
  }
  throw InvalidArgument(parameter, std::string(name), "one of " + one_of(names) + did_you_mean(name, names));
}

}  // namespace bounce
