// ContactLaw (a static contact law bound to a pair) and contact_laws().
#include <memory>

#include <pybind11/stl.h>

#include "bounce/contact/law.hpp"
#include "objects.hpp"

namespace bounce::python {

namespace {

struct PyContactLaw {
  std::shared_ptr<contact::ContactLaw> law;
  api::Inputs inputs;  // the pair's, the law's keyword and its parameters: for the front door
};

using ContactAt = contact::ContactPoint (contact::ContactLaw::*)(double) const;

// law->*at for a float (-> dict) or an array (-> dict of arrays of its shape).
py::object contact_points(const PyContactLaw& l, ContactAt at, const py::object& x) {
  if (is_number(x)) {
    const auto p = ((*l.law).*at)(x.cast<double>());
    py::dict d;
    d["contact_radius"] = p.contact_radius;
    d["overlap"] = p.overlap;
    d["force"] = p.force;
    return d;
  }
  const Array in = x.cast<Array>();
  const std::vector<py::ssize_t> shape(in.shape(), in.shape() + in.ndim());
  Array a(shape), delta(shape), force(shape);
  for (py::ssize_t i = 0; i < in.size(); ++i) {
    const auto p = ((*l.law).*at)(in.data()[i]);
    a.mutable_data()[i] = p.contact_radius;
    delta.mutable_data()[i] = p.overlap;
    force.mutable_data()[i] = p.force;
  }
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
          "at_force", [](const PyContactLaw& l, const py::object& f) { return contact_points(l, &contact::ContactLaw::at_force, f); },
          py::arg("force"),
          "Stable state at normal force(s) F [N] (force control): dict of contact_radius [m], overlap [m], force [N]")
      .def(
          "at_overlap",
          [](const PyContactLaw& l, const py::object& d) { return contact_points(l, &contact::ContactLaw::at_overlap, d); },
          py::arg("overlap"), "Stable state at overlap(s) delta [m] (displacement control)")
      .def(
          "at_contact_radius",
          [](const PyContactLaw& l, const py::object& a) {
            return contact_points(l, &contact::ContactLaw::at_contact_radius, a);
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
