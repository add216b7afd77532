#pragma once
// The text layer of a measured restitution curve's CSV (docs/fitting.md, "The data"): what real
// files written by spreadsheets and instruments hold around the numbers. A UTF-8 byte-order
// mark, a delimiter other than the comma (tab or semicolon, sniffed from the header), fields in
// double quotes, header names in any case with a unit in brackets (`Velocity [m/s]`), a decimal
// comma where the delimiter is a semicolon or a tab.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bounce::analysis::detail {

/// `s` without leading and trailing spaces, tabs and carriage returns.
std::string_view trim(std::string_view s);
/// `s` in ASCII lower case.
std::string lower(std::string_view s);

/// `text` without a UTF-8 byte-order mark; InvalidArgument(`source`) for a UTF-16 or UTF-32
/// one (a file saved as "Unicode text": the reader takes UTF-8 or ASCII).
std::string_view strip_byte_order_mark(std::string_view text, std::string_view source);

/// The delimiter of a header line: a tab if it holds one (outside quotes), else a semicolon if
/// it holds one, else a comma.
char sniff_delimiter(std::string_view header);

/// The fields of one line split at `delimiter` (outside double quotes), each trimmed of spaces
/// and its quotes removed (`""` inside quotes is one `"`); nullopt for a quote left open.
std::optional<std::vector<std::string>> split_fields(std::string_view line, char delimiter);

/// A header cell read: its name in lower case without its unit, and the unit ("" when none),
/// from `Velocity [m/s]`, `velocity (m/s)` or `velocity`.
struct HeaderName {
  std::string name;
  std::string unit;
};
HeaderName read_header_name(std::string_view cell);

/// `field` as a number with a decimal comma read as a point (`0,52`) when the file's
/// delimiter is not the comma; the field unchanged otherwise.
std::string decimal_point(std::string_view field, char delimiter);

/// What a unit of a column means in SI: the factor to m/s for a speed (`m/s`, `cm/s`, `mm/s`,
/// spaces and `m s^-1` forms allowed), 1 for a dimensionless column (`-`, `1` or none);
/// nullopt for a unit that is not the column's.
std::optional<double> unit_factor(std::string_view column, std::string_view unit);

}  // namespace bounce::analysis::detail
