// pybind11 bindings of the bounce library (docs/python.md). Thin: every physical
// quantity comes from the library; arrays of speeds loop in C++, not in Python.
// Library errors map to Python: InvalidArgument -> ValueError (the foundation's one-line
// message naming the parameter, its value and the allowed range), NumericalError ->
// RuntimeError.
#include <cmath>
#include <map>
#include <optional>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bounce/analysis/closed_forms.hpp"
#include "bounce/analysis/collide.hpp"
#include "bounce/analysis/rules.hpp"
#include "bounce/analysis/sticking.hpp"
#include "bounce/analysis/tables.hpp"
#include "bounce/analytic/master_curve.hpp"
#include "bounce/analytic/viscoelastic.hpp"
#include "bounce/contact/law.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/models/registry.hpp"
#include "bounce/pair/materials_table.hpp"

namespace py = pybind11;
using namespace bounce;

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

Material resolve(const std::optional<std::string>& name, std::optional<double> E, std::optional<double> nu,
                 std::optional<double> density, std::optional<double> gamma, const Material* fallback,
                 const std::string& suffix) {
  Material m;
  if (name) {
    m = MaterialTable::builtin().at(*name);
  } else if (fallback) {
    m = *fallback;
  } else if (!E || !nu || !density) {
    const char* missing = !E ? "E" : !nu ? "nu" : "density";
    throw InvalidArgument(missing + suffix, "(not given)", "a value, or material" + suffix + "=NAME");
  }
  if (E) m.youngs_modulus = *E;
  if (nu) m.poisson_ratio = *nu;
  if (density) m.density = *density;
  if (gamma) m.surface_energy = *gamma;
  if ((E || nu || density || gamma) && !m.name.empty()) m.name += " (modified)";
  return m;
}

Pair make_pair(std::optional<std::string> material, std::optional<double> radius, std::optional<double> E,
               std::optional<double> nu, std::optional<double> density, std::optional<double> gamma,
               std::optional<std::string> material2, std::optional<double> radius2, std::optional<double> E2,
               std::optional<double> nu2, std::optional<double> density2, std::optional<double> gamma2,
               const std::string& wall, double inertia, std::optional<double> inertia2) {
  const Material m1 = resolve(material, E, nu, density, gamma, nullptr, "");
  const Material m2 = resolve(material2, E2, nu2, density2, gamma2, &m1, "2");
  if (!radius) throw InvalidArgument("radius", "(not given)", "a radius > 0 m for body 1");
  Body b1 = sphere(m1, *radius);
  b1.inertia_factor = inertia;
  Body b2;
  if (wall == "elastic" || wall == "rigid") {
    if (radius2) throw InvalidArgument("radius2", std::to_string(*radius2), "no radius2 with a wall");
    b2 = wall == "rigid" ? rigid_wall(m2) : bounce::wall(m2);
  } else if (wall == "none") {
    b2 = sphere(m2, radius2.value_or(*radius));
    b2.inertia_factor = inertia2.value_or(inertia);
  } else {
    throw InvalidArgument("wall", wall, "one of none, elastic, rigid");
  }
  return Pair(b1, b2);
}

models::ModelSpec make_model(const std::string& name, std::optional<double> A, std::optional<double> eta1,
                             std::optional<double> eta2, const std::string& contact_end, std::optional<double> tvis,
                             double z0, double k, std::optional<double> B, std::optional<double> yield_strength,
                             const std::string& tangential_law, const std::string& asperity_form,
                             std::optional<double> friction, std::optional<double> asperity,
                             std::optional<double> shear_damping) {
  (void)models::model_info(name);  // InvalidArgument for an unknown model
  models::ModelSpec s;
  s.name = name;
  s.dissipative_constant = A;
  s.shear_viscosity = eta1;
  s.bulk_viscosity = eta2;
  s.end_rule = models::parse_end_rule(contact_end);
  s.relaxation_time = tvis;
  s.z0 = z0;
  s.k = k;
  s.dissipative_constant_b = B;
  s.yield_strength = yield_strength;
  s.tangential_law = models::parse_tangential_law(tangential_law);
  s.asperity_form = models::parse_asperity_form(asperity_form);
  s.friction = friction;
  s.asperity_size = asperity;
  s.shear_damping = shear_damping;
  return s;
}

