#include "stream.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numeric>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "output.hpp"

namespace bounce::cli {

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

void require_finite_element(const Value& v) {
  if (const std::string at = non_finite_at(v); !at.empty()) {
    throw NumericalError(fmt::format("result {} is outside the range of double precision (inputs too extreme for this "
                                     "computation); refusing to print it",
                                     at));
  }
}

}  // namespace

void write_json(std::ostream& out, const Value& value, int depth) { std::visit(Writer{out, depth}, value.data()); }

std::string non_finite_at(const Value& value) {
  double bad = 0.0;
  const std::string path = find_non_finite(value, "$", bad);
  if (path.empty()) return {};
  return fmt::format("{} = {}", path.substr(path.find('.') + 1), bad);
}

void CsvStream::write(const Table& rows) {
  std::string text;
  if (!header_written_) {
    for (std::size_t i = 0; i < rows.columns.size(); ++i) text += (i ? "," : "") + rows.columns[i];
    text += '\n';
    header_written_ = true;
  }
  for (const auto& row : rows.rows) {
    for (std::size_t i = 0; i < row.size(); ++i) text += (i ? "," : "") + csv_cell(row[i], i);
    text += '\n';
    std::cout << text << std::flush;
    require_output();  // a closed pipe stops the computation at the first row it refuses
    text.clear();
  }
  if (!text.empty()) std::cout << text << std::flush;  // a header without rows
  require_output();
}

void WarningTally::add(const Value& result) { walk(result, ""); }

// One line per kind of warning: the last row's (the fastest or largest), and how many rows had it.
void WarningTally::walk(const Value& v, const std::string& where) {
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
      auto [it, fresh] = kinds_.try_emplace(message_kind(w.text()), here + w.text(), 0);
      if (fresh) order_.push_back(it->first);
      it->second = {here + w.text(), it->second.second + 1};
    }
  }
}

void WarningTally::print() const {
  for (const std::string& kind : order_) {
    const auto& [text, rows] = kinds_.at(kind);
    std::cerr << "bounce: warning: " << text << (rows > 1 ? fmt::format(" ({} rows in all)", rows) : "") << '\n';
  }
}

void JsonListStream::add(const Value& element) {
  require_finite_element(element);
  std::cout << (first_ ? "[\n" : ",\n") << indent(1);
  write_json(std::cout, element, 1);
  std::cout.flush();
  require_output();
  first_ = false;
}

void JsonListStream::close() { std::cout << (first_ ? "[]" : "\n]") << '\n'; }

JsonSpool::JsonSpool() : file_(std::tmpfile()) {}

JsonSpool::~JsonSpool() {
  if (file_ != nullptr) std::fclose(file_);
}

void JsonSpool::add(const Value& element, int depth) {
  require_finite_element(element);
  std::ostringstream text;
  text << (count_ == 0 ? "" : ",\n") << indent(depth + 1);
  write_json(text, element, depth + 1);
  const std::string s = text.str();
  if (file_ == nullptr || std::fwrite(s.data(), 1, s.size(), file_) != s.size()) {
    if (file_ != nullptr) throw NumericalError("could not write the temporary file that holds the points (disk full?)");
    memory_ += s;
  }
  ++count_;
}

void JsonSpool::print_list(std::ostream& out, int depth) {
  if (count_ == 0) {
    out << "[]";
    return;
  }
  out << "[\n";
  if (file_ != nullptr) {
    std::rewind(file_);
    std::vector<char> buffer(std::size_t{1} << 16);
    std::size_t n = 0;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), file_)) > 0) out.write(buffer.data(), static_cast<std::streamsize>(n));
  } else {
    out << memory_;
  }
  out << '\n' << indent(depth) << ']';
}

}  // namespace bounce::cli
