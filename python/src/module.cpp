// pybind11 bindings of the bounce library (docs/python.md). Thin: inputs go to the front
// door (api/front_door.hpp) by parameter name, results come back as its Records (the CLI's
// JSON keys); arrays of speeds loop in C++, not in Python. Library errors map to Python:
// InvalidArgument -> ValueError (the one-line message naming the parameter, its value and
// the allowed range), NumericalError -> RuntimeError.
#include "bounce/core/error.hpp"
#include "objects.hpp"

PYBIND11_MODULE(_bounce, m) {
  using namespace bounce;
  m.doc() = "bounce: the physics of colliding grains (C++ core; see docs/python.md)";
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidArgument& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const NumericalError& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    } catch (const Error& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    }
  });
  python::bind_objects(m);
  python::bind_collisions(m);
  python::bind_contact(m);
  python::bind_analytic(m);
  python::bind_tables(m);
  python::bind_rules(m);
}
