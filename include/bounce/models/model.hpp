#pragma once
// A collision model: what it declares about itself (Traits, one per registry row) and what it is
// once configured for a pair (Model: its normal interaction as one of three typed kinds, plus the
// slots every model has). Physics only: no engine, no output format.
//
// The three kinds of normal interaction, each with its own engine (dynamics/):
//   ForceLaw         a force F(xi, xi') (normal_force.hpp): dopri5 with event location, or the
//                    master curves where the model declares them
//   AdhesiveContact  a contact held on an adhesive equilibrium branch (adhesive_geometry.hpp: JKR,
//                    Maugis-Dugdale) with the bulk damping of K13 (19): dopri5
//   CrackContact     K13's contact whose radius moves by its crack law (krijt.hpp): the stiff engine
// A model's factory makes one of them (its type is the model's engine) and, in it, the same law
// as a DEM law (dem_law.hpp) whose radii and masses are given per contact: two shapes of one
// law, because a collision's is bound to one pair (its engines ask for a reference overlap,
// the sign of the force for event location, master-curve scaling) while a DEM has grains of
// many sizes per pair of materials. Both evaluate the same formula, written once.

#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "bounce/models/adhesive_geometry.hpp"
#include "bounce/models/adhesive_pair.hpp"
#include "bounce/models/dem_law.hpp"
#include "bounce/models/end_rule.hpp"
#include "bounce/models/krijt.hpp"
#include "bounce/models/normal_force.hpp"
#include "bounce/models/tangential.hpp"

