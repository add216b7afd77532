// The post-collision rules: given coefficients, or the model's at the encounter.
#include <array>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bounce/analysis/rules.hpp"
#include "bounce/core/error.hpp"
#include "objects.hpp"

namespace bounce::python {

namespace {

using analysis::GrainMotion;
using Vector = std::array<double, 3>;

py::dict rule_dict(const analysis::CollisionRuleResult& r) {
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

// A vector of three numbers (list, tuple or array); TypeError naming it otherwise.
Vector to_vector(const char* name, const py::handle& x) {
  if (is_number(x)) refuse_type(name, x, "a list of 3 numbers");
  const Array a = to_array(name, x);
  if (a.ndim() != 1 || a.size() != 3) refuse_type(name, x, "a list of 3 numbers");
  return {a.data()[0], a.data()[1], a.data()[2]};
}

// The library names the grains' vectors grain1.velocity, ...: Python's arguments are velocity1, ...
template <class F>
py::dict named_as_python(F f) {
  try {
    return rule_dict(f());
  } catch (const InvalidArgument& e) {
    for (const char* grain : {"1", "2"}) {
      for (const char* what : {"velocity", "angular_velocity"}) {
        if (e.parameter() == fmt::format("grain{}.{}", grain, what)) throw e.renamed(fmt::format("{}{}", what, grain));
      }
    }
    throw;
  }
}

py::dict apply_restitution(const PyPair& pair, const py::object& normal, const py::object& v1, const py::object& w1,
                           const py::object& v2, const py::object& w2, const py::object& cor,
                           const py::object& cor_tangential) {
  const Vector n = to_vector("normal", normal);
  const GrainMotion g1{to_vector("velocity1", v1), to_vector("angular_velocity1", w1)};
  const GrainMotion g2{to_vector("velocity2", v2), to_vector("angular_velocity2", w2)};
  const double e = to_number("cor", cor), e_t = to_number("cor_tangential", cor_tangential);
  return named_as_python([&] { return analysis::apply_restitution(pair.pair, n, g1, g2, e, e_t); });
}

py::dict collide_grains(const PyPair& pair, const PyModel& model, const py::object& normal, const py::object& v1,
                        const py::object& w1, const py::object& v2, const py::object& w2) {
  const Vector n = to_vector("normal", normal);
  const GrainMotion g1{to_vector("velocity1", v1), to_vector("angular_velocity1", w1)};
  const GrainMotion g2{to_vector("velocity2", v2), to_vector("angular_velocity2", w2)};
  const api::Case c = make_case(pair, model);
  return named_as_python([&] {
    py::gil_scoped_release release;
    return analysis::collide_grains(c.pair, c.model, n, g1, g2, c.options);
  });
}

}  // namespace

void bind_rules(py::module_& m) {
  m.def("apply_restitution", &apply_restitution, py::arg("pair"), py::arg("normal"), py::arg("velocity1"),
        py::arg("angular_velocity1"), py::arg("velocity2"), py::arg("angular_velocity2"), py::arg("cor"),
        py::arg("cor_tangential") = 1.0,
        "Post-collision velocities and spins from given eps^N, eps^T (BSHP96 (42)-(43), corrected impulse).");
  m.def("collide_grains", &collide_grains, py::arg("pair"), py::arg("model"), py::arg("normal"), py::arg("velocity1"),
        py::arg("angular_velocity1"), py::arg("velocity2"), py::arg("angular_velocity2"),
        "Post-collision velocities and spins with eps^N, eps^T of the model at the encounter's g^N, g^T.");
}

}  // namespace bounce::python
