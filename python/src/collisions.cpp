// collide (one speed or an array of them), closed_forms, viscoelastic_scales, sticking.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bounce/analysis/closed_forms.hpp"
#include "bounce/analysis/sticking.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "objects.hpp"

namespace bounce::python {

namespace {

std::vector<py::ssize_t> shape_of(const Array& a) { return {a.shape(), a.shape() + a.ndim()}; }

// A result that is inf or NaN is refused as the speed's fault (the pair and the model were
// checked before): "velocity = 1e+308 is invalid: expected ... (contact_time = inf)".
void require_finite_results(const Value& results, double velocity) {
  if (const std::string bad = non_finite(results); !bad.empty()) {
    throw InvalidArgument("velocity", format_value(velocity),
                          fmt::format("an impact velocity at which every result of this pair and model is finite in "
                                      "double precision ({})",
                                      bad));
  }
}

// collide() over speeds, in pieces between which Ctrl-C is checked: each piece (one front
// door call, GIL released) is sized from the last one's time per collision to take about
// 20 ms (at most twice the last, at most 4096 speeds), so the checks cost nothing and a
// KeyboardInterrupt arrives within about one piece.
Table collide_in_pieces(const api::Inputs& inputs, const std::vector<double>& v, std::vector<std::string>& warnings) {
  using Clock = std::chrono::steady_clock;
  constexpr double target = 0.02;  // s
  Table all;
  std::size_t done = 0, piece = 1;
  do {  // at least once: an empty array still has its inputs checked
    const std::size_t n = std::min(piece, v.size() - done);
    const std::vector<double> part(v.begin() + static_cast<std::ptrdiff_t>(done),
                                   v.begin() + static_cast<std::ptrdiff_t>(done + n));
    const auto start = Clock::now();
    Table t;
    {
      py::gil_scoped_release release;
      t = api::collide_columns(inputs, part, &warnings);  // each kind once over all the pieces
    }
    check_signals();
    if (all.columns.empty()) all.columns = t.columns;
    for (auto& row : t.rows) all.rows.push_back(std::move(row));
    done += n;
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    const double fits = seconds > 0.0 ? target * static_cast<double>(n) / seconds : 2.0 * static_cast<double>(n);
    piece = static_cast<std::size_t>(std::clamp(fits, 1.0, std::min(2.0 * static_cast<double>(n), 4096.0)));
  } while (done < v.size());
  return all;
}

std::size_t column_of(const Table& t, const char* name) {
  return static_cast<std::size_t>(std::find(t.columns.begin(), t.columns.end(), name) - t.columns.begin());
}

// collide() over an array of speeds: the columns of the front door's curve, each an array
// of the input's shape, and `stick` (bool) beside `outcome`.
py::dict collide_many(const api::Inputs& inputs, const Array& speeds) {
  const std::vector<double> v(speeds.data(), speeds.data() + speeds.size());
  std::vector<std::string> warnings;
  const Table t = collide_in_pieces(inputs, v, warnings);
  const std::size_t velocity = column_of(t, "velocity"), outcome = column_of(t, "outcome");
  py::array_t<bool> stick(shape_of(speeds));
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const auto& row = t.rows[i];
    Record r;
    for (std::size_t c = 0; c < t.columns.size(); ++c) r.set(t.columns[c], row[c]);
    require_finite_results(r, row[velocity].number());
    stick.mutable_data()[i] = row[outcome].text() == "stick";
  }
  py::dict d = table_to_python(t);
  if (t.rows.empty()) d["outcome"] = py::module_::import("numpy").attr("asarray")(py::list(), "str");
  const py::tuple shape = py::cast(shape_of(speeds));
  for (const auto& [key, column] : d) d[key] = column.attr("reshape")(shape);
  d["stick"] = stick;
  // The validity warnings the CLI's curve prints, one per kind: in the dict, and as Python warnings.
  d["warnings"] = py::cast(warnings);
  for (const std::string& w : warnings) warn_validity(w);
  return d;
}

py::object collide(const PyPair& pair, const PyModel& model, const py::object& velocity, const py::kwargs& options) {
  api::Inputs in = case_inputs(pair, model, options);
  const auto speeds = to_numbers("velocity", velocity);
  if (const Array* many = std::get_if<Array>(&speeds)) return collide_many(in, *many);
  const double v = std::get<double>(speeds);
  in["velocity"] = v;
  Record out;
  {
    py::gil_scoped_release release;
    out = api::collide(in);
  }
  require_finite_results(out, v);
  for (const Value& w : out.contains("warnings") ? out.at("warnings").list() : Value::List{}) warn_validity(w.text());
  return to_python(out);
}

py::dict curve(const PyPair& pair, const PyModel& model, const py::object& velocities, const py::kwargs& options) {
  const api::Inputs in = case_inputs(pair, model, options);
  if (!is_number(velocities)) return collide_many(in, to_array("velocities", velocities));
  const double one = to_number("velocities", velocities);
  return collide_many(in, Array(std::vector<py::ssize_t>{}, &one));
}

// The closed forms at v as a Record: one beyond its validity None, with "warnings" saying why.
Record closed_forms_at(const api::Case& c, double v) {
  const analysis::ClosedForms forms = analysis::closed_forms(c.pair, c.model, check_speed("velocity", v));
  Record r;
  for (const auto& [key, value] : analysis::named_values(forms)) r.set(key, value ? Value(*value) : Value());
  if (!forms.warnings.empty()) r.set("warnings", forms.warnings);
  require_finite_results(r, v);
  return r;
}

py::object closed_forms(const PyPair& pair, const PyModel& model, const py::object& velocity) {
  const api::Case c = make_case(pair, model);
  const auto speeds = to_numbers("velocity", velocity);
  if (const double* v = std::get_if<double>(&speeds)) return to_python(closed_forms_at(c, *v));
  const Array& v = std::get<Array>(speeds);
  // the keys depend on the pair and the model, not on the speed; a null is NaN in its column
  const Record keys = closed_forms_at(c, v.size() > 0 ? v.data()[0] : 1.0);
  std::map<std::string, Array> columns;
  std::map<std::string, double*> cells;
  for (const auto& [key, value] : keys.fields()) {
    if (key != "warnings") cells[key] = columns.try_emplace(key, shape_of(v)).first->second.mutable_data();
  }
  const double* speeds_i = v.data();
  for_each_index(v.size(), [&](py::ssize_t i) {
    const Record at = closed_forms_at(c, speeds_i[i]);  // named: fields() refers into it
    for (const auto& [key, value] : at.fields()) {
      if (key != "warnings") cells.at(key)[i] = value.is_null() ? std::nan("") : value.number();
    }
  });
  py::dict d;
  for (const auto& [key, column] : columns) d[py::str(key)] = column;
  return d;
}

py::dict viscoelastic_scales(const PyPair& pair, const PyModel& model, const py::object& velocity) {
  const double v = to_number("velocity", velocity);
  const api::Case c = make_case(pair, model);
  const analysis::ViscoelasticScales s = analysis::viscoelastic_scales(c.pair, c.model, v);
  if (!(s.dissipative_constant > 0.0)) {  // g* (8.88) = inf: the CLI's analytic refuses it the same way
    const bool given = model.inputs.contains("A");
    throw InvalidArgument(given ? "A" : "model", given ? format_value(s.dissipative_constant) : model.name,
                          "a dissipative constant A > 0 s for BP04's viscoelastic scales (with A = 0 the collision is "
                          "elastic, e = 1, and g* (8.88) is infinite)");
  }
  Record r;
  r.set("dissipative_constant", s.dissipative_constant)
      .set("force_constant", s.force_constant)
      .set("kappa", s.kappa)
      .set("characteristic_velocity", s.characteristic_velocity)
      .set("q", s.q)
      .set("reference_overlap", s.reference_overlap)
      .set("hertz_contact_time", s.hertz_contact_time);
  require_finite_results(r, v);
  return to_python(r);
}

// The sticking velocity at each radius of body 1 (numpy in, a dict of arrays of its shape out;
// NaN where none was found, with its note): one radius per front-door call, Ctrl-C between them.
py::dict sticking_over_radii(const api::Inputs& in, const py::handle& radii_given) {
  if (py::isinstance<py::str>(radii_given))
    refuse_type("radii", radii_given, "an array of radii [m] (e.g. numpy.geomspace(1e-7, 1e-4, 30))");
  const Array radii = to_array("radii", radii_given);
  Value::List rows;
  for (py::ssize_t i = 0; i < radii.size(); ++i) {
    {
      py::gil_scoped_release release;
      api::sticking_over_radii(in, {radii.data()[i]}, [&rows](const Record& row) { rows.push_back(row); }, {});
    }
    check_signals();
  }
  if (radii.size() == 0) api::sticking_over_radii(in, {}, [](const Record&) {}, {});  // the inputs still checked
  py::dict d = table_to_python(api::sticking_table(Value(rows)));
  const py::tuple shape = py::cast(shape_of(radii));
  for (const auto& [key, column] : d) d[key] = column.attr("reshape")(shape);
  if (radii.size() == 0) d["note"] = py::module_::import("numpy").attr("asarray")(py::list(), "str");
  return d;
}

py::object sticking(const PyPair& pair, const PyModel& model, const py::kwargs& options) {
  if (options.contains("radii")) {
    py::kwargs rest;
    for (const auto& [key, value] : options)
      if (py::str(key).cast<std::string>() != "radii") rest[key] = value;
    api::Inputs in = case_inputs(pair, model, rest);
    in.erase("radius");  // the sweep's radii replace the Pair's
    return sticking_over_radii(in, options["radii"]);
  }
  const api::Inputs in = case_inputs(pair, model, options);
  Record out;
  {
    py::gil_scoped_release release;
    out = api::sticking(in);
  }
  check_signals();
  return to_python(out);
}

py::object sticking_velocity(const PyPair& pair, const PyModel& model, const py::object& relative_tolerance) {
  py::kwargs options;
  options["relative_tolerance"] = relative_tolerance;
  return sticking(pair, model, options)["sticking_velocity"];  // None: no threshold below c_t
}

}  // namespace