CollideOptions options(const std::string& method, double tangential_velocity) {
  CollideOptions o;
  o.method = parse_method(method);
  require_finite("tangential_velocity", tangential_velocity);
  if (tangential_velocity < 0.0) {
    throw InvalidArgument("tangential_velocity", std::to_string(tangential_velocity), "g^T >= 0 m/s");
  }
  o.tangential_velocity = tangential_velocity;
  return o;
}

py::dict energy_dict(const dynamics::EnergyBudget& e) {
  py::dict d;
  d["initial_kinetic"] = e.initial_kinetic;
  d["final_kinetic"] = e.final_kinetic;
  d["bulk_dissipated"] = e.bulk_dissipated;
  d["crack_dissipated"] = e.crack_dissipated;
  d["plastic_dissipated"] = e.plastic_dissipated;
  d["elastic_remaining"] = e.elastic_remaining;
  d["surface_remaining"] = e.surface_remaining;
  d["closure_error"] = e.closure_error;
  return d;
}

py::dict outcome_dict(const dynamics::CollisionOutcome& o) {
  py::dict d;
  d["cor"] = o.cor;
  d["outcome"] = std::string(dynamics::to_string(o.outcome));
  d["contact_time"] = o.contact_time;
  d["max_overlap"] = o.max_overlap;
  d["energy"] = energy_dict(o.energy);
  d["warnings"] = o.warnings;
  if (o.tangential) d["cor_tangential"] = o.tangential->cor;
  return d;
}

// collide() over an array of speeds: a dict of arrays of the input's shape.
py::dict collide_many(const Pair& pair, const models::ModelSpec& model, const Array& speeds, const CollideOptions& o) {
  const py::ssize_t n = speeds.size();
  std::vector<py::ssize_t> shape(speeds.shape(), speeds.shape() + speeds.ndim());
  Array cor(shape), time(shape), overlap(shape), cor_t(shape), bulk(shape), crack(shape);
  py::array_t<bool> stick(shape);
  const double* v = speeds.data();
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < n; ++i) {
      const auto out = collide(pair, model, v[i], o);
      cor.mutable_data()[i] = out.cor;
      time.mutable_data()[i] = out.contact_time;
      overlap.mutable_data()[i] = out.max_overlap;
      bulk.mutable_data()[i] = out.energy.bulk_dissipated;
      crack.mutable_data()[i] = out.energy.crack_dissipated;
      stick.mutable_data()[i] = out.outcome == dynamics::Outcome::stick;
      cor_t.mutable_data()[i] = out.tangential ? out.tangential->cor : std::nan("");
    }
  }
  py::dict d;
  d["velocity"] = speeds;
  d["cor"] = cor;
  d["stick"] = stick;
  d["contact_time"] = time;
  d["max_overlap"] = overlap;
  d["bulk_dissipated"] = bulk;
  d["crack_dissipated"] = crack;
  if (o.tangential_velocity > 0.0) d["cor_tangential"] = cor_t;
  return d;
}

// A Python int or float (numpy float64 included): the scalar form of the calls that take arrays.
bool is_number(const py::handle& x) { return py::isinstance<py::float_>(x) || py::isinstance<py::int_>(x); }

// f applied to a float (-> float) or elementwise to an array (-> array of its shape).
template <class R, class F>
py::object map_values(py::object x, F f) {
  if (is_number(x)) return py::cast(f(x.cast<double>()));
  const Array a = x.cast<Array>();
  py::array_t<R> out(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()));
  for (py::ssize_t i = 0; i < a.size(); ++i) out.mutable_data()[i] = f(a.data()[i]);
  return out;
}

Vector3 vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

