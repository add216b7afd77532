#pragma once
// The CLI's output: Records as JSON, Tables as CSV (never a NaN or an infinity: a
// non-finite number is a NumericalError), progress on stderr, and the error policy.

#include <cstddef>
#include <functional>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "bounce/api/front_door.hpp"
#include "bounce/core/record.hpp"

namespace bounce::cli {

/// A Value as JSON (a Table as a list of objects).
nlohmann::json to_json(const Value& value);
/// Print a Value as JSON (2-space indent, keys sorted).
void print_json(const Value& value);
/// Print a Table as CSV: a header line, then one row per line; numbers in their shortest
/// round-trip form, text quoted when it holds a space, a comma or a quote, null empty.
void print_csv(const Table& table);
/// Refuse a result holding a NaN or an infinity anywhere (NumericalError naming the field):
/// every output format goes through this, so no format can print one.
void require_finite(const Value& result);
/// One CSV cell: numbers in their shortest round-trip form, text quoted when it holds a space,
/// a comma or a quote, null empty; NumericalError for a number that is not finite.
std::string csv_cell(const Value& v, std::size_t column);
/// Write `text`, the words for `result`, to stdout, after require_finite(result).
void print_text(const Value& result, const std::string& text);
/// Write generated text (a table as JSON, CSV or C) to stdout. `json`: the same content as
/// JSON, refused (NumericalError) when a number in it is not finite.
void print_text(const std::string& text, const std::string& json);

/// Warnings on stderr (`bounce: warning: ...`), for outputs that have no place for them
/// (CSV, tables): every "warnings" list in `result`, each message once, with the
/// velocity or radius of the row it came from.
void print_warnings(const Value& result);
void print_warnings(const std::vector<std::string>& warnings);

/// Progress on stderr for long runs: shown when stderr is a terminal or `forced`, at most
/// once a second.
class Progress {
 public:
  Progress(std::string what, bool forced);
  void operator()(std::size_t done, std::size_t total);

 private:
  std::string what_;
  bool enabled_;
  double start_;
  double last_ = -1.0;
  std::size_t last_total_ = 0;
};

/// Standard output failed: thrown by the streams at the first row that could not be written, so
/// that the computation stops there.
struct OutputFailed {};
/// Throws OutputFailed when std::cout has failed.
void require_output();

/// Runs a command under the error policy: InvalidArgument -> one line on stderr naming the
/// option (a parameter in `options` as --name) and its value as typed (`typed`, the inputs
/// given), exit 2; NumericalError -> one line, exit 3; anything else -> exit 4. A failed write
/// to stdout is an error too (exit 3): the results did not arrive; but a reader that went away
/// (`| head -2` where SIGPIPE is ignored: EPIPE) is a normal end, exit 0 and nothing said, as
/// SIGPIPE's default would have ended it.
int run_guarded(const std::function<int()>& body, const std::set<std::string>& options, const api::Inputs& typed = {});

}  // namespace bounce::cli
