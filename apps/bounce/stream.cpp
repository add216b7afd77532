#include "stream.hpp"

#include <cmath>
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "output.hpp"

namespace bounce::cli {

namespace {

std::string indent(int depth) { return std::string(static_cast<std::size_t>(2 * depth), ' '); }

void require_finite_element(const Value& v) {
  if (const std::string at = non_finite_at(v); !at.empty()) {
    throw NumericalError(fmt::format("result {} is outside the range of double precision (inputs too extreme for this "
                                     "computation); refusing to print it",
                                     at));
  }
}

}  // namespace

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
