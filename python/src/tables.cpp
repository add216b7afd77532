// NormalTable and TangentialTable: build from a pair and a model, read back, evaluate.
#include <pybind11/stl.h>

#include "bounce/analysis/tables.hpp"
#include "objects.hpp"

namespace bounce::python {

namespace {

using analysis::NormalTable;
using analysis::TangentialTable;


NormalTable build_normal(const PyPair& pair, const PyModel& model, double g_min, double g_max, double bound) {
  const api::Case c = make_case(pair, model);
  analysis::TableOptions t;
  t.bound = bound;
  py::gil_scoped_release release;
  return analysis::build_normal_table(c.pair, c.model, g_min, g_max, c.options, t);
}

TangentialTable build_tangential(const PyPair& pair, const PyModel& model, double gn_min, double gn_max, double gt_min,
                                 double gt_max, double bound) {
  const api::Case c = make_case(pair, model);
  analysis::TableOptions t;
  t.bound = bound;
  py::gil_scoped_release release;
  return analysis::build_tangential_table(c.pair, c.model, gn_min, gn_max, gt_min, gt_max, c.options, t);
}

void bind_normal_table(py::module_& m) {
  py::class_<NormalTable>(m, "NormalTable", "eps^N(g) with the outcome, to a stated interpolation error.")
      .def_static("build", &build_normal, py::arg("pair"), py::arg("model"), py::arg("g_min"), py::arg("g_max"),
                  py::arg("bound") = 1e-6)
      .def_static("from_json", &NormalTable::from_json, py::arg("text"))
      .def(
          "cor", [](const NormalTable& t, const py::object& g) { return map_values<double>(g, [&](double v) { return t.cor(v); }); },
          py::arg("velocity"), "eps^N at speed(s) g [m/s] (ValueError outside [g_min, g_max])")
      .def(
          "sticks",
          [](const NormalTable& t, const py::object& g) {
            return map_values<bool>(g, [&](double v) { return t.outcome(v) == dynamics::Outcome::stick; });
          },
          py::arg("velocity"), "True where grains meeting at g stick")
      .def("to_json", &NormalTable::to_json)
      .def("to_csv", &NormalTable::to_csv)
      .def("to_c_header", &NormalTable::to_c_header, py::arg("prefix"))
      .def_readonly("g_min", &NormalTable::g_min)
      .def_readonly("g_max", &NormalTable::g_max)
      .def_readonly("sticking_velocity", &NormalTable::sticking_velocity)
      .def_readonly("bound", &NormalTable::bound);
}

void bind_tangential_table(py::module_& m) {
  py::class_<TangentialTable>(m, "TangentialTable",
                              "eps^T(g^N, g^T) of the asperity law (published form), to a stated error (docs/tables.md).")
      .def_static("build", &build_tangential, py::arg("pair"), py::arg("model"), py::arg("gn_min"), py::arg("gn_max"),
                  py::arg("gt_min"), py::arg("gt_max"), py::arg("bound") = 1e-6)
      .def_static("from_json", &TangentialTable::from_json, py::arg("text"))
      .def(
          "cor",
          [](const TangentialTable& t, const py::object& gn, const py::object& gt) {
            return py::vectorize([&t](double n, double g) { return t.cor(n, g); })(gn, gt);
          },
          py::arg("velocity"), py::arg("tangential_velocity"),
          "eps^T at (g^N, g^T) [m/s], numpy broadcasting (ValueError outside the table's range)")
      .def(
          "breaks",
          [](const TangentialTable& t, const py::object& gn, const py::object& gt) {
            return py::vectorize([&t](double n, double g) { return t.breaks(n, g); })(gn, gt);
          },
          py::arg("velocity"), py::arg("tangential_velocity"), "the number of asperities that break")
      .def("to_json", &TangentialTable::to_json)
      .def("to_csv", &TangentialTable::to_csv)
      .def("to_c_header", &TangentialTable::to_c_header, py::arg("prefix"))
      .def_readonly("gn_min", &TangentialTable::gn_min)
      .def_readonly("gn_max", &TangentialTable::gn_max)
      .def_readonly("gt_min", &TangentialTable::gt_min)
      .def_readonly("gt_max", &TangentialTable::gt_max)
      .def_readonly("bound", &TangentialTable::bound)
      .def_readonly("checked_error", &TangentialTable::checked_error)
      .def_readonly("check_points", &TangentialTable::check_points);
}

}  // namespace

void bind_tables(py::module_& m) {
  bind_normal_table(m);
  bind_tangential_table(m);
}

}  // namespace bounce::python
