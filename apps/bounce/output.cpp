#include "output.hpp"

#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <new>
#include <set>
#include <iostream>

#include <fmt/format.h>

#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "options.hpp"
#include "stream.hpp"

namespace bounce::cli {

namespace {

struct ToJson {
  nlohmann::json operator()(std::monostate) const { return nullptr; }
  nlohmann::json operator()(bool b) const { return b; }
  nlohmann::json operator()(std::int64_t i) const { return i; }
  nlohmann::json operator()(double x) const { return x; }
  nlohmann::json operator()(const std::string& s) const { return s; }
  nlohmann::json operator()(const Box<Value::List>& list) const {
    nlohmann::json j = nlohmann::json::array();
    for (const Value& v : *list) j.push_back(to_json(v));
    return j;
  }
  nlohmann::json operator()(const Box<Record>& r) const {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [key, value] : r->fields()) j[key] = to_json(value);
    return j;
  }
  nlohmann::json operator()(const Box<Table>& boxed) const {
    const Table& t = *boxed;
    nlohmann::json j = nlohmann::json::array();
    for (const auto& row : t.rows) {
      nlohmann::json r = nlohmann::json::object();
      for (std::size_t i = 0; i < t.columns.size(); ++i) r[t.columns[i]] = to_json(row[i]);
      j.push_back(r);
    }
    return j;
  }
};

// A saved table (JSON text) has no nulls: one there is a non-finite number that nlohmann wrote
// as null.
void check_table_json(const nlohmann::json& value, const std::string& path) {
  if (value.is_null()) {
    throw NumericalError(fmt::format("table value {} is not finite; refusing to print the table", path));
  }
  if (value.is_object()) {
    for (const auto& [key, item] : value.items()) check_table_json(item, path + "." + key);
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) check_table_json(value[i], path + "[" + std::to_string(i) + "]");
  }
}

// The reader of stdout went away: a pipe whose read end is closed (poll: POLLERR) or a socket
// hung up. A full disk or another failure is not that.
bool reader_gone() {
  if (errno == EPIPE) return true;
  pollfd out{STDOUT_FILENO, POLLOUT, 0};
  return ::poll(&out, 1, 0) == 1 && (out.revents & (POLLERR | POLLHUP)) != 0;
}

int output_failed() {
  if (reader_gone()) return 0;
  std::cerr << "bounce: error: could not write the results (standard output failed)\n";
  return 3;
}

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

nlohmann::json to_json(const Value& value) { return std::visit(ToJson{}, value.data()); }

std::string csv_cell(const Value& v, std::size_t column) {
  if (v.is_null()) return "";
  if (const auto* s = std::get_if<std::string>(&v.data())) {
    return s->find_first_of(" ,\"") == std::string::npos ? *s : '"' + *s + '"';
  }
  if (const auto* i = std::get_if<std::int64_t>(&v.data())) return fmt::format("{}", *i);
  const double x = v.number();
  if (!std::isfinite(x)) throw NumericalError(fmt::format("CSV column {} is not finite; refusing to print it", column + 1));
  return fmt::format("{}", x);
}

void require_finite(const Value& result) {
  if (const std::string at = non_finite_at(result); !at.empty()) {
    throw NumericalError(fmt::format("result {} is outside the range of double precision (inputs too extreme for this "
                                     "computation); refusing to print it",
                                     at));
  }
}

void print_json(const Value& value) {
  require_finite(value);  // before a byte is written
  write_json(std::cout, value);
  std::cout << '\n';
}

void print_csv(const Table& table) { CsvStream().write(table); }

void print_text(const std::string& text, const std::string& json) {
  check_table_json(nlohmann::json::parse(json), "table");
  std::cout << text;
}

void print_text(const Value& result, const std::string& text) {
  require_finite(result);
  std::cout << text;
}

void print_warnings(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings) std::cerr << "bounce: warning: " << w << '\n';
}

void print_warnings(const Value& result) {
  WarningTally tally;
  tally.add(result);
  tally.print();
}

Progress::Progress(std::string what, bool forced)
    : what_(std::move(what)), enabled_(forced || ::isatty(STDERR_FILENO)), start_(now_seconds()) {}

void Progress::operator()(std::size_t done, std::size_t total) {
  if (!enabled_) return;
  const double t = now_seconds() - start_;
  // At most once a second, but at once where a phase of known size gives way to an adaptive one
  // (a fit's grid to its refinement and ranges), so that no phase runs silently.
  const bool phase_change = total == 0 && last_total_ != 0;
  if (!phase_change && (total == 0 || done < total) && t - last_ < 1.0) return;
  last_ = t;
  last_total_ = total;
  if (total == 0) {  // an adaptive run: its size is not known in advance
    std::cerr << fmt::format("{}: {} collisions{}, {:.1f} s\n", what_, done,
                             phase_change ? " (the grid done; refining, its size not known in advance)" : "", t);
    return;
  }
  std::cerr << fmt::format("{}: {}/{} ({:.0f}%) {:.1f} s\n", what_, done, total,
                           100.0 * static_cast<double>(done) / static_cast<double>(total), t);
}

void require_output() {
  if (!std::cout) throw OutputFailed{};
}

int run_guarded(const std::function<int()>& body, const std::set<std::string>& options, const api::Inputs& typed) {
  try {
    const int code = body();
    std::cout.flush();
    return std::cout ? code : output_failed();  // a write error is an error: the results did not arrive
  } catch (const OutputFailed&) {
    return output_failed();
  } catch (const InvalidArgument& caught) {
    const InvalidArgument e = api::as_typed(caught, typed);
    const bool option = options.count(e.parameter()) > 0;
    std::cerr << "bounce: error: " << (option ? e.renamed(option_name(e.parameter())).what() : e.what()) << '\n';
    return 2;
  } catch (const NumericalError& e) {
    std::cerr << "bounce: numerical error: " << e.what() << '\n';
    return 3;
  } catch (const InstallationError& e) {
    std::cerr << "bounce: installation error: " << e.what() << '\n';
    return 3;
  } catch (const std::bad_alloc&) {  // every output is bounded (docs/cli.md, "Memory"): a machine too small
    std::cerr << "bounce: numerical error: out of memory: the computation does not fit in this machine's memory\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "bounce: internal error: " << e.what() << '\n';
    return 4;
  }
}

}  // namespace bounce::cli
