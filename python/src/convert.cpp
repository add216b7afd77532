#include "convert.hpp"

#include <cmath>

#include <pybind11/stl.h>

#include "bounce/core/error.hpp"

namespace bounce::python {

namespace {

struct ToPython {
  py::object operator()(std::monostate) const { return py::none(); }
  py::object operator()(bool b) const { return py::bool_(b); }
  py::object operator()(std::int64_t i) const { return py::int_(i); }
  py::object operator()(double x) const { return py::float_(x); }
  py::object operator()(const std::string& s) const { return py::str(s); }
  py::object operator()(const Box<Value::List>& list) const {
    py::list out;
    for (const Value& v : *list) out.append(to_python(v));
    return out;
  }
  py::object operator()(const Box<Record>& r) const {
    py::dict out;
    for (const auto& [key, value] : r->fields()) out[py::str(key)] = to_python(value);
    return out;
  }
  py::object operator()(const Box<Table>& t) const { return table_to_python(*t); }
};

bool text_column(const Table& t, std::size_t c) {
  for (const auto& row : t.rows) {
    if (std::holds_alternative<std::string>(row[c].data())) return true;
  }
  return false;
}

}  // namespace

py::object to_python(const Value& value) { return std::visit(ToPython{}, value.data()); }

py::dict table_to_python(const Table& t) {
  py::dict out;
  const auto n = static_cast<py::ssize_t>(t.rows.size());
  for (std::size_t c = 0; c < t.columns.size(); ++c) {
    if (text_column(t, c)) {
      py::list texts;
      for (const auto& row : t.rows) texts.append(to_python(row[c]));
      out[py::str(t.columns[c])] = py::module_::import("numpy").attr("asarray")(texts, "str");
      continue;
    }
    Array column(n);
    for (py::ssize_t i = 0; i < n; ++i) {
      const Value& v = t.rows[static_cast<std::size_t>(i)][c];
      column.mutable_data()[i] = v.is_null() ? std::nan("") : v.number();
    }
    out[py::str(t.columns[c])] = column;
  }
  return out;
}

bool is_number(const py::handle& x) { return py::isinstance<py::float_>(x) || py::isinstance<py::int_>(x); }

ParameterValue to_value(const std::string& name, const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (is_number(value)) return value.cast<double>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::sequence>(value) || py::isinstance<py::array>(value)) {
    try {
      return value.cast<std::vector<double>>();
    } catch (const py::cast_error&) {
    }
  }
  throw py::type_error(name + " = " + py::repr(value).cast<std::string>() +
                       " is invalid: expected a number, a word or a list of numbers");
}

api::Inputs to_inputs(const py::kwargs& kwargs) {
  api::Inputs in;
  for (const auto& [key, value] : kwargs) {
    std::string name = key.cast<std::string>();
    if (name == "yield_strength") name = "yield";
    if (value.is_none()) continue;
    if (name == "follow_time") {  // Python's spelling, where 0 (the default) means "stop when sticking is certain"
      name = "follow";
      if (is_number(value) && value.cast<double>() == 0.0) continue;
    }
    in.insert_or_assign(name, to_value(name, value));
  }
  return in;
}

}  // namespace bounce::python
