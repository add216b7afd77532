// ContactLaw (a static contact law bound to a pair) and contact_laws().
#include <cmath>
#include <memory>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include <pybind11/stl.h>

#include "bounce/api/resistance.hpp"
#include "bounce/contact/law.hpp"
#include "bounce/contact/resistance.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "objects.hpp"

namespace bounce::python {

namespace {

struct PyContactLaw {
  std::shared_ptr<contact::ContactLaw> law;
  api::Inputs inputs;  // the pair's, the law's keyword and its parameters: for the front door
};

using ContactAt = contact::ContactPoint (contact::ContactLaw::*)(double) const;

// One point of the law, never inf or NaN: a point beyond double precision (overlap 1e308 of
// Hertz gives an infinite force) is refused naming the input, as is one the law's solver
// cannot reach (its message, where the library throws something other than its own error).
contact::ContactPoint contact_point(const PyContactLaw& l, ContactAt at, const char* name, double x) {
  contact::ContactPoint p;
  try {
    p = ((*l.law).*at)(x);
  } catch (const Error&) {
    throw;
  } catch (const std::logic_error& e) {  // boost's root finders: std::domain_error
    throw InvalidArgument(name, format_value(x), fmt::format("a value at which the {} law can be solved ({})",
                                                             l.law->name(), e.what()));
  } catch (const std::runtime_error& e) {  // boost's evaluation and overflow errors
    throw InvalidArgument(name, format_value(x), fmt::format("a value at which the {} law can be solved ({})",
                                                             l.law->name(), e.what()));
  }
  for (const auto& [key, value] : {std::pair{"contact_radius", p.contact_radius}, {"overlap", p.overlap},
                                   {"force", p.force}}) {
    if (!std::isfinite(value)) {
      throw InvalidArgument(name, format_value(x),
                            fmt::format("a value at which the {} law's point is finite in double precision ({} = {})",
                                        l.law->name(), key, format_value(value)));
    }
  }
  return p;
}

// law->*at for a float (-> dict) or an array (-> dict of arrays of its shape).
py::object contact_points(const PyContactLaw& l, ContactAt at, const char* name, const py::object& x) {
  const auto values = to_numbers(name, x);
  if (const double* one = std::get_if<double>(&values)) {
    const auto p = contact_point(l, at, name, *one);
    py::dict d;
    d["contact_radius"] = p.contact_radius;
    d["overlap"] = p.overlap;
    d["force"] = p.force;
    return d;
  }
  const Array& in = std::get<Array>(values);
  const std::vector<py::ssize_t> shape(in.shape(), in.shape() + in.ndim());
  Array a(shape), delta(shape), force(shape);
  const double* x_i = in.data();
  double *a_i = a.mutable_data(), *delta_i = delta.mutable_data(), *force_i = force.mutable_data();
  for_each_index(in.size(), [&](py::ssize_t i) {
    const auto p = contact_point(l, at, name, x_i[i]);
    a_i[i] = p.contact_radius;
    delta_i[i] = p.overlap;
    force_i[i] = p.force;
  });
  py::dict d;
  d["contact_radius"] = a;
  d["overlap"] = delta;
  d["force"] = force;
  return d;
}

PyContactLaw make_law(const PyPair& pair, const std::string& law, const py::kwargs& parameters) {
  const api::Inputs own = to_inputs(parameters);
  api::Inputs in = pair.inputs;
  in.insert(own.begin(), own.end());
  in["law"] = law;
  return PyContactLaw{std::shared_ptr<contact::ContactLaw>(contact::make_contact_law(law, pair.pair, own)), std::move(in)};
}

// One state with everything `bounce contact --json` prints, through the front door.
py::object state(const PyContactLaw& l, const py::object& force, const py::object& overlap) {
  api::Inputs in = l.inputs;
  if (!force.is_none()) in["force"] = to_value("force", force);
  if (!overlap.is_none()) in["overlap"] = to_value("overlap", overlap);
  Record out;
  {
    py::gil_scoped_release release;
    out = api::contact(in);
  }
  if (const std::string bad = non_finite(out); !bad.empty()) {
    const char* name = overlap.is_none() ? "force" : "overlap";
    throw InvalidArgument(name, value_text(in.count(name) ? in.at(name) : ParameterValue{0.0}),
                          fmt::format("a value at which every result of the {} law is finite in double precision ({})",
                                      l.law->name(), bad));
  }
  return to_python(out);
}

py::object adhesion(const PyContactLaw& l) {
  const auto a = l.law->adhesion();
  if (!a) return py::none();
  py::dict d;
  for (const auto& [key, value] : contact::named_values(*a)) d[py::str(key)] = value;
  return d;
}

}  // namespace

void bind_contact(py::module_& m) {
  m.def(
      "contact_resistance",
      [](const PyPair& pair, const py::object& xi_crit) {
        api::Inputs in = pair.inputs;
        in["xi_crit"] = to_number("xi_crit", xi_crit);
        return to_python(api::contact_resistance(in));
      },
      py::arg("pair"), py::arg("xi_crit") = contact::resistance::standard_critical_rolling,
      "How the pair's JKR contact resists rolling, sliding and twisting, and the energy that breaks it (Dominik & "
      "Tielens; Wada et al. 2007; docs/resistance.md): the dict of `bounce contact resistance --json`. xi_crit: the "
      "critical rolling displacement [m], 0 < xi_crit < a0.");
  m.def(
      "contact_laws",
      [] {
        py::list out;
        for (const auto& row : contact::contact_laws()) {
          py::dict d;
          d["name"] = row.name;
          d["needs_surface_energy"] = row.needs_surface_energy;
          d["summary"] = row.summary;
          d["references"] = row.references;
          out.append(d);
        }
        return out;
      },
      "The static contact laws: name, needs_surface_energy, summary, references (bounce.models() adds parameters).");
  py::class_<PyContactLaw>(m, "ContactLaw",
                           "A static contact law for a pair: hertz, jkr, dmt or maugis (docs/contact.md).")
      .def(py::init(&make_law), py::arg("pair"), py::arg("law") = "hertz",
           "ContactLaw(pair, 'maugis', z0=3e-10): the law's parameters by keyword (z0 for the adhesive laws; "
           "curvature_radii, curvature_radii2, angle for hertz between convex bodies).")
      .def_property_readonly("name", [](const PyContactLaw& l) { return std::string(l.law->name()); })
      .def(
          "at_force",
          [](const PyContactLaw& l, const py::object& f) {
            return contact_points(l, &contact::ContactLaw::at_force, "force", f);
          },
          py::arg("force"),
          "Stable state at normal force(s) F [N] (force control): dict of contact_radius [m], overlap [m], force [N]")
      .def(
          "at_overlap",
          [](const PyContactLaw& l, const py::object& d) {
            return contact_points(l, &contact::ContactLaw::at_overlap, "overlap", d);
          },
          py::arg("overlap"), "Stable state at overlap(s) delta [m] (displacement control)")
      .def(
          "at_contact_radius",
          [](const PyContactLaw& l, const py::object& a) {
            return contact_points(l, &contact::ContactLaw::at_contact_radius, "contact_radius", a);
          },
          py::arg("contact_radius"), "The point of the law's curve with contact radius a [m] (stable or not)")
      .def("state", &state, py::arg("force") = py::none(), py::arg("overlap") = py::none(),
           "One state at a force [N] (default 0) or an overlap [m] with everything `bounce contact --json` prints, the "
           "same keys and values: the point, the pair, the adhesive law's pull-off and zero-load values, Tabor "
           "parameters, regimes and warnings, the contact ellipse of convex bodies.")
      .def_property_readonly("adhesion", &adhesion, "Pull-off and zero-load quantities (dict), None for hertz")
      .def("__repr__", [](const PyContactLaw& l) { return "<bounce.ContactLaw " + std::string(l.law->name()) + ">"; });
}

}  // namespace bounce::python
