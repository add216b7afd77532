// The post-collision rules: given coefficients, or the model's at the encounter.
#include <array>

#include <pybind11/stl.h>

#include "bounce/analysis/rules.hpp"
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

py::dict apply_restitution(const PyPair& pair, Vector normal, Vector v1, Vector w1, Vector v2, Vector w2, double cor,
                           double cor_tangential) {
  return rule_dict(analysis::apply_restitution(pair.pair, normal, GrainMotion{v1, w1}, GrainMotion{v2, w2}, cor,
                                               cor_tangential));
}

py::dict collide_grains(const PyPair& pair, const PyModel& model, Vector normal, Vector v1, Vector w1, Vector v2,
                        Vector w2) {
  const api::Case c = make_case(pair, model);
  return rule_dict(analysis::collide_grains(c.pair, c.model, normal, GrainMotion{v1, w1}, GrainMotion{v2, w2}, c.options));
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
