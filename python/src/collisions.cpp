// collide (one speed or an array of them), closed_forms, viscoelastic_scales, sticking.
#include <map>

#include <pybind11/stl.h>

#include "bounce/analysis/closed_forms.hpp"
#include "bounce/analysis/sticking.hpp"
#include "bounce/core/error.hpp"
#include "objects.hpp"

namespace bounce::python {

namespace {

std::vector<py::ssize_t> shape_of(const Array& a) { return {a.shape(), a.shape() + a.ndim()}; }

// collide() over an array of speeds: the columns of the front door's curve, each an array
// of the input's shape, and `stick` (bool) beside `outcome`.
py::dict collide_many(const api::Inputs& inputs, const Array& speeds) {
  const std::vector<double> v(speeds.data(), speeds.data() + speeds.size());
  Table t;
  {
    py::gil_scoped_release release;
    t = api::collide_columns(inputs, v);
  }
  py::dict d = table_to_python(t);
  const py::tuple shape = py::cast(shape_of(speeds));
  for (const auto& [key, column] : d) d[key] = column.attr("reshape")(shape);
  d["stick"] = d["outcome"].attr("__eq__")(py::str("stick"));
  return d;
}

py::object collide(const PyPair& pair, const PyModel& model, const py::object& velocity, const py::kwargs& options) {
  api::Inputs in = case_inputs(pair, model, options);
  if (!is_number(velocity)) return collide_many(in, velocity.cast<Array>());
  in["velocity"] = velocity.cast<double>();
  Record out;
  {
    py::gil_scoped_release release;
    out = api::collide(in);
  }
  return to_python(out);
}

py::object closed_forms(const PyPair& pair, const PyModel& model, const py::object& velocity) {
  const api::Case c = make_case(pair, model);
  if (is_number(velocity)) {
    return to_python(to_record(analysis::named_values(analysis::closed_forms(c.pair, c.model, velocity.cast<double>()))));
  }
  const Array v = velocity.cast<Array>();
  std::map<std::string, Array> columns;  // the keys depend on the model, not on the speed
  for (py::ssize_t i = 0; i < v.size(); ++i) {
    for (const auto& [key, value] : analysis::named_values(analysis::closed_forms(c.pair, c.model, v.data()[i]))) {
      columns.try_emplace(key, shape_of(v)).first->second.mutable_data()[i] = value;
    }
  }
  py::dict d;
  for (const auto& [key, column] : columns) d[py::str(key)] = column;
  return d;
}

py::dict viscoelastic_scales(const PyPair& pair, const PyModel& model, double velocity) {
  const api::Case c = make_case(pair, model);
  const analysis::ViscoelasticScales s = analysis::viscoelastic_scales(c.pair, c.model, velocity);
  py::dict d;
  d["dissipative_constant"] = s.dissipative_constant;
  d["force_constant"] = s.force_constant;
  d["kappa"] = s.kappa;
  d["characteristic_velocity"] = s.characteristic_velocity;
  d["q"] = s.q;
  d["reference_overlap"] = s.reference_overlap;
  d["hertz_contact_time"] = s.hertz_contact_time;
  return d;
}

py::object sticking(const PyPair& pair, const PyModel& model, const py::kwargs& options) {
  const api::Inputs in = case_inputs(pair, model, options);
  Record out;
  {
    py::gil_scoped_release release;
    out = api::sticking(in);
  }
  return to_python(out);
}

}  // namespace

void bind_collisions(py::module_& m) {
  m.def("collide", &collide, py::arg("pair"), py::arg("model"), py::arg("velocity"),
        "One head-on (or oblique) collision at impact speed `velocity` [m/s]: a dict with the keys of the CLI's "
        "`bounce collide --json` (cor, outcome, contact_time, max_overlap, energy, warnings, notes, ...). Keywords: "
        "tangential_velocity [m/s], trajectory=True (adds 'trajectory', a dict of arrays), trajectory_points, "
        "follow_time [s] (krijt, jkr-viscoelastic), and any numerical setting of the model (method, tolerance, "
        "adhesive_tolerance, stiff_engine). An array of speeds gives a dict of arrays of its shape (velocity, cor, "
        "outcome, stick, contact_time, max_overlap, bulk_dissipated, crack_dissipated; cor_tangential when oblique), "
        "computed in C++.");
  m.def("closed_forms", &closed_forms, py::arg("pair"), py::arg("model"), py::arg("velocity"),
        "The closed forms beside a collision: K13 (22) hertz_time_k13_22, (24) e_jkr, (25) sticking_velocity_k13_25 "
        "and the exact sticking_velocity_jkr, (26) e_d, (27) e_i, (11) tabor_parameter; BP04 (8.95), (8.98) for "
        "adhesive-viscoelastic; K13 (28), (29), (33) with a yield strength. An array of speeds gives arrays.");
  m.def("viscoelastic_scales", &viscoelastic_scales, py::arg("pair"), py::arg("model"), py::arg("velocity"),
        "BP04 §8.3 scales of a Hertz-type collision: A [s], C0, kappa (8.70), g* (8.88) [m/s], q = (g/g*)^{1/5}, "
        "xi0 (8.65) [m], the exact Hertz contact time [s].");
  m.def("sticking", &sticking, py::arg("pair"), py::arg("model"),
        "The sticking velocity of an adhesive model with its bracket, the collisions it took and the closed forms: "
        "the keys of `bounce sticking --json` (keyword relative_tolerance, default 1e-6).");
  m.def(
      "sticking_velocity",
      [](const PyPair& pair, const PyModel& model, double relative_tolerance) {
        py::kwargs options;
        options["relative_tolerance"] = relative_tolerance;
        return sticking(pair, model, options)["sticking_velocity"].cast<double>();
      },
      py::arg("pair"), py::arg("model"), py::arg("relative_tolerance") = 1e-6,
      "The sticking velocity [m/s] of an adhesive model (bisection on the outcome).");
}

}  // namespace bounce::python
