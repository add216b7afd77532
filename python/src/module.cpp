// pybind11 bindings of the bounce library (docs/python.md). Thin: inputs go to the front
// door (api/front_door.hpp) by parameter name, results come back as its Records (the CLI's
// JSON keys); arrays of speeds loop in C++, not in Python. Library errors map to Python:
// InvalidArgument -> ValueError (the one-line message naming the parameter, its value and
// the allowed range), NumericalError -> RuntimeError.
#include <regex>
#include <string>

#include "bounce/core/error.hpp"
#include "bounce/core/version.hpp"
#include "objects.hpp"

namespace {

// The message in Python's spelling: the parameters Python names differently (yield_strength,
// follow_time: convert.cpp), as the parameter and in the lists of names a message gives.
std::string python_message(const bounce::InvalidArgument& e) {
  static const std::regex yield(R"((^|one of |, )yield(?=,|$))"), follow(R"((^|one of |, )follow(?=,|$))");
  const std::string& p = e.parameter();
  const std::string text = p == "yield"    ? e.renamed("yield_strength").what()
                           : p == "follow" ? e.renamed("follow_time").what()
                                           : e.what();
  return std::regex_replace(std::regex_replace(text, yield, "$1yield_strength"), follow, "$1follow_time");
}

}  // namespace

PYBIND11_MODULE(_bounce, m) {
  using namespace bounce;
  m.doc() = "bounce: the physics of colliding grains (C++ core; see docs/python.md)";
  m.attr("__version__") = std::string(bounce::version());  // the CMake project's version
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidArgument& e) {
      PyErr_SetString(PyExc_ValueError, python_message(e).c_str());
    } catch (const NumericalError& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    } catch (const Error& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    }
  });
  // The CLI's validity warnings (strain, T_vis against the contact time, K13 (A.2), ...) in Python.
  PyObject* validity = PyErr_NewExceptionWithDoc("bounce._bounce.ValidityWarning",
                                                 "A validity condition of the model does not hold at these inputs "
                                                 "(the warnings the CLI prints on stderr).",
                                                 PyExc_UserWarning, nullptr);
  m.attr("ValidityWarning") = pybind11::reinterpret_borrow<pybind11::object>(validity);
  python::set_validity_warning(validity);
  python::bind_objects(m);
  python::bind_collisions(m);
  python::bind_contact(m);
  python::bind_analytic(m);
  python::bind_tables(m);
  python::bind_atlas(m);
  python::bind_aggregate(m);
  python::bind_rules(m);
  python::bind_fit(m);
  python::bind_posterior(m);
}
