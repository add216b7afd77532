#include "convert.hpp"

#include <cmath>
#include <map>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bounce/api/aggregate.hpp"
#include "bounce/core/checks.hpp"
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

// numpy's abstract scalar types and asarray, looked up once (the module keeps them alive).
struct Numpy {
  py::object integer, floating, bool_, ndarray, asarray;
};
const Numpy& numpy() {
  static const Numpy* np = [] {
    const py::module_ m = py::module_::import("numpy");
    return new Numpy{m.attr("integer"), m.attr("floating"), m.attr("bool_"), m.attr("ndarray"), m.attr("asarray")};
  }();
  return *np;
}

bool is_bool(const py::handle& x) { return PyBool_Check(x.ptr()) || py::isinstance(x, numpy().bool_); }

// A numpy array's dtype holds integers or floats (not bool, complex, text or objects).
bool numeric_dtype(const py::handle& array) {
  const std::string kind = py::str(array.attr("dtype").attr("kind"));
  return kind == "i" || kind == "u" || kind == "f";
}

// What a wrong value is told it should have been: a bool is not a number here.
std::string number_expected(const py::handle& x, std::string_view what) {
  if (is_bool(x)) return fmt::format("{} (True and False are not numbers here)", what);
  return std::string(what);
}

// Every leaf of a (nested) list or tuple is a number.
void check_leaves(std::string_view name, const py::handle& whole, const py::handle& x, std::string_view expected) {
  if (py::isinstance<py::list>(x) || py::isinstance<py::tuple>(x)) {
    for (const py::handle item : x) check_leaves(name, whole, item, expected);
  } else if (!is_number(x)) {
    refuse_type(name, whole, number_expected(x, expected));
  }
}

// Every spec a front end offers, by name (the kinds are what Python checks types against).
const std::map<std::string, ParameterSpec, std::less<>>& declared() {
  static const auto* specs = [] {
    auto* out = new std::map<std::string, ParameterSpec, std::less<>>;
    for (const api::CommandSpec& c : api::commands()) {
      for (ParameterSpec& s : api::offered_parameters(c.name)) out->try_emplace(s.name, std::move(s));
    }
    for (const api::CommandSpec& c : api::aggregate_commands()) {
      for (const ParameterSpec& s : c.parameters) out->try_emplace(s.name, s);
    }
    out->try_emplace("model", api::model_parameter());
    out->try_emplace("law", api::law_parameter());
    return out;
  }();
  return *specs;
}

// A value whose name nothing declares: passed on as well as it converts, so that the front
// door refuses the name (ValueError naming it) rather than Python its type.
ParameterValue undeclared(const py::handle& value) {
  if (is_bool(value)) return value.cast<bool>();
  if (is_number(value)) return to_number("", value);
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  return py::repr(value).cast<std::string>();
}

std::string non_finite(const Value& value, const std::string& path) {
  const auto& data = value.data();
  if (const double* x = std::get_if<double>(&data)) return std::isfinite(*x) ? "" : path + " = " + format_value(*x);
  if (const auto* list = std::get_if<Box<Value::List>>(&data)) {
    for (std::size_t i = 0; i < (*list)->size(); ++i) {
      if (auto bad = non_finite((**list)[i], fmt::format("{}[{}]", path, i)); !bad.empty()) return bad;
    }
  } else if (const auto* record = std::get_if<Box<Record>>(&data)) {
    for (const auto& [key, item] : (*record)->fields()) {
      if (auto bad = non_finite(item, path.empty() ? key : path + "." + key); !bad.empty()) return bad;
    }
  } else if (const auto* table = std::get_if<Box<Table>>(&data)) {
    const Table& t = **table;
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      for (std::size_t c = 0; c < t.columns.size(); ++c) {  // cells are numbers, text or none
        const double* x = std::get_if<double>(&t.rows[i][c].data());
        if (x && !std::isfinite(*x)) {
          return fmt::format("{}{}{}[{}] = {}", path, path.empty() ? "" : ".", t.columns[c], i, format_value(*x));
        }
      }
    }
  }
  return "";
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

namespace {
PyObject* validity_warning = nullptr;  // bounce.ValidityWarning, made by the module
}  // namespace

void set_validity_warning(PyObject* type) { validity_warning = type; }

void warn_validity(const std::string& text) {
  if (PyErr_WarnEx(validity_warning != nullptr ? validity_warning : PyExc_UserWarning, text.c_str(), 1) < 0)
    throw py::error_already_set();  // warnings turned into errors
}

