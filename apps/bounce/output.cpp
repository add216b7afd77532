#include "output.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <iostream>

#include <fmt/format.h>

#include "bounce/core/checks.hpp"
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

// `null_refused`: a saved table has no nulls, so one there is a non-finite number that
// nlohmann wrote as null.
void check_finite(const nlohmann::json& value, const std::string& path, bool null_refused = false) {
  if (null_refused && value.is_null()) {
    throw NumericalError(fmt::format("table value {} is not finite; refusing to print the table", path));
  }
  if (value.is_number_float() && !std::isfinite(value.get<double>())) {
    throw NumericalError(fmt::format("result {} = {} is outside the range of double precision (inputs too extreme "
                                     "for this computation); refusing to print it",
                                     path.substr(path.find('.') + 1), value.get<double>()));
  }
  if (value.is_object()) {
    for (const auto& [key, item] : value.items()) check_finite(item, path + "." + key, null_refused);
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) {
      check_finite(value[i], path + "[" + std::to_string(i) + "]", null_refused);
    }
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

void require_finite(const Value& result) { check_finite(to_json(result), "$"); }

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

void print_text(const std::string& text, const std::string& json) {
  check_finite(nlohmann::json::parse(json), "table", true);
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
  // One line per kind of warning: the last row's (the fastest or largest), and how many rows had it.
  std::map<std::string, std::pair<std::string, int>> kinds;
  std::vector<std::string> order;
  const std::function<void(const Value&, const std::string&)> walk = [&](const Value& v, const std::string& where) {
    if (const auto* list = std::get_if<Box<Value::List>>(&v.data())) {
      for (const Value& item : **list) walk(item, where);
      return;
    }
    const auto* boxed = std::get_if<Box<Record>>(&v.data());
    if (boxed == nullptr) return;
    const Record& r = **boxed;
    std::string here = where;
    for (const char* key : {"velocity", "radius"}) {
      if (r.contains(key) && std::holds_alternative<double>(r.at(key).data())) {
        here = fmt::format("at {} {:g}: ", key, r.at(key).number());
      }
    }
    for (const auto& [key, item] : r.fields()) {
      if (key != "warnings") {
        walk(item, here);
        continue;
      }
      for (const Value& w : item.list()) {
        auto [it, fresh] = kinds.try_emplace(message_kind(w.text()), here + w.text(), 0);
        if (fresh) order.push_back(it->first);
        it->second = {here + w.text(), it->second.second + 1};
      }
    }
  };
  walk(result, "");
  for (const std::string& kind : order) {
    const auto& [text, rows] = kinds.at(kind);
    std::cerr << "bounce: warning: " << text << (rows > 1 ? fmt::format(" ({} rows in all)", rows) : "") << '\n';
  }
}

Progress::Progress(std::string what, bool forced)
    : what_(std::move(what)), enabled_(forced || ::isatty(STDERR_FILENO)), start_(now_seconds()) {}

void Progress::operator()(std::size_t done, std::size_t total) {
  if (!enabled_) return;
  const double t = now_seconds() - start_;
  if ((total == 0 || done < total) && t - last_ < 1.0) return;  // at most once a second
  last_ = t;
  if (total == 0) {  // an adaptive run: its size is not known in advance
    std::cerr << fmt::format("{}: {} collisions, {:.1f} s\n", what_, done, t);
    return;
  }
  std::cerr << fmt::format("{}: {}/{} ({:.0f}%) {:.1f} s\n", what_, done, total,
                           100.0 * static_cast<double>(done) / static_cast<double>(total), t);
}

int run_guarded(const std::function<int()>& body, const std::set<std::string>& options, const api::Inputs& typed) {
  try {
    const int code = body();
    std::cout.flush();
    if (!std::cout) {  // a write error is an error: the results did not arrive
      std::cerr << "bounce: error: could not write the results (standard output failed)\n";
      return 3;
    }
    return code;
  } catch (const InvalidArgument& caught) {
    const InvalidArgument e = api::as_typed(caught, typed);
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
