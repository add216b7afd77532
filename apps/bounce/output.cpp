#include "output.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "bounce/core/error.hpp"
#include "options.hpp"

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

void check_finite(const nlohmann::json& value, const std::string& path) {
  if (value.is_number_float() && !std::isfinite(value.get<double>())) {
    throw NumericalError("result " + path + " is not finite; refusing to print it");
  }
  if (value.is_object()) {
    for (const auto& [key, item] : value.items()) check_finite(item, path + "." + key);
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) check_finite(value[i], path + "[" + std::to_string(i) + "]");
  }
}

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

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

nlohmann::json to_json(const Value& value) { return std::visit(ToJson{}, value.data()); }

void print_json(const Value& value) {
  const nlohmann::json j = to_json(value);
  check_finite(j, "$");
  std::cout << j.dump(2) << '\n';
}

void print_csv(const Table& table) {
  std::string text;
  for (std::size_t i = 0; i < table.columns.size(); ++i) text += (i ? "," : "") + table.columns[i];
  text += '\n';
  for (const auto& row : table.rows) {
    for (std::size_t i = 0; i < row.size(); ++i) text += (i ? "," : "") + csv_cell(row[i], i);
    text += '\n';
  }
  std::cout << text;
}

void print_text(const std::string& text) { std::cout << text; }

Progress::Progress(std::string what, bool forced)
    : what_(std::move(what)), enabled_(forced || ::isatty(STDERR_FILENO)), start_(now_seconds()) {}

void Progress::operator()(std::size_t done, std::size_t total) {
  if (!enabled_) return;
  const double t = now_seconds() - start_;
  if (done < total && t - last_ < 1.0) return;  // at most once a second
  last_ = t;
  std::cerr << fmt::format("{}: {}/{} ({:.0f}%) {:.1f} s\n", what_, done, total,
                           100.0 * static_cast<double>(done) / static_cast<double>(total), t);
}

int run_guarded(const std::function<int()>& body, const std::set<std::string>& options) {
  try {
    const int code = body();
    std::cout.flush();
    if (!std::cout) {  // a write error is an error: the results did not arrive
      std::cerr << "bounce: error: could not write the results (standard output failed)\n";
      return 3;
    }
    return code;
  } catch (const InvalidArgument& e) {
    const bool option = options.count(e.parameter()) > 0;
    std::cerr << "bounce: error: " << (option ? e.renamed(option_name(e.parameter())).what() : e.what()) << '\n';
    return 2;
  } catch (const NumericalError& e) {
    std::cerr << "bounce: numerical error: " << e.what() << '\n';
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "bounce: internal error: " << e.what() << '\n';
    return 4;
  }
}

}  // namespace bounce::cli