void refuse_type(std::string_view name, const py::handle& value, std::string_view expected) {
  std::string shown = py::repr(value).cast<std::string>();
  if (shown.size() > 80) shown = shown.substr(0, 76) + " ...";
  throw py::type_error(fmt::format("{} = {} is invalid: expected {}", name, shown, expected));
}

bool is_number(const py::handle& x) {
  if (is_bool(x)) return false;
  return PyFloat_Check(x.ptr()) || PyLong_Check(x.ptr()) || py::isinstance(x, numpy().integer) ||
         py::isinstance(x, numpy().floating);
}

double to_number(std::string_view name, const py::handle& x) {
  if (is_number(x)) {
    const double v = PyFloat_AsDouble(x.ptr());
    if (v == -1.0 && PyErr_Occurred()) {  // an int beyond double precision: as large as a double goes
      if (!PyErr_ExceptionMatches(PyExc_OverflowError)) throw py::error_already_set();
      PyErr_Clear();
      return x > py::int_(0) ? HUGE_VAL : -HUGE_VAL;
    }
    return v;
  }
  if (py::isinstance(x, numpy().ndarray) && x.attr("ndim").cast<int>() == 0 && numeric_dtype(x)) {
    return to_number(name, x.attr("item")());
  }
  refuse_type(name, x, number_expected(x, "a number"));
}

Array to_array(std::string_view name, const py::handle& x) {
  constexpr std::string_view expected = "a number or an array of numbers";
  if (py::isinstance<py::list>(x) || py::isinstance<py::tuple>(x)) {
    check_leaves(name, x, x, expected);
  } else if (!py::isinstance(x, numpy().ndarray)) {
    refuse_type(name, x, number_expected(x, expected));
  }
  py::object a;
  try {
    a = numpy().asarray(x);
  } catch (const py::error_already_set&) {  // a ragged list
    refuse_type(name, x, "an array of numbers of a regular shape");
  }
  if (!numeric_dtype(a)) refuse_type(name, x, "an array of numbers (integers or floats; not bool, complex or text)");
  return a.cast<Array>();
}

std::variant<double, Array> to_numbers(std::string_view name, const py::handle& x) {
  if (is_number(x)) return to_number(name, x);
  return to_array(name, x);
}

ParameterValue to_value(const std::string& name, const py::handle& value, std::string_view python_name) {
  const std::string_view shown = python_name.empty() ? std::string_view(name) : python_name;
  const auto& specs = declared();
  const auto it = specs.find(name);
  if (it == specs.end()) return undeclared(value);
  const ParameterSpec& spec = it->second;
  switch (spec.kind) {
    case ParameterKind::real:
      return to_number(shown, value);
    case ParameterKind::reals: {
      const std::string expected = fmt::format("a list of {} numbers", spec.count);
      if (is_number(value) || py::isinstance<py::str>(value)) refuse_type(shown, value, expected);
      const Array a = to_array(shown, value);
      if (a.ndim() != 1) refuse_type(shown, value, expected);
      return std::vector<double>(a.data(), a.data() + a.size());
    }
    case ParameterKind::flag:
      if (!is_bool(value)) refuse_type(shown, value, "True or False");
      return value.cast<bool>();
    case ParameterKind::choice:
      if (!py::isinstance<py::str>(value)) refuse_type(shown, value, "a str: one of " + one_of(spec.choices));
      return value.cast<std::string>();
    case ParameterKind::text:
      if (py::isinstance(value, py::module_::import("os").attr("PathLike"))) {
        return py::module_::import("os").attr("fspath")(value).cast<std::string>();
      }
      if (!py::isinstance<py::str>(value)) refuse_type(shown, value, "a str");
      return value.cast<std::string>();
  }
  return undeclared(value);
}

std::string library_name(std::string_view python_name) {
  if (python_name == "yield_strength") return "yield";
  if (python_name == "follow_time") return "follow";
  return std::string(python_name);
}

api::Inputs to_inputs(const py::kwargs& kwargs) {
  api::Inputs in;
  for (const auto& [key, value] : kwargs) {
    const std::string python_name = key.cast<std::string>(), name = library_name(python_name);
    if (value.is_none()) continue;
    // follow_time = 0 (Python's default) means "stop when sticking is certain": not given
    if (python_name == "follow_time" && is_number(value) && to_number(python_name, value) == 0.0) continue;
    in.insert_or_assign(name, to_value(name, value, python_name));
  }
  return in;
}

void check_signals() {
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

void check_signals_without_gil() {
  py::gil_scoped_acquire gil;
  check_signals();
}

std::string non_finite(const Value& value) { return non_finite(value, ""); }

}  // namespace bounce::python
