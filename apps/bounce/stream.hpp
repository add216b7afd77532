#pragma once
// Output written as it is computed (docs/cli.md, "Memory"): JSON without building a tree in
// memory, CSV rows one at a time (each flushed, so that Ctrl-C keeps them), a curve's JSON points
// spooled to a temporary file until its boundaries are known, and warnings tallied as rows go.

#include <cstdio>
#include <map>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "bounce/api/json.hpp"
#include "bounce/core/record.hpp"

namespace bounce::cli {

/// The library's JSON writer (bounce/api/json.hpp), which the explorer shares.
using api::non_finite_at;
using api::write_json;

/// A CSV written to stdout as it comes: the header with the first rows, then each row as one
/// line, flushed (a Ctrl-C keeps the rows written, docs/cli.md).
class CsvStream {
 public:
  /// The rows of `rows` (its columns printed as the header the first time).
  void write(const Table& rows);

 private:
  bool header_written_ = false;
};

/// The validity warnings of results, gathered as they go and printed on stderr at the end: one
/// line per kind (`bounce: warning: at velocity 3: ...`), from the last row that had it, with
/// the number of rows that had it.
class WarningTally {
 public:
  void add(const Value& result);
  void print() const;

 private:
  void walk(const Value& value, const std::string& where);
  std::map<std::string, std::pair<std::string, int>> kinds_;
  std::vector<std::string> order_;
};

/// A JSON list written to stdout element by element ("[", the elements, "]"): the elements are
/// never all in memory.
class JsonListStream {
 public:
  void add(const Value& element);  ///< refused (NumericalError) when a number in it is not finite
  void close();                    ///< the closing bracket ("[]" for no element)

 private:
  bool first_ = true;
};

/// JSON text kept in a temporary file (in memory if none can be made) until it is printed:
/// a curve's points wait there for its boundaries, which its JSON prints first (keys sorted).
class JsonSpool {
 public:
  JsonSpool();
  ~JsonSpool();
  JsonSpool(const JsonSpool&) = delete;
  JsonSpool& operator=(const JsonSpool&) = delete;
  /// One more element of a list at `depth` (refused when a number in it is not finite).
  void add(const Value& element, int depth);
  /// The elements as a JSON list at `depth`, to `out`.
  void print_list(std::ostream& out, int depth);
  std::size_t size() const { return count_; }

 private:
  std::FILE* file_ = nullptr;
  std::string memory_;
  std::size_t count_ = 0;
};

}  // namespace bounce::cli
