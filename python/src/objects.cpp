// Pair, Model and the listings (materials, models).
#include "objects.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/models/registry.hpp"
#include "bounce/pair/materials_table.hpp"
#include "bounce/pair/pair_parameters.hpp"

namespace bounce::python {

namespace {

// Python's wall="none" | "elastic" | "rigid" as the pair's flags wall and rigid_wall (a
// bool is the flag wall itself: True for an elastic wall).
api::Inputs pair_inputs(const py::kwargs& kwargs) {
  py::kwargs rest;
  std::string wall = "none";
  for (const auto& [key, value] : kwargs) {
    if (key.cast<std::string>() != "wall" || value.is_none() || PyBool_Check(value.ptr())) {
      rest[key] = value;
    } else if (py::isinstance<py::str>(value)) {
      wall = value.cast<std::string>();
    } else {
      refuse_type("wall", value, "a str: one of none, elastic, rigid");
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

// The pair's derived quantities are never inf or 0 (R = 1e100 of water ice gave m_eff =
// m1 m2/(m1 + m2) = inf): refused here, naming the radius, where the library lets one through.
void require_normal_quantities(const Pair& pair, const api::Inputs& in) {
  const std::pair<const char*, double> derived[] = {{"effective radius R_eff [m]", pair.effective_radius()},
                                                    {"effective mass m_eff [kg]", pair.effective_mass()},
                                                    {"effective modulus E* [Pa]", pair.effective_modulus()}};
  for (const auto& [what, x] : derived) {
    if (std::isnormal(x)) continue;
    const auto r = in.find("radius");
    throw InvalidArgument("radius", r == in.end() ? "(not given)" : value_text(r->second),
                          fmt::format("a pair whose {} is finite and > 0 in double precision (it is {})", what,
                                      format_value(x)));
  }
}

PyPair make_py_pair(const py::kwargs& kwargs) {
  api::Inputs in = pair_inputs(kwargs);
  Pair pair = api::make_pair(in);
  require_normal_quantities(pair, in);
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

double check_speed(const char* python_name, double velocity) {
  static const ParameterSpec spec = [] {
    for (const ParameterSpec& s : api::command("collide").parameters) {
      if (s.name == "velocity") return s;
    }
    throw std::logic_error("bounce collide declares no velocity");
  }();
  try {
    bind_parameters(std::span(&spec, 1), api::Inputs{{"velocity", velocity}}, "bounce collide");
  } catch (const InvalidArgument& e) {
    throw e.renamed(python_name);
  }
  return velocity;
}

api::Inputs case_inputs(const PyPair& pair, const PyModel& model, const py::kwargs& options) {
  api::Inputs in = pair.inputs;
  for (const auto& [key, value] : model.inputs) in[key] = value;
  in["model"] = model.name;
  // The Pair and the Model hold their parameters: a call keyword adds a setting, it does not
  // silently replace what the Pair or the Model says (radius=..., A=... given twice).
  const auto& pair_specs = pair_parameters();
  for (const auto& [key, value] : options) {
    const std::string python = key.cast<std::string>(), name = library_name(python);
    if (value.is_none()) continue;
    const bool of_pair = name == "model" || std::any_of(pair_specs.begin(), pair_specs.end(),
                                                        [&](const ParameterSpec& s) { return s.name == name; });
    if (of_pair) {
      throw InvalidArgument(python, py::repr(value).cast<std::string>(),
                            fmt::format("{} in bounce.{}(...), not as a keyword of the call", python,
                                        name == "model" ? "Model" : "Pair"));
    }
    if (const auto set = model.inputs.find(name); set != model.inputs.end()) {
      throw InvalidArgument(python, py::repr(value).cast<std::string>(),
                            fmt::format("{} once: the Model already sets {} = {}", python, python,
                                        value_text(set->second)));
    }
  }
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
      .def(py::init(&make_py_model), py::arg("name") = std::string(models::ModelRegistry::default_name()),
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