void bind_collisions(py::module_& m) {
  m.def("collide", &collide, py::arg("pair"), py::arg("model"), py::arg("velocity"),
        "One head-on (or oblique) collision at impact speed `velocity` [m/s]: a dict with the keys of the CLI's "
        "`bounce collide --json` (cor, outcome, contact_time, max_overlap, energy, warnings, notes, ...). Keywords: "
        "tangential_velocity [m/s], trajectory=True (adds 'trajectory', a dict of arrays), trajectory_points, "
        "follow_time [s] (krijt, jkr-viscoelastic), and any numerical setting of the model (method, tolerance, "
        "adhesive_tolerance, stiff_engine). An array of speeds gives a dict of arrays of its shape (velocity, cor, "
        "outcome, stick, contact_time, max_overlap, bulk_dissipated, crack_dissipated; cor_tangential when oblique; "
        "warnings, each kind once), computed in C++ (Ctrl-C interrupts it). Validity warnings are also raised as "
        "bounce.ValidityWarning.");
  m.def("curve", &curve, py::arg("pair"), py::arg("model"), py::arg("velocities"),
        "The COR curve over an array of impact speeds [m/s] (the CLI's `bounce curve`): collide() over the array, a "
        "dict of arrays of its shape (velocity, cor, outcome, stick, contact_time, max_overlap, bulk_dissipated, "
        "crack_dissipated; cor_tangential with a tangential_velocity) and `warnings`, the validity warnings the CLI "
        "prints (each kind once, also raised as bounce.ValidityWarning); the loop in C++ (Ctrl-C interrupts it).");
  m.def("closed_forms", &closed_forms, py::arg("pair"), py::arg("model"), py::arg("velocity"),
        "The closed forms that apply to the pair and model at impact speed(s) `velocity` [m/s]: K13 (22) "
        "hertz_time_k13_22 always; with a surface energy (gamma > 0) (24) e_jkr, (25) sticking_velocity_k13_25 and the "
        "exact sticking_velocity_jkr, (11) tabor_parameter; with a dissipative constant A (26) e_d and "
        "dissipative_constant, and (27) e_i with both; BP04 (8.95), (8.98) for adhesive-viscoelastic; K13 (28), "
        "(29), (33) with a yield strength. A key that does not apply is absent (docs/python.md); e_d and e_i are "
        "None beyond (26)'s validity (5.57 A/t_H > 1), with `warnings` saying so. An array of speeds gives arrays "
        "(NaN for None).");
  m.def("viscoelastic_scales", &viscoelastic_scales, py::arg("pair"), py::arg("model"), py::arg("velocity"),
        "BP04 §8.3 scales of a Hertz-type collision with A > 0: A [s], C0, kappa (8.70), g* (8.88) [m/s], "
        "q = (g/g*)^{1/5}, xi0 (8.65) [m], the exact Hertz contact time [s].");
  m.def("sticking", &sticking, py::arg("pair"), py::arg("model"),
        "The sticking velocity of an adhesive model with its bracket, the collisions it took and the closed forms: "
        "the keys of `bounce sticking --json` (keyword relative_tolerance, default 1e-6). sticking_velocity is None, "
        "with a note, where the grains stick at every speed up to the transversal sound speed. With radii=array "
        "(body 1's radius [m], replacing the Pair's; body 2's follows it unless the Pair gives radius2): a dict of "
        "arrays of its shape, as `bounce sticking --radii` (radius, effective_radius, sticking_velocity, "
        "sticking_velocity_jkr, sticking_velocity_k13_25, note), NaN with a note where none was found.");
  m.def("sticking_velocity", &sticking_velocity, py::arg("pair"), py::arg("model"),
        py::arg("relative_tolerance") = 1e-6,
        "The sticking velocity [m/s] of an adhesive model (bisection on the outcome to relative_tolerance), or None "
        "where the grains stick at every speed up to the transversal sound speed (no threshold where the "
        "quasi-static models hold).");
}

}  // namespace bounce::python