py::dict rule_dict(const CollisionRuleResult& r) {
  py::dict d;
  d["velocity1"] = r.grain1.velocity;
  d["angular_velocity1"] = r.grain1.angular_velocity;
  d["velocity2"] = r.grain2.velocity;
  d["angular_velocity2"] = r.grain2.angular_velocity;
  d["cor"] = r.cor;
  d["cor_tangential"] = r.cor_tangential;
  d["energy_change"] = r.energy_change;
  return d;
}

// The trajectory as a dict of arrays (one entry per TrajectorySample field).
py::dict trajectory_dict(const std::vector<dynamics::TrajectorySample>& samples) {
  const auto column = [&](double dynamics::TrajectorySample::*field) {
    Array a(static_cast<py::ssize_t>(samples.size()));
    for (std::size_t i = 0; i < samples.size(); ++i) a.mutable_data()[i] = samples[i].*field;
    return a;
  };
  using S = dynamics::TrajectorySample;
  py::dict d;
  d["time"] = column(&S::time);
  d["overlap"] = column(&S::overlap);
  d["rate"] = column(&S::rate);
  d["contact_radius"] = column(&S::contact_radius);
  d["elastic_force"] = column(&S::elastic_force);
  d["dissipative_force"] = column(&S::dissipative_force);
  d["beta"] = column(&S::effective_surface_energy_ratio);
  d["kinetic"] = column(&S::kinetic);
  d["elastic"] = column(&S::elastic);
  d["surface"] = column(&S::surface);
  d["bulk_dissipated"] = column(&S::bulk_dissipated);
  d["crack_dissipated"] = column(&S::crack_dissipated);
  return d;
}

// A static contact law bound to one pair (contact/law.hpp).
struct PyContactLaw {
  std::shared_ptr<contact::ContactLaw> law;
};

using ContactAt = contact::ContactPoint (contact::ContactLaw::*)(double) const;

// law->*at for a float (-> dict) or an array (-> dict of arrays of its shape).
py::object contact_points(const PyContactLaw& l, ContactAt at, py::object x) {
  const auto point_dict = [](const contact::ContactPoint& p) {
    py::dict d;
    d["contact_radius"] = p.contact_radius;
    d["overlap"] = p.overlap;
    d["force"] = p.force;
    return d;
  };
  if (is_number(x)) {
    return point_dict(((*l.law).*at)(x.cast<double>()));
  }
  const Array in = x.cast<Array>();
  std::vector<py::ssize_t> shape(in.shape(), in.shape() + in.ndim());
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

py::dict closed_forms_dict(const AdhesiveClosedForms& c) {
  py::dict d;
  for (const auto& [key, value] : named_values(c)) d[py::str(key)] = value;
  return d;
}

// The a_k of BP04 (8.89) by name: "bp04-simple", "bp04" (quoted), "bounce" (master curve fit).
analytic::IntegerSeries series_named(const std::string& name) {
  if (name == "bp04-simple") return analytic::bp04_simple_series();
  if (name == "bp04") return analytic::bp04_rigorous_series();
  if (name == "bounce") return analytic::master_series_overlap();
  throw InvalidArgument("series", name, "one of bp04-simple, bp04, bounce");
}

// The d_k of BP04 (8.92): "bp04-printed" (8.93 as printed) or (8.93) applied to a named series.
analytic::PadeCoefficients pade_named(const std::string& name) {
  if (name == "bp04-printed") return analytic::bp04_printed_pade();
  if (name == "bp04-simple" || name == "bp04" || name == "bounce") {
    return analytic::pade_coefficients(series_named(name));
  }
  throw InvalidArgument("coefficients", name, "one of bp04-printed, bp04-simple, bp04, bounce");
}

}  // namespace

