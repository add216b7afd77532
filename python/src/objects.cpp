// Pair, Model and the listings (materials, models).
#include "objects.hpp"

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bounce/core/error.hpp"
#include "bounce/pair/materials_table.hpp"

namespace bounce::python {

namespace {

// Python's wall="none" | "elastic" | "rigid" as the pair's flags wall and rigid_wall.
api::Inputs pair_inputs(const py::kwargs& kwargs) {
  py::kwargs rest;
  std::string wall = "none";
  for (const auto& [key, value] : kwargs) {
    if (key.cast<std::string>() == "wall" && py::isinstance<py::str>(value)) {
      wall = value.cast<std::string>();
    } else {
      rest[key] = value;
    }
  }
  api::Inputs in = to_inputs(rest);
  if (wall == "elastic") {
    in["wall"] = true;
  } else if (wall == "rigid") {
    in["rigid_wall"] = true;
  } else if (wall != "none") {
    throw InvalidArgument("wall", wall, "one of none, elastic, rigid");
  }
  return in;
}

PyPair make_py_pair(const py::kwargs& kwargs) {
  api::Inputs in = pair_inputs(kwargs);
  Pair pair = api::make_pair(in);
  return PyPair{std::move(in), std::move(pair)};
}

PyModel make_py_model(const std::string& name, const py::kwargs& kwargs) {
  api::Inputs in = to_inputs(kwargs);
  api::check_model(name, in);  // ValueError naming a parameter the model does not take
  return PyModel{name, std::move(in)};
}

py::dict material_dict(const std::string& name) {
  const Material& x = MaterialTable::builtin().at(name);
  py::dict d;
  d["name"] = x.name;
  d["E"] = x.youngs_modulus;
  d["nu"] = x.poisson_ratio;
  d["density"] = x.density;
  d["gamma"] = x.surface_energy ? py::cast(*x.surface_energy) : py::none();
  d["source"] = x.source;
  return d;
}

}  // namespace

api::Inputs case_inputs(const PyPair& pair, const PyModel& model, const py::kwargs& options) {
  api::Inputs in = pair.inputs;
  for (const auto& [key, value] : model.inputs) in[key] = value;
  in["model"] = model.name;
  for (const auto& [key, value] : to_inputs(options)) in[key] = value;
  return in;
}

api::Case make_case(const PyPair& pair, const PyModel& model, const py::kwargs& options) {
  return api::make_case("collide", case_inputs(pair, model, options));
}

void bind_objects(py::module_& m) {
  m.def("material_names", [] { return MaterialTable::builtin().names(); },
        "Names of the built-in materials (K13 table 2 and ice-bshp96).");
  m.def("material", &material_dict, py::arg("name"),
        "A built-in material as a dict: E [Pa], nu, density [kg/m^3], gamma [J/m^2] or None.");
  m.def("materials", [] { return to_python(api::materials({})); },
        "The materials table as the CLI's `bounce materials --json` prints it.");
  m.def("models", [] { return to_python(api::models()); },
        "The collision models and contact laws with every parameter (name, kind, unit, allowed, default, help).");

  py::class_<PyPair>(m, "Pair", "Two bodies in contact: body 1 a sphere, body 2 a sphere or a wall (SI units).")
      .def(py::init(&make_py_pair),
           "Pair(material='water-ice', radius=1e-6) or explicit E, nu, density, gamma; body 2 defaults to body 1 "
           "(material2=..., radius2=..., E2=..., ...) or wall='elastic'|'rigid'; inertia = J/(m R^2); "
           "materials_file=PATH for another table. The names are those of the CLI's options.")
      .def_property_readonly("effective_radius", [](const PyPair& p) { return p.pair.effective_radius(); }, "R_eff [m]")
      .def_property_readonly("effective_mass", [](const PyPair& p) { return p.pair.effective_mass(); }, "m_eff [kg]")
      .def_property_readonly("effective_modulus", [](const PyPair& p) { return p.pair.effective_modulus(); }, "E* [Pa]")
      .def_property_readonly("surface_energy", [](const PyPair& p) { return p.pair.surface_energy(); },
                             "combined gamma [J/m^2] or None")
      .def_property_readonly("kappa", [](const PyPair& p) { return p.pair.tangential_mass_factor(); },
                             "kappa of BSHP96 (8)")
      .def("to_dict", [](const PyPair& p) { return to_python(api::pair_record(p.pair)); },
           "The pair as the CLI's JSON prints it (bodies and pair quantities).")
      .def("__repr__", [](const PyPair& p) {
        return fmt::format("<bounce.Pair R_eff={:.6g} m, m_eff={:.6g} kg>", p.pair.effective_radius(),
                           p.pair.effective_mass());  // %g: micron grains are not 0.000000
      });

  py::class_<PyModel>(m, "Model", "A collision model and its parameters (the CLI's option names, SI units).")
      .def(py::init(&make_py_model), py::arg("name") = "viscoelastic",
           "Model('krijt', tvis=1e-11): any model of bounce.models() with the parameters it takes (bounce.models() "
           "lists them; yield_strength is Python's spelling of yield). A parameter the model does not take is a "
           "ValueError.")
      .def_readonly("name", &PyModel::name)
      .def_property_readonly("parameters", [](const PyModel& p) {
        py::dict d;
        for (const auto& [key, value] : p.inputs) {
          d[py::str(key)] = std::visit([](const auto& v) { return py::cast(v); }, value);
        }
        return d;
      }, "The parameters given.")
      .def("__repr__", [](const PyModel& p) { return "<bounce.Model " + p.name + ">"; });
}

}  // namespace bounce::python
