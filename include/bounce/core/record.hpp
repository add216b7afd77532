#pragma once
// What the front door returns: results as named values, one serialisation for every front
// end. The CLI prints a Record as JSON (and a Table as CSV), Python turns it into a dict (a
// Table into a dict of numpy arrays), so both carry the same keys and values.

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace bounce {

class Value;
class Record;
struct Table;

/// A value held through a pointer, copied deeply: lets Value contain the containers that
/// contain Values (the types are complete only after Value).
template <class T>
class Box {
 public:
  explicit Box(T value) : p_(std::make_unique<T>(std::move(value))) {}
  Box(const Box& other) : p_(std::make_unique<T>(*other.p_)) {}
  Box(Box&&) noexcept = default;
  Box& operator=(const Box& other) {
    p_ = std::make_unique<T>(*other.p_);
    return *this;
  }
  Box& operator=(Box&&) noexcept = default;
  ~Box() = default;
  const T& operator*() const { return *p_; }
  const T* operator->() const { return p_.get(); }

 private:
  std::unique_ptr<T> p_;
};

class Value {
 public:
  using List = std::vector<Value>;
  using Data = std::variant<std::monostate, bool, std::int64_t, double, std::string, Box<List>, Box<Record>, Box<Table>>;

  Value() = default;
  Value(std::nullptr_t) {}
  Value(bool b) : data_(b) {}
  Value(int i) : data_(std::int64_t{i}) {}
  Value(long i) : data_(std::int64_t{i}) {}
  Value(long long i) : data_(std::int64_t{i}) {}
  Value(unsigned long i) : data_(static_cast<std::int64_t>(i)) {}
  Value(double x) : data_(x) {}
  Value(const char* s) : data_(std::string(s)) {}
  Value(std::string s) : data_(std::move(s)) {}
  Value(std::string_view s) : data_(std::string(s)) {}
  Value(List list);
  Value(Record record);
  Value(Table table);
  Value(const std::vector<double>& numbers);
  Value(const std::vector<std::string>& texts);

  const Data& data() const noexcept { return data_; }
  bool is_null() const { return std::holds_alternative<std::monostate>(data_); }
  /// The number (integers too); std::bad_variant_access for anything else.
  double number() const;
  const std::string& text() const { return std::get<std::string>(data_); }
  const List& list() const;
  const Record& record() const;
  const Table& table() const;

 private:
  Data data_;
};

/// Named values in the order they were set (JSON printing sorts the keys).
class Record {
 public:
  /// Sets `key` (replacing an earlier value of it); returns *this for chaining.
  Record& set(std::string key, Value value);
  const Value* find(std::string_view key) const;
  const Value& at(std::string_view key) const;  ///< std::out_of_range without the key
  bool contains(std::string_view key) const { return find(key) != nullptr; }
  const std::vector<std::pair<std::string, Value>>& fields() const noexcept { return fields_; }
  bool empty() const noexcept { return fields_.empty(); }

 private:
  std::vector<std::pair<std::string, Value>> fields_;
};

/// Rows of equal columns (a trajectory, a curve): a list of records in JSON, CSV rows on
/// a command line, one array per column in Python.
struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<Value>> rows;
};

/// A Record of name -> number pairs (the named_values() of the library's result structs).
Record to_record(const std::vector<std::pair<std::string, double>>& named);

}  // namespace bounce
