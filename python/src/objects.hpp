#pragma once
// The Python objects Pair and Model: what the user gave (by parameter name, for the front
// door) and, for a pair, the Pair it makes.

#include <string>

#include "bounce/api/front_door.hpp"
#include "convert.hpp"

namespace bounce::python {

struct PyPair {
  api::Inputs inputs;
  Pair pair;
};

struct PyModel {
  std::string name;
  api::Inputs inputs;
};

/// The pair's and the model's inputs with the model's keyword and the call's own keywords
/// (which may override a model's numerical setting, e.g. method="integrate").
api::Inputs case_inputs(const PyPair& pair, const PyModel& model, const py::kwargs& options = {});

/// The case (pair, model, integration options) of a collide call with these inputs.
api::Case make_case(const PyPair& pair, const PyModel& model, const py::kwargs& options = {});

/// An impact speed [m/s] checked against the declaration of collide's `velocity` (> 0 and
/// finite), for the calls that take speeds without a collision of their own (closed forms,
/// a table's range); the message names it `python_name`.
double check_speed(const char* python_name, double velocity);

// Registration of the module's parts (module.cpp calls them in order).
void bind_objects(py::module_& m);      // Pair, Model, materials, models
void bind_collisions(py::module_& m);   // collide, closed_forms, viscoelastic_scales, sticking
void bind_contact(py::module_& m);      // ContactLaw, contact_laws
void bind_analytic(py::module_& m);     // master_cor, cor_series, cor_pade
void bind_tables(py::module_& m);       // NormalTable, TangentialTable
void bind_atlas(py::module_& m);       // Atlas, open_atlas
void bind_aggregate(py::module_& m);    // build_aggregate
void bind_rules(py::module_& m);        // apply_restitution, collide_grains
void bind_fit(py::module_& m);          // fit
void bind_posterior(py::module_& m);    // Likelihood, _likelihood (bounce.posterior)

}  // namespace bounce::python
