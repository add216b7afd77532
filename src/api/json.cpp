// The JSON writer of the front ends (include/bounce/api/json.hpp).
#include "bounce/api/json.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace bounce::api {

namespace {

std::string indent(int depth) { return std::string(static_cast<std::size_t>(2 * depth), ' '); }

// A scalar exactly as nlohmann writes it (shortest round-trip numbers, 2.0 with its ".0",
// escaped strings; bytes that are not UTF-8 replaced rather than thrown on).
template <class T>
std::string scalar(const T& x) {
  return nlohmann::json(x).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

// An object or a list: `items` calls back with each member's key (objects) and value.
template <class Items>
void write_container(std::ostream& out, int depth, bool object, std::size_t count, const Items& items) {
  if (count == 0) {
    out << (object ? "{}" : "[]");
    return;
  }
  out << (object ? "{\n" : "[\n");
  for (std::size_t i = 0; i < count; ++i) {
    out << indent(depth + 1);
    items(i);
    out << (i + 1 < count ? ",\n" : "\n");
  }
  out << indent(depth) << (object ? '}' : ']');
}

void write_record(std::ostream& out, const Record& r, int depth) {
  std::vector<const std::pair<std::string, Value>*> fields;
  for (const auto& field : r.fields()) fields.push_back(&field);
  std::sort(fields.begin(), fields.end(), [](const auto* a, const auto* b) { return a->first < b->first; });
  write_container(out, depth, true, fields.size(), [&](std::size_t i) {
    out << scalar(fields[i]->first) << ": ";
    write_json(out, fields[i]->second, depth + 1);
  });
}

// A Table as nlohmann writes a list of row objects: each row's keys sorted.
void write_table(std::ostream& out, const Table& t, int depth) {
  std::vector<std::size_t> order(t.columns.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return t.columns[a] < t.columns[b]; });
  write_container(out, depth, false, t.rows.size(), [&](std::size_t r) {
    const auto& row = t.rows[r];
    write_container(out, depth + 1, true, order.size(), [&](std::size_t k) {
      out << scalar(t.columns[order[k]]) << ": ";
      write_json(out, row[order[k]], depth + 2);
    });
  });
}

struct Writer {
  std::ostream& out;
  int depth;
  void operator()(std::monostate) const { out << "null"; }
  void operator()(bool b) const { out << (b ? "true" : "false"); }
  void operator()(std::int64_t i) const { out << scalar(i); }
  void operator()(double x) const { out << scalar(x); }
  void operator()(const std::string& s) const { out << scalar(s); }
  void operator()(const Box<Value::List>& list) const {
    write_container(out, depth, false, list->size(), [&](std::size_t i) { write_json(out, (*list)[i], depth + 1); });
  }
  void operator()(const Box<Record>& r) const { write_record(out, *r, depth); }
  void operator()(const Box<Table>& t) const { write_table(out, *t, depth); }
};

// The path of the first non-finite number below `v` ("$.energy.final_kinetic"), or "".
std::string find_non_finite(const Value& v, const std::string& path, double& bad) {
  const auto& data = v.data();
  if (const auto* x = std::get_if<double>(&data)) {
    if (std::isfinite(*x)) return {};
    bad = *x;
    return path;
  }
  if (const auto* list = std::get_if<Box<Value::List>>(&data)) {
    for (std::size_t i = 0; i < (*list)->size(); ++i) {
      if (auto p = find_non_finite((**list)[i], fmt::format("{}[{}]", path, i), bad); !p.empty()) return p;
    }
  } else if (const auto* r = std::get_if<Box<Record>>(&data)) {
    for (const auto& [key, item] : (*r)->fields()) {
      if (auto p = find_non_finite(item, path + "." + key, bad); !p.empty()) return p;
    }
  } else if (const auto* t = std::get_if<Box<Table>>(&data)) {
    for (std::size_t i = 0; i < (*t)->rows.size(); ++i) {
      for (std::size_t c = 0; c < (*t)->columns.size(); ++c) {
        const std::string at = fmt::format("{}[{}].{}", path, i, (*t)->columns[c]);
        if (auto p = find_non_finite((*t)->rows[i][c], at, bad); !p.empty()) return p;
      }
    }
  }
  return {};
}

}  // namespace

void write_json(std::ostream& out, const Value& value, int depth) { std::visit(Writer{out, depth}, value.data()); }

std::string non_finite_at(const Value& value) {
  double bad = 0.0;
  const std::string path = find_non_finite(value, "$", bad);
  if (path.empty()) return {};
  return fmt::format("{} = {}", path.substr(path.find('.') + 1), bad);
}

}  // namespace bounce::api
