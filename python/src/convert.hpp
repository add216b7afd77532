#pragma once
// Between Python and the front door: keyword arguments in (api::Inputs), Records out (dicts,
// with a Table as a dict of numpy arrays), so that Python gets the CLI's JSON keys.

#include <string>
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

/// A Python value as a parameter value: float or int -> number, str -> text, bool -> flag,
/// a sequence of numbers -> numbers. TypeError for anything else.
ParameterValue to_value(const std::string& name, const py::handle& value);
/// Keyword arguments as inputs, with Python's spellings of two names (yield_strength for the
/// keyword yield, follow_time for follow); None means "not given".
api::Inputs to_inputs(const py::kwargs& kwargs);

/// A Python int or float (numpy float64 included): the scalar form of the calls that take arrays.
bool is_number(const py::handle& x);

/// f applied to a float (-> float) or elementwise to an array (-> array of its shape).
template <class R, class F>
py::object map_values(const py::object& x, F f) {
  if (is_number(x)) return py::cast(f(x.cast<double>()));
  const Array a = x.cast<Array>();
  py::array_t<R> out(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()));
  for (py::ssize_t i = 0; i < a.size(); ++i) out.mutable_data()[i] = f(a.data()[i]);
  return out;
}

}  // namespace bounce::python