namespace bounce::models {

/// How a model's collision is integrated: the kind of its normal interaction (engine_of), which
/// a registry row reads from its factory's type (model_row), not from a declaration.
enum class Engine {
  force_law,  ///< ForceLaw
  adhesive,   ///< AdhesiveContact
  crack,      ///< CrackContact
};

/// What a model assumes about adhesion: which validity checks its collisions carry.
enum class Adhesion {
  unchecked,   ///< no Hertz geometry to compare with (power-law)
  negligible,  ///< left out; BP04 (8.99) says when that holds
  weak,        ///< BP04's quasi-static estimate, (8.56)-(8.58) with (8.95)-(8.101)
  jkr,         ///< JKR's contact (K13): the Tabor parameter must be > 5 (K13 §2.1.2)
  maugis,      ///< Maugis-Dugdale's contact: any Tabor parameter
};

/// The closed forms shown beside a model's collision (analysis::closed_forms; yield's and the
/// Hertz time are every model's).
struct ClosedFormSet {
  bool jkr = false;        ///< with a gamma: K13 (24), (25), JKR's sticking velocity, the Tabor parameter
  bool viscous = false;    ///< with the model's A: K13 (26), (27)
  bool bp04_weak = false;  ///< BP04 (8.95), (8.98)
};

/// How `bounce lammps` writes the model as stock pair_style granular.
enum class StockLammps {
  none,            ///< it cannot
  hertz_material,  ///< hertz/material with damping viscoelastic
  jkr,             ///< jkr with damping viscoelastic
};

/// A line of K13 Fig 6's comparison of mechanisms (`bounce fit --compare`): this model, fitting
/// `fit`, with A held at `dissipative_constant` where given; lines are listed by `rank`.
struct Comparison {
  int rank = 0;
  std::string label;
  std::string fit;
  std::optional<double> dissipative_constant;
};

/// What a model declares about itself (its registry row's): the analysis, the front door and the
/// front ends read it, and nothing infers it from anything else.
struct Traits {
  Engine engine = Engine::force_law;  ///< set by model_row from the factory's kind
  /// The contact_end rules it takes; the first is the default.
  std::vector<EndRule> end_rules = {EndRule::overlap, EndRule::force};
  /// Why the other rules are not taken (the end of a refusal's "expected ...").
  std::string end_rules_why;
  Adhesion adhesion = Adhesion::negligible;
  ClosedFormSet closed_forms;
  bool adhesive = false;      ///< needs gamma; the outcome can be "stick"
  bool master_curve = false;  ///< BP04's master curves e(kappa) apply (method master)
  bool convex = false;        ///< general convex bodies (curvature radii) change its force constant
  bool analytic = false;      ///< BP04 §8.3's closed forms (`bounce analytic`) are derived for it
  StockLammps stock_lammps = StockLammps::none;
  std::vector<Comparison> comparisons;
  std::string docs;           ///< the docs page of its physics (docs/<page>)
};

/// The constants of BP04's dimensional analysis for a Hertz-type force (§8.3): kappa (8.70),
/// g* (8.88), xi0 (8.65) and the master curves follow from them.
struct HertzScaling {
  double force_constant = 0.0;        ///< C0 [N/m^{3/2}] (rho for spheres, BP04 (8.21) for convex bodies)
  double dissipative_constant = 0.0;  ///< A [s]
};

/// The normal interaction of each kind: what its collision engine integrates for the pair, and
/// `dem`, the same law for a DEM contact (every model has one).
struct ForceLaw {
  std::shared_ptr<const NormalForceModel> force;
  std::shared_ptr<const DemLaw> dem;
};
struct AdhesiveContact {
  AdhesivePair parameters;  ///< the pair (R, E*, m*, gamma), the bulk damping A of K13 (19), z0
  std::shared_ptr<const AdhesiveGeometry> geometry;
  std::shared_ptr<const DemLaw> dem;
};
struct CrackContact {
  KrijtParameters parameters;
  std::shared_ptr<const DemCrackLaw> dem;
};
using NormalInteraction = std::variant<ForceLaw, AdhesiveContact, CrackContact>;
/// The engine a normal interaction is integrated by.
Engine engine_of(const NormalInteraction& normal);
template <class Kind>
constexpr Engine engine_of() {
  if constexpr (std::is_same_v<Kind, ForceLaw>) return Engine::force_law;
  else if constexpr (std::is_same_v<Kind, AdhesiveContact>) return Engine::adhesive;
  else {
    static_assert(std::is_same_v<Kind, CrackContact>, "a kind of NormalInteraction");
    return Engine::crack;
  }
}

/// What the analysis reads of a model beside its normal interaction (its factory sets it).
struct ModelPhysics {
  std::optional<HertzScaling> hertz;           ///< Hertz-type forces: kappa, g*, master curves
  std::optional<double> dissipative_constant;  ///< A [s], where the model has one
  /// A is T_vis / nu^2 (K13 after (18)), not given: the bulk damping then scales with T_vis too.
  bool dissipative_constant_from_tvis = false;
  double viscous_time = 0.0;   ///< viscous relaxation time, for BSHP96 (B12) / BP04 (8.26)
  double z0 = 0.2e-9;          ///< equilibrium separation [m] of the Tabor parameter K13 (11)
};

/// What a model's factory makes: its normal interaction, of the kind that is its engine, and
/// the rest of its physics.
template <class Kind>
struct Made : ModelPhysics {
  Kind normal;
};

struct Model : ModelPhysics {
  std::string name;  ///< the registry keyword
  Traits traits;     ///< as the row declares them

  NormalInteraction normal;

  // The slots every model has (the registry fills them from the shared parameters).
  EndRule end_rule = EndRule::overlap;
  std::optional<double> yield_strength;  ///< Y [Pa]: Thornton-Ning losses, K13 (28)-(30)
  std::optional<TangentialModel> tangential;  ///< with a friction coefficient: oblique collisions

  /// The force law (ForceLaw models), else nullptr.
  const NormalForceModel* force_law() const;
  /// The adhesive pair of a contact model (AdhesiveContact, CrackContact), else nullptr.
  const AdhesivePair* contact_parameters() const;
  /// K13's parameters of a crack model (CrackContact), else nullptr.
  const KrijtParameters* crack_parameters() const;
};

}  // namespace bounce::models
