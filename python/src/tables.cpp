// NormalTable and TangentialTable: build from a pair and a model, read back, evaluate.
#include <string>
#include <utility>
#include <variant>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bounce/analysis/tables.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "objects.hpp"

namespace bounce::python {

namespace {

using analysis::NormalTable;
using analysis::TangentialTable;

// "LO:HI" of the front door's table command, each end as the shortest text that reads back
// as the same double; the ends are first checked one by one under Python's names.
std::string interval(const char* lo_name, double lo, const char* hi_name, double hi) {
  check_speed(lo_name, lo);
  check_speed(hi_name, hi);
  if (!(hi > lo)) {
    throw InvalidArgument(hi_name, format_value(hi),
                          fmt::format("{} > {} = {} m/s", hi_name, lo_name, format_value(lo)));
  }
  return fmt::format("{}:{}", lo, hi);
}

// The front door's table (its declared bound, the model's checks), with Ctrl-C checked as
// it grows; what it says about an interval is said about Python's arguments.
template <class T>
T build(api::Inputs in, const char* gn_names, const char* gt_names) {
  try {
    auto table = [&] {
      py::gil_scoped_release release;
      return api::table(in, [](std::size_t, std::size_t) { check_signals_without_gil(); });
    }();
    return std::get<T>(std::move(table));
  } catch (const InvalidArgument& e) {
    // the front door's "... expected tangential_velocities too": in Python, a TangentialTable
    if (std::string allowed = e.allowed(); allowed.starts_with("tangential_velocities too")) {
      throw InvalidArgument(e.parameter(), e.value(),
                            allowed.replace(0, 25, "TangentialTable.build for it, not NormalTable.build"));
    }
    if (e.parameter() == "velocities") throw InvalidArgument(gn_names, e.value(), e.allowed());
    if (e.parameter() == "tangential_velocities") throw InvalidArgument(gt_names, e.value(), e.allowed());
    throw;
  }
}

NormalTable build_normal(const PyPair& pair, const PyModel& model, const py::object& g_min, const py::object& g_max,
                         const py::object& bound) {
  py::kwargs options;
  options["bound"] = bound;
  api::Inputs in = case_inputs(pair, model, options);
  in["velocities"] = interval("g_min", to_number("g_min", g_min), "g_max", to_number("g_max", g_max));
  return build<NormalTable>(std::move(in), "g_min:g_max", "");
}

TangentialTable build_tangential(const PyPair& pair, const PyModel& model, const py::object& gn_min,
                                 const py::object& gn_max, const py::object& gt_min, const py::object& gt_max,
                                 const py::object& bound) {
  py::kwargs options;
  options["bound"] = bound;
  api::Inputs in = case_inputs(pair, model, options);
  in["velocities"] = interval("gn_min", to_number("gn_min", gn_min), "gn_max", to_number("gn_max", gn_max));
  in["tangential_velocities"] =
      interval("gt_min", to_number("gt_min", gt_min), "gt_max", to_number("gt_max", gt_max));
  return build<TangentialTable>(std::move(in), "gn_min:gn_max", "gt_min:gt_max");
}

// f(g^N, g^T) for numbers (-> a number) or arrays broadcast together (-> an array).
template <class R, class F>
py::object map_pairs(const py::object& gn, const py::object& gt, F f) {
  const auto n = to_numbers("velocity", gn), t = to_numbers("tangential_velocity", gt);
  if (std::holds_alternative<double>(n) && std::holds_alternative<double>(t)) {
    return py::cast(f(std::get<double>(n), std::get<double>(t)));
  }
  const auto as_array = [](const std::variant<double, Array>& v) -> py::object {
    return std::holds_alternative<double>(v) ? py::object(Array(std::vector<py::ssize_t>{}, &std::get<double>(v)))
                                             : py::object(std::get<Array>(v));
  };
  const py::tuple both = py::module_::import("numpy").attr("broadcast_arrays")(as_array(n), as_array(t));
  const Array a = both[0].cast<Array>(), b = both[1].cast<Array>();
  py::array_t<R> out(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()));
  const double *n_i = a.data(), *t_i = b.data();
  R* out_i = out.mutable_data();
  for_each_index(a.size(), [&](py::ssize_t i) { out_i[i] = f(n_i[i], t_i[i]); });
  return out;
}

void bind_normal_table(py::module_& m) {
  py::class_<NormalTable>(m, "NormalTable", "eps^N(g) with the outcome, to a stated interpolation error.")
      .def_static("build", &build_normal, py::arg("pair"), py::arg("model"), py::arg("g_min"), py::arg("g_max"),
                  py::arg("bound") = 1e-6,
                  "The table on [g_min, g_max] [m/s] to interpolation error `bound` (the CLI's `bounce table`; Ctrl-C "
                  "interrupts it).")
      .def_static("from_json", &NormalTable::from_json, py::arg("text"))
      .def(
          "cor",
          [](const NormalTable& t, const py::object& g) {
            return map_values<double>("velocity", g, [&](double v) { return t.cor(v); });
          },
          py::arg("velocity"), "eps^N at speed(s) g [m/s] (ValueError outside [g_min, g_max])")
      .def(
          "sticks",
          [](const NormalTable& t, const py::object& g) {
            return map_values<bool>("velocity", g, [&](double v) { return t.outcome(v) == dynamics::Outcome::stick; });
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
                  py::arg("gt_min"), py::arg("gt_max"), py::arg("bound") = 1e-6,
                  "The table on [gn_min, gn_max] x [gt_min, gt_max] [m/s] to error `bound` (the CLI's `bounce table "
                  "--tangential-velocities`; Ctrl-C interrupts it).")
      .def_static("from_json", &TangentialTable::from_json, py::arg("text"))
      .def(
          "cor",
          [](const TangentialTable& t, const py::object& gn, const py::object& gt) {
            return map_pairs<double>(gn, gt, [&t](double n, double g) { return t.cor(n, g); });
          },
          py::arg("velocity"), py::arg("tangential_velocity"),
          "eps^T at (g^N, g^T) [m/s], numpy broadcasting (ValueError outside the table's range)")
      .def(
          "breaks",
          [](const TangentialTable& t, const py::object& gn, const py::object& gt) {
            return map_pairs<long>(gn, gt, [&t](double n, double g) { return t.breaks(n, g); });
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