PYBIND11_MODULE(_bounce, m) {
  m.doc() = "bounce: the physics of colliding grains (C++ core; see docs/python.md)";
  py::register_exception_translator([](std::exception_ptr p) {
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

  m.def("material_names", [] { return MaterialTable::builtin().names(); },
        "Names of the built-in materials (K13 table 2 and ice-bshp96).");
  m.def(
      "material",
      [](const std::string& name) {
        const Material& x = MaterialTable::builtin().at(name);
        py::dict d;
        d["name"] = x.name;
        d["E"] = x.youngs_modulus;
        d["nu"] = x.poisson_ratio;
        d["density"] = x.density;
        d["gamma"] = x.surface_energy ? py::cast(*x.surface_energy) : py::none();
        d["source"] = x.source;
        return d;
      },
      py::arg("name"), "A built-in material as a dict: E [Pa], nu, density [kg/m^3], gamma [J/m^2] or None.");

  py::class_<Pair>(m, "Pair", "Two bodies in contact: body 1 a sphere, body 2 a sphere or a wall (SI units).")
      .def(py::init(&make_pair), py::kw_only(), py::arg("material") = py::none(), py::arg("radius") = py::none(),
           py::arg("E") = py::none(), py::arg("nu") = py::none(), py::arg("density") = py::none(),
           py::arg("gamma") = py::none(), py::arg("material2") = py::none(), py::arg("radius2") = py::none(),
           py::arg("E2") = py::none(), py::arg("nu2") = py::none(), py::arg("density2") = py::none(),
           py::arg("gamma2") = py::none(), py::arg("wall") = "none", py::arg("inertia") = 0.4,
           py::arg("inertia2") = py::none(),
           "Pair(material='water-ice', radius=1e-6) or explicit E, nu, density, gamma; body 2 defaults to body 1 "
           "(material2=..., radius2=..., ...) or wall='elastic'|'rigid'. inertia = J/(m R^2).")
      .def_property_readonly("effective_radius", &Pair::effective_radius, "R_eff [m]")
      .def_property_readonly("effective_mass", &Pair::effective_mass, "m_eff [kg]")
      .def_property_readonly("effective_modulus", &Pair::effective_modulus, "E* [Pa]")
      .def_property_readonly("surface_energy", &Pair::surface_energy, "combined gamma [J/m^2] or None")
      .def_property_readonly("kappa", &Pair::tangential_mass_factor, "kappa of BSHP96 (8)")
      .def("__repr__", [](const Pair& p) {
        return "<bounce.Pair R_eff=" + std::to_string(p.effective_radius()) +
               " m, m_eff=" + std::to_string(p.effective_mass()) + " kg>";
      });

  py::class_<models::ModelSpec>(m, "Model", "A collision model and its parameters (SPEC §7 names, SI units).")
      .def(py::init(&make_model), py::arg("name") = "viscoelastic", py::kw_only(), py::arg("A") = py::none(),
           py::arg("eta1") = py::none(), py::arg("eta2") = py::none(), py::arg("contact_end") = "overlap",
           py::arg("tvis") = py::none(), py::arg("z0") = 0.2e-9, py::arg("k") = 0.02, py::arg("B") = py::none(),
           py::arg("yield_strength") = py::none(), py::arg("tangential_law") = "asperity",
           py::arg("asperity_form") = "published", py::arg("friction") = py::none(),
           py::arg("asperity") = py::none(), py::arg("shear_damping") = py::none(),
           "Model('krijt', tvis=1e-11): hertz, viscoelastic, viscoelastic-shifted, power-law, "
           "adhesive-viscoelastic, krijt, jkr-viscoelastic; tangential: friction, asperity [m], shear_damping.")
      .def_readonly("name", &models::ModelSpec::name)
      .def("__repr__", [](const models::ModelSpec& s) { return "<bounce.Model " + s.name + ">"; });

  m.def(
      "collide",
      [](const Pair& pair, const models::ModelSpec& model, py::object velocity, double tangential_velocity,
         const std::string& method, bool trajectory, int trajectory_points, double follow_time) -> py::object {
        CollideOptions o = options(method, tangential_velocity);
        const bool scalar = is_number(velocity);
        if (trajectory) {
          if (!scalar) throw InvalidArgument("trajectory", "True", "a single velocity (not an array)");
          if (trajectory_points < 2) {
            throw InvalidArgument("trajectory_points", std::to_string(trajectory_points), "at least 2 samples");
          }
          o.record_trajectory = true;
          o.trajectory_points = trajectory_points;
        }
        o.follow_time = require_non_negative("follow_time", follow_time, "follow time [s]");
        if (scalar) {
          const double v = velocity.cast<double>();
          dynamics::CollisionOutcome out;
          {
            py::gil_scoped_release release;
            out = collide(pair, model, v, o);
          }
          py::dict d = outcome_dict(out);
          if (trajectory) d["trajectory"] = trajectory_dict(out.trajectory);
          return d;
        }
        return collide_many(pair, model, velocity.cast<Array>(), o);
      },
      py::arg("pair"), py::arg("model"), py::arg("velocity"), py::kw_only(), py::arg("tangential_velocity") = 0.0,
      py::arg("method") = "auto", py::arg("trajectory") = false, py::arg("trajectory_points") = 400,
      py::arg("follow_time") = 0.0,
      "One head-on (or oblique) collision at impact speed `velocity` [m/s]: a dict with cor, outcome, "
      "contact_time, max_overlap, energy, warnings (and cor_tangential). An array of speeds gives a dict of arrays "
      "(cor, stick, contact_time, max_overlap, bulk_dissipated, crack_dissipated), computed in C++. "
      "trajectory=True (one speed) adds 'trajectory': arrays time, overlap, rate, contact_radius, elastic_force, "
      "dissipative_force, beta, kinetic, elastic, surface, bulk_dissipated, crack_dissipated [SI]; follow_time [s] "
      "keeps integrating a sticking collision (krijt, jkr-viscoelastic) to show how the grains settle.");

  m.def(
      "closed_forms",
      [](const Pair& pair, const models::ModelSpec& model, py::object velocity) -> py::object {
        if (is_number(velocity)) {
          return closed_forms_dict(adhesive_closed_forms(pair, model, velocity.cast<double>()));
        }
        const Array v = velocity.cast<Array>();
        const std::vector<py::ssize_t> shape(v.shape(), v.shape() + v.ndim());
        std::map<std::string, Array> columns;  // the keys depend on the model, not on the speed
        for (py::ssize_t i = 0; i < v.size(); ++i) {
          for (const auto& [key, value] : named_values(adhesive_closed_forms(pair, model, v.data()[i]))) {
            columns.try_emplace(key, shape).first->second.mutable_data()[i] = value;
          }
        }
        py::dict d;
        for (const auto& [key, column] : columns) d[py::str(key)] = column;
        return d;
      },
      py::arg("pair"), py::arg("model"), py::arg("velocity"),
      "The closed forms beside an adhesive collision: K13 (22) hertz_time_k13_22, (24) e_jkr, (25) "
      "sticking_velocity_k13_25 and the exact sticking_velocity_jkr, (26) e_d, (27) e_i, (11) tabor_parameter; "
      "BP04 (8.95), (8.98) for adhesive-viscoelastic; K13 (28), (29), (33) with a yield strength. "
      "An array of speeds gives a dict of arrays.");

  m.def(
      "viscoelastic_scales",
      [](const Pair& pair, const models::ModelSpec& model, double velocity) {
        const ViscoelasticScales s = viscoelastic_scales(pair, model, velocity);
        py::dict d;
        d["dissipative_constant"] = s.dissipative_constant;
        d["force_constant"] = s.force_constant;
        d["kappa"] = s.kappa;
        d["characteristic_velocity"] = s.characteristic_velocity;
        d["q"] = s.q;
        d["reference_overlap"] = s.reference_overlap;
        d["hertz_contact_time"] = s.hertz_contact_time;
        return d;
      },
      py::arg("pair"), py::arg("model"), py::arg("velocity"),
      "BP04 §8.3 scales of a viscoelastic collision: A [s], C0, kappa (8.70), g* (8.88) [m/s], q = (g/g*)^{1/5}, "
      "xi0 (8.65) [m], the exact Hertz contact time [s].");

  m.def(
      "cor_series",
      [](py::object q, const std::string& series) {
        const auto s = series_named(series);
        return map_values<double>(q, [&](double x) { return analytic::cor_series(x, s); });
      },
      py::arg("q"), py::arg("series") = "bounce",
      "BP04 (8.89) truncated after a4, e(q) with q = (g/g*)^{1/5}; series = 'bounce' (master curve fit), "
      "'bp04' (BP04's quoted a_k) or 'bp04-simple'.");
  m.def(
      "cor_pade",
      [](py::object q, const std::string& coefficients) {
        const auto d = pade_named(coefficients);
        return map_values<double>(q, [&](double x) { return analytic::cor_pade(x, d); });
      },
      py::arg("q"), py::arg("coefficients") = "bp04-printed",
      "BP04 (8.92) Pade form e(q), q = (g/g*)^{1/5}; coefficients = 'bp04-printed' ((8.93) as printed, BP04 "
      "Fig 8.2) or (8.93) applied to the a_k of 'bp04', 'bp04-simple' or 'bounce'.");

  m.def(
      "contact_laws",
      [] {
        py::list out;
        for (const auto& info : contact::contact_laws()) {
          py::dict d;
          d["name"] = info.name;
          d["needs_surface_energy"] = info.needs_surface_energy;
          d["summary"] = info.summary;
          d["references"] = info.references;
          out.append(d);
        }
        return out;
      },
      "The static contact laws: name, needs_surface_energy, summary, references.");
  py::class_<PyContactLaw>(m, "ContactLaw",
                           "A static contact law for a pair: hertz, jkr, dmt or maugis (docs/contact.md).")
      .def(py::init([](const Pair& pair, const std::string& law, double z0) {
             require_positive("z0", z0, "equilibrium separation z0 [m]");
             return PyContactLaw{std::shared_ptr<contact::ContactLaw>(
                 contact::make_contact_law(law, pair, contact::LawOptions{z0}))};
           }),
           py::arg("pair"), py::arg("law") = "hertz", py::kw_only(), py::arg("z0") = 0.2e-9)
      .def_property_readonly("name", [](const PyContactLaw& l) { return std::string(l.law->name()); })
      .def(
          "at_force", [](const PyContactLaw& l, py::object f) { return contact_points(l, &contact::ContactLaw::at_force, f); },
          py::arg("force"),
          "Stable state at normal force(s) F [N] (force control): dict of contact_radius [m], overlap [m], force [N]")
      .def(
          "at_overlap",
          [](const PyContactLaw& l, py::object d) { return contact_points(l, &contact::ContactLaw::at_overlap, d); },
          py::arg("overlap"), "Stable state at overlap(s) delta [m] (displacement control)")
      .def(
          "at_contact_radius",
          [](const PyContactLaw& l, py::object a) {
            return contact_points(l, &contact::ContactLaw::at_contact_radius, a);
          },
          py::arg("contact_radius"), "The point of the law's curve with contact radius a [m] (stable or not)")
      .def_property_readonly(
          "adhesion",
          [](const PyContactLaw& l) -> py::object {
            const auto a = l.law->adhesion();
            if (!a) return py::none();
            py::dict d;
            for (const auto& [key, value] : contact::named_values(*a)) d[py::str(key)] = value;
            return d;
          },
          "Pull-off and zero-load quantities (dict), None for hertz")
      .def("__repr__", [](const PyContactLaw& l) { return "<bounce.ContactLaw " + std::string(l.law->name()) + ">"; });

  m.def(
      "sticking_velocity",
      [](const Pair& pair, const models::ModelSpec& model, double relative_tolerance) {
        py::gil_scoped_release release;
        return sticking_velocity(pair, model, {}, relative_tolerance).velocity;
      },
      py::arg("pair"), py::arg("model"), py::arg("relative_tolerance") = 1e-6,
      "The sticking velocity [m/s] of an adhesive model (bisection on the outcome).");

  m.def(
      "master_cor",
      [](py::object kappa, const std::string& contact_end) {
        const auto rule = models::parse_end_rule(contact_end);
        return map_values<double>(kappa, [&](double k) { return analytic::master_cor(k, rule); });
      },
      py::arg("kappa"), py::arg("contact_end") = "overlap",
      "The viscoelastic master curve e(kappa) (BP04 (8.66) scaling), error <= 1e-10.");

  py::class_<NormalTable>(m, "NormalTable", "eps^N(g) with the outcome, to a stated interpolation error.")
      .def_static(
          "build",
          [](const Pair& pair, const models::ModelSpec& model, double g_min, double g_max, double bound) {
            TableOptions t;
            t.bound = bound;
            py::gil_scoped_release release;
            return build_normal_table(pair, model, g_min, g_max, {}, t);
          },
          py::arg("pair"), py::arg("model"), py::arg("g_min"), py::arg("g_max"), py::arg("bound") = 1e-6)
      .def_static("from_json", &NormalTable::from_json, py::arg("text"))
      .def(
          "cor", [](const NormalTable& t, py::object g) { return map_values<double>(g, [&](double v) { return t.cor(v); }); },
          py::arg("velocity"), "eps^N at speed(s) g [m/s] (ValueError outside [g_min, g_max])")
      .def(
          "sticks",
          [](const NormalTable& t, py::object g) {
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

  py::class_<TangentialTable>(m, "TangentialTable",
                              "eps^T(g^N, g^T) of the asperity law (published form), to a stated error (docs/tables.md).")
      .def_static(
          "build",
          [](const Pair& pair, const models::ModelSpec& model, double gn_min, double gn_max, double gt_min,
             double gt_max, double bound) {
            TableOptions t;
            t.bound = bound;
            py::gil_scoped_release release;
            return build_tangential_table(pair, model, gn_min, gn_max, gt_min, gt_max, {}, t);
          },
          py::arg("pair"), py::arg("model"), py::arg("gn_min"), py::arg("gn_max"), py::arg("gt_min"), py::arg("gt_max"),
          py::arg("bound") = 1e-6)
      .def_static("from_json", &TangentialTable::from_json, py::arg("text"))
      .def(
          "cor",
          [](const TangentialTable& t, py::object gn, py::object gt) {
            return py::vectorize([&t](double n, double g) { return t.cor(n, g); })(gn, gt);
          },
          py::arg("velocity"), py::arg("tangential_velocity"),
          "eps^T at (g^N, g^T) [m/s], numpy broadcasting (ValueError outside the table's range)")
      .def(
          "breaks",
          [](const TangentialTable& t, py::object gn, py::object gt) {
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

  m.def(
      "apply_restitution",
      [](const Pair& pair, std::array<double, 3> normal, std::array<double, 3> v1, std::array<double, 3> w1,
         std::array<double, 3> v2, std::array<double, 3> w2, double cor, double cor_tangential) {
        return rule_dict(apply_restitution(pair, vec(normal), {vec(v1), vec(w1)}, {vec(v2), vec(w2)}, cor,
                                           cor_tangential));
      },
      py::arg("pair"), py::arg("normal"), py::arg("velocity1"), py::arg("angular_velocity1"), py::arg("velocity2"),
      py::arg("angular_velocity2"), py::arg("cor"), py::arg("cor_tangential") = 1.0,
      "Post-collision velocities and spins from given eps^N, eps^T (BSHP96 (42)-(43), corrected impulse).");
  m.def(
      "collide_grains",
      [](const Pair& pair, const models::ModelSpec& model, std::array<double, 3> normal, std::array<double, 3> v1,
         std::array<double, 3> w1, std::array<double, 3> v2, std::array<double, 3> w2) {
        return rule_dict(collide_grains(pair, model, vec(normal), {vec(v1), vec(w1)}, {vec(v2), vec(w2)}));
      },
      py::arg("pair"), py::arg("model"), py::arg("normal"), py::arg("velocity1"), py::arg("angular_velocity1"),
      py::arg("velocity2"), py::arg("angular_velocity2"),
      "Post-collision velocities and spins with eps^N, eps^T of the model at the encounter's g^N, g^T.");
}
