#include "bounce/core/record.hpp"

#include <stdexcept>

namespace bounce {

Value::Value(List list) : data_(Box<List>(std::move(list))) {}
Value::Value(Record record) : data_(Box<Record>(std::move(record))) {}
Value::Value(Table table) : data_(Box<Table>(std::move(table))) {}
Value::Value(const std::vector<double>& numbers) : Value(List(numbers.begin(), numbers.end())) {}
Value::Value(const std::vector<std::string>& texts) : Value(List(texts.begin(), texts.end())) {}

double Value::number() const {
  if (const auto* i = std::get_if<std::int64_t>(&data_)) return static_cast<double>(*i);
  return std::get<double>(data_);
}

const Value::List& Value::list() const { return *std::get<Box<List>>(data_); }
const Record& Value::record() const { return *std::get<Box<Record>>(data_); }
const Table& Value::table() const { return *std::get<Box<Table>>(data_); }

Record& Record::set(std::string key, Value value) {
  for (auto& [k, v] : fields_) {
    if (k == key) {
      v = std::move(value);
      return *this;
    }
  }
  fields_.emplace_back(std::move(key), std::move(value));
  return *this;
}

const Value* Record::find(std::string_view key) const {
  for (const auto& [k, v] : fields_) {
    if (k == key) return &v;
  }
  return nullptr;
}

const Value& Record::at(std::string_view key) const {
  const Value* v = find(key);
  if (v == nullptr) throw std::out_of_range("no key " + std::string(key) + " in the record");
  return *v;
}

Record to_record(const std::vector<std::pair<std::string, double>>& named) {
  Record r;
  for (const auto& [key, value] : named) r.set(key, value);
  return r;
}

}  // namespace bounce
