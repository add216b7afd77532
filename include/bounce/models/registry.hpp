#pragma once
// The collision models by keyword: the single source of truth of what each model is,
// what it takes and how it is made (the CLI's options and --help, Python's keywords and
// type stubs and docs/models.md are generated from these rows).
//
// One keyword <-> one row <-> one factory, in the file of its physics (src/models/*.cpp:
// hertz with viscoelastic, jkr-viscoelastic with krijt). A row declares what the model is
// (Traits: end rules, adhesion checks, closed forms, ...; its engine is the kind its factory
// makes) and its own parameters, as the field table of its parameter struct with the rules
// between them (core/fields.hpp, model_parameters.hpp); the registry adds the parameters every
// model shares (contact_end, yield, the tangential law, method) and those its traits call for
// (curvature radii for convex bodies; tolerance for force laws; adhesive_tolerance for the
// contact engines, stiff_engine for the crack's). To add a model: write its file with a factory
// that turns its parameter struct into Made<Kind> (model.hpp: the collision law and the same law
// for DEM contacts), declare the factory in src/models/factories.hpp and add its row (model_row)
// to the table in src/models/registry.cpp (or, outside the library, model_registry().add(row)).

#include <deque>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "bounce/core/fields.hpp"
#include "bounce/core/parameters.hpp"
#include "bounce/models/model.hpp"
#include "bounce/models/model_parameters.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce::models {

/// Makes the model's physics for a pair from its bound parameters and the context (the shared
/// slots, end rule, yield and tangential law, are filled by make_model afterwards). model_row
/// makes one from a factory of the model's parameter struct.
using ModelFactory = std::function<Model(const Pair& pair, const Parameters& parameters, const ModelContext& context)>;

struct ModelRow {
  std::string name;        ///< the keyword (`--model NAME`, `bounce.Model(NAME)`)
  std::string summary;     ///< one line
  std::string references;  ///< equations it implements
  Traits traits;
  std::vector<ParameterSpec> parameters;  ///< the model's own, then (after add) the shared ones
  ModelFactory factory;
  /// What `bounce fit` fits by default (parameters with a fit grid: the model's, the shared
  /// yield, the pair's gamma); empty: the user names them.
  std::vector<std::string> fit = {};
  /// Its parameter table's rules between parameters, checked where the model is made.
  std::vector<ParameterRule> rules = {};
};

namespace detail {
template <class T>
struct MadeKind;
template <class Kind>
struct MadeKind<Made<Kind>> {
  using type = Kind;
};
}  // namespace detail

/// A row whose own parameters are the fields of `fields` (its specs and rules): `make(pair, S,
/// context)` returns Made<Kind>, the model's physics, whose Kind (ForceLaw, AdhesiveContact,
/// CrackContact) sets the row's engine. Its normal interaction carries the same law as a DEM
/// law: one factory serves collisions and DEM codes.
template <class S, class Make>
ModelRow model_row(std::string name, std::string summary, std::string references, Traits traits,
                   const FieldTable<S>& fields, Make make, std::vector<std::string> fit = {}) {
  using Result = std::invoke_result_t<Make, const Pair&, const S&, const ModelContext&>;
  using Kind = typename detail::MadeKind<Result>::type;
  traits.engine = engine_of<Kind>();
  ModelRow row{std::move(name), std::move(summary), std::move(references), std::move(traits), fields.specs(), {},
               std::move(fit), fields.rules()};
  row.factory = [fields, make](const Pair& pair, const Parameters& p, const ModelContext& c) {
    Made<Kind> made = make(pair, fields.read(p), c);
    Model m;
    static_cast<ModelPhysics&>(m) = made;
    m.normal = std::move(made.normal);
    return m;
  };
  return row;
}

class ModelRegistry {
 public:
  /// Adds a row and appends the shared parameters its capabilities call for;
  /// InvalidArgument if the keyword is taken or a parameter is declared twice.
  const ModelRow& add(ModelRow row);
  /// The row of `name`; InvalidArgument("model", name, "one of …") for an unknown keyword.
  const ModelRow& at(std::string_view name) const;
  const std::deque<ModelRow>& rows() const noexcept { return rows_; }
  std::vector<std::string> names() const;
  /// The model a command uses when none is named.
  static const char* default_name();
  /// The rows whose traits satisfy `pred`, by name, in the table's order.
  template <class Pred>
  std::vector<std::string> names_where(Pred pred) const {
    std::vector<std::string> out;
    for (const ModelRow& row : rows_) {
      if (pred(row)) out.push_back(row.name);
    }
    return out;
  }

 private:
  std::deque<ModelRow> rows_;  // a deque: rows stay where they are when one is added
};

/// The registry, holding the checked-in table from the first call on.
ModelRegistry& model_registry();

/// `inputs` checked against the parameters of model `name` (an input the model does not
/// take is an InvalidArgument naming it).
Parameters bind_model_parameters(std::string_view name, const ParameterInputs& inputs);

/// The model `name` for `pair`: its factory's physics plus the shared slots.
Model make_model(const Pair& pair, std::string_view name, const Parameters& parameters);
/// The same from unchecked inputs (binds them first).
Model make_model(const Pair& pair, std::string_view name, const ParameterInputs& inputs = {});

/// The model `name` as a DEM law for a pair of materials (the pair's radii and masses are
/// replaced per contact): the DEM form of its normal law (made by its one factory, every model
/// has one), its end rule and tangential law.
DemModel make_dem_model(const Pair& pair, std::string_view name, const Parameters& parameters);

/// The longest viscous time (A or T_vis) a model takes for the pair: 1e6 times its shortest
/// elastic contact time t_H(c_t), BSHP96 (A13) at the sound speed (docs/models.md, "Validity").
double longest_viscous_time(const Pair& pair);

/// BP04 (8.38): A = (1/3) (3 eta2 - eta1)^2 / (3 eta2 + 2 eta1) (1 - nu^2)(1 - 2 nu) / (E nu^2).
double dissipative_constant_from_viscosities(double shear_viscosity, double bulk_viscosity,
                                             double youngs_modulus, double poisson_ratio);

}  // namespace bounce::models
