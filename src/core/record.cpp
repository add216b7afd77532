#include "bounce/core/record.hpp"

#include <stdexcept>

namespace bounce {

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

Value::Value(const std::vector<double>& numbers) {
  List list(numbers.begin(), numbers.end());
  data_ = std::move(list);
}

Value::Value(const std::vector<std::string>& texts) {
  List list(texts.begin(), texts.end());
  data_ = std::move(list);
}

double Value::number() const {
  if (const auto* i = std::get_if<std::int64_t>(&data_)) return static_cast<double>(*i);
  return std::get<double>(data_);
}

Record to_record(const std::vector<std::pair<std::string, double>>& named) {
  Record r;
  for (const auto& [key, value] : named) r.set(key, value);
  return r;
}

}  // namespace bounce
