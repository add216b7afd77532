#pragma once
// Between Python and the front door: keyword arguments in (api::Inputs), Records out (dicts,
// with a Table as a dict of numpy arrays), so that Python gets the CLI's JSON keys.
//
// Types are strict: where a number is expected, an int, a float, a numpy integer or float
// scalar (or a 0-d array of them) is one; a bool, a str, None or a complex is not, and is a
// TypeError naming the parameter, in the one message form "NAME = VALUE is invalid:
// expected ...". The values themselves (ranges) are checked by the library, against the
// parameters' declarations: ValueError (module.cpp).

#include <algorithm>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "bounce/api/front_door.hpp"
#include "bounce/core/record.hpp"

namespace bounce::python {

namespace py = pybind11;
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// A Value as Python: dict, list, float, int, str, bool, None; a Table as a dict of arrays.
py::object to_python(const Value& value);
/// A Table as a dict of numpy arrays (numbers: float64, NaN for none; text: str arrays).
py::dict table_to_python(const Table& table);

/// TypeError "NAME = repr(value) is invalid: expected <expected>".
[[noreturn]] void refuse_type(std::string_view name, const py::handle& value, std::string_view expected);

/// True for one number: int, float, a numpy integer or float scalar (not bool, not an array).
bool is_number(const py::handle& x);
/// `x` as one number (a 0-d numeric array too); TypeError naming `name` otherwise.
double to_number(std::string_view name, const py::handle& x);
/// `x` as a float64 array: a numpy array of integers or floats, or a (nested) list or tuple
/// of numbers; TypeError naming `name` otherwise (bool and complex arrays included).
Array to_array(std::string_view name, const py::handle& x);
/// The argument of a call that takes one number or an array of them: a number (is_number)
/// gives the scalar form, anything else must be an array (to_array).
std::variant<double, Array> to_numbers(std::string_view name, const py::handle& x);

/// A Python value as the value of the declared parameter `name` (Python's spelling
/// `python_name` for messages): a number for a real, a list of numbers for reals, a bool for
/// a flag, a str for a choice or text. TypeError for another type. A name nothing declares
/// is passed on as given, for the front door to refuse it by name (ValueError).
ParameterValue to_value(const std::string& name, const py::handle& value, std::string_view python_name = {});
/// The library's name of a Python keyword: yield for yield_strength, follow for follow_time.
std::string library_name(std::string_view python_name);

/// Keyword arguments as inputs, with Python's spellings of two names (yield_strength for the
/// keyword yield, follow_time for follow); None means "not given".
api::Inputs to_inputs(const py::kwargs& kwargs);

/// The pending Ctrl-C (or another signal's handler error) as a Python exception: call with
/// the GIL held, between pieces of a long computation.
void check_signals();
/// Raises bounce.ValidityWarning (a UserWarning) with `text`: a validity condition of the model
/// that does not hold, as the CLI prints it on stderr.
void warn_validity(const std::string& text);
void set_validity_warning(PyObject* type);
/// The same from code that runs with the GIL released (a progress callback).
void check_signals_without_gil();

/// "contact_time = inf" for the first number of `value` (Tables included) that is not
/// finite, "" when all are: a result is never returned as inf or NaN.
std::string non_finite(const Value& value);

/// body(i) for i = 0 .. n-1 with the GIL released, in pieces of `piece` indices between
/// which Ctrl-C is checked (KeyboardInterrupt within one piece). `body` touches no Python
/// object: it reads and writes raw buffers taken before.
template <class Body>
void for_each_index(py::ssize_t n, Body body, py::ssize_t piece = 1024) {
  for (py::ssize_t start = 0; start < n; start += piece) {
    {
      py::gil_scoped_release release;
      for (py::ssize_t i = start; i < std::min(n, start + piece); ++i) body(i);
    }
    check_signals();
  }
}

/// f applied to a number (-> float) or elementwise to an array (-> array of its shape);
/// `name` for a TypeError. The loop runs without the GIL, Ctrl-C checked as it goes.
template <class R, class F>
py::object map_values(std::string_view name, const py::handle& x, F f) {
  const auto in = to_numbers(name, x);
  if (const double* one = std::get_if<double>(&in)) return py::cast(f(*one));
  const Array& a = std::get<Array>(in);
  py::array_t<R> out(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()));
  const double* from = a.data();
  R* to = out.mutable_data();
  for_each_index(a.size(), [&](py::ssize_t i) { to[i] = f(from[i]); });
  return out;
}

}  // namespace bounce::python
