#include "bounce/models/registry.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "bounce/contact/convex.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "catalogue.hpp"
#include "factories.hpp"

namespace bounce::models {

namespace {

using namespace catalogue;

// The end rules of the force laws, and of the adhesive models that end where they break.
Traits force_law(bool master_curve, Adhesion adhesion = Adhesion::negligible) {
  Traits t;
  t.master_curve = master_curve;
  t.convex = master_curve;
  t.adhesion = adhesion;
  t.closed_forms.jkr = true;
  t.end_rules_why = "overlap or force";
  t.docs = "viscoelastic.md";
  return t;
}
Traits adhesive(Adhesion adhesion, std::vector<EndRule> end_rules, std::string why) {
  Traits t;
  t.adhesive = true;
  t.adhesion = adhesion;
  t.end_rules = std::move(end_rules);
  t.end_rules_why = std::move(why);
  t.closed_forms.viscous = true;
  t.docs = "adhesive.md";
  return t;
}

Traits hertz_traits() {
  Traits t = force_law(true);
  t.stock_lammps = StockLammps::hertz_material;
  return t;
}
Traits viscoelastic_traits() {
  Traits t = force_law(true);
  t.closed_forms.viscous = true;
  t.analytic = true;
  t.stock_lammps = StockLammps::hertz_material;
  t.comparisons = {{5, "viscoelastic + plastic, no adhesion", "A,yield", std::nullopt}};
  return t;
}
Traits shifted_traits() {
  Traits t = force_law(false);
  t.convex = true;
  t.closed_forms.viscous = true;
  return t;
}
Traits adhesive_viscoelastic_traits() {
  Traits t = adhesive(Adhesion::weak, {EndRule::overlap},
                      "overlap (an adhesive contact ends where it breaks, not where the force first vanishes)");
  t.closed_forms.jkr = true;
  t.closed_forms.bp04_weak = true;
  t.comparisons = {{3, "BP04 quasi-static adhesion, viscous, plastic", "gamma,tvis,yield", std::nullopt}};
  return t;
}
Traits jkr_viscoelastic_traits() {
  Traits t = adhesive(Adhesion::jkr, {EndRule::overlap, EndRule::fold, EndRule::pull_off},
                      "overlap (the fold), fold or pull-off");
  t.closed_forms.jkr = true;
  t.stock_lammps = StockLammps::jkr;
  t.comparisons = {{2, "instantaneous JKR crack, bulk damping, plastic", "gamma,tvis,yield", std::nullopt},
                   {4, "elastic JKR + plastic (K13 Fig 6 dashed)", "gamma,yield", 0.0}};
  return t;
}
Traits krijt_traits() {
  Traits t = adhesive(Adhesion::jkr, {EndRule::overlap},
                      "overlap (an adhesive contact ends where it breaks, here where K13's crack law ends it)");
  t.closed_forms.jkr = true;
  t.comparisons = {{1, "K13: adhesion, viscous crack, bulk damping, plastic", "gamma,tvis,yield", std::nullopt}};
  return t;
}

// No pull-off end: toward DMT the least force lies at touching, inside the attraction's range,
// past the snap-on; a release there would hand the pair the zone's energy (e > 1).
Traits maugis_viscoelastic_traits() {
  return adhesive(Adhesion::maugis, {EndRule::overlap, EndRule::fold},
                  "overlap or fold (the Maugis jump-off; no pull-off: toward DMT the least force lies inside the "
                  "attraction's range)");
}

// The checked-in table: one row per model (keyword, summary, references, traits, own
// parameters and their rules, factory, what fit fits). To add a model, write src/models/<model>.cpp
// with its factory (declared in factories.hpp) and add its row here: the CLI, Python and
// docs/models.md take it from this table.
std::vector<ModelRow> builtin_rows() {
  return {
      model_row("hertz", "elastic spheres, no dissipation", "BP04 (8.24), BSHP96 (14)", hertz_traits(), no_fields(),
                &make_hertz, {"yield"}),
      model_row("viscoelastic", "Hertz plus the quasi-static viscous force (3/2) A rho sqrt(xi) xi'",
                "BP04 (8.42), BSHP96 (24)", viscoelastic_traits(), viscous_fields(),
                &make_viscoelastic, {"A"}),
      model_row("viscoelastic-shifted", "Hertz law at the shifted overlap xi + A xi', clamped at zero", "BSHP96 (25)",
                shifted_traits(), viscous_fields(),
                &make_viscoelastic_shifted, {"A"}),
      model_row("power-law", "F = m (D1 xi^alpha + D2 xi^gamma xi'^beta)", "BP04 (8.63)-(8.69)",
                force_law(false, Adhesion::unchecked), power_law_fields(),
                &make_power_law),
      model_row("adhesive-viscoelastic",
                "BP04's quasi-static adhesive force (8.56) with its dissipation (8.57), ending with the neck's work (8.97)",
                "BP04 (8.56)-(8.58), (8.94)-(8.98), docs/adhesive.md", adhesive_viscoelastic_traits(), adhesive_viscous_fields(),
                &make_adhesive_viscoelastic,
                {"gamma", "tvis", "yield"}),
      model_row("jkr-viscoelastic", "contact radius on the JKR equilibrium (instantaneous crack) plus the bulk force",
                "K13 (8), (9), (19), (20)", jkr_viscoelastic_traits(), contact_fields(),
                &make_jkr_viscoelastic,
                {"gamma", "tvis", "yield"}),
      model_row("krijt", "K13's dynamic contact: independent a and delta, viscoelastic crack, bulk damping",
                "K13 (2), (14)-(21), appendices B, C", krijt_traits(), crack_fields(),
                &make_krijt, {"gamma", "tvis", "yield"}),
      model_row("maugis-viscoelastic", "contact on the Maugis-Dugdale branch (any Tabor parameter) plus the bulk force",
                "Maugis 1992 (MD1)-(MD3), K13 (19), (20), docs/adhesive.md", maugis_viscoelastic_traits(),
                contact_fields(),
                &make_maugis_viscoelastic,
                {"gamma", "tvis", "yield"}),
  };
}

// Every model: the end rule, plastic losses, the tangential law, the method.
std::vector<ParameterSpec> every_model() {
  return {
      choice_parameter("contact_end", {"overlap", "force", "fold", "pull-off"},
                       "overlap | force | fold | pull-off: when the contact ends (default overlap; the rules each "
                       "model takes: bounce models)"),
      // K13 Fig 7 finds Y / E_soft from 1e-3 to the theoretical 0.2; at 1 no collision yields.
      fittable(real_parameter("yield", "yield strength Y", "Pa", positive(),
                              "yield strength Y [Pa] (<= the softer body's E): adds Thornton-Ning plastic losses, K13 (28)-(30)"),
               {1e-4, 1.0, 100, "E_soft"}),
      real_parameter("friction", "friction coefficient mu", "", non_negative(), "friction coefficient mu (BSHP96 (36))"),
      // At least 1e-20 m, far below any roughness (the property tests reach 5e-15 m: 1e-7 of a
      // 50 nm R_eff): 1e-300 m made the spring's stiffness mu F^N / zeta0 overflow (found trying
      // the LAMMPS plugin as a new user).
      real_parameter("asperity", "asperity size zeta0", "m", Range{1e-20, std::numeric_limits<double>::infinity(), true},
                     "asperity size zeta0 [m] (BSHP96 (32); asperity law)"),
      choice_parameter("tangential_law", {"asperity", "step"}, "asperity (BSHP96 (35), default) | step (BSHP96 (39))"),
      // passive by default since issue 40: a DEM or table user takes defaults, and the published
      // form's spring gains energy from its changing stiffness (|eps^T| up to 1.13, D12).
      choice_parameter("asperity_form", {"passive", "published"},
                       "passive (default: no energy from the changing stiffness) | published (BSHP96 (35) as "
                       "printed, for its figures: eps^T can leave [-1, 1])"),
      real_parameter("shear_damping", "shear damping gamma_s", "1/s", non_negative(),
                     "gamma_s [1/s] (BSHP96 (39); step law)"),
      choice_parameter("method", {"auto", "integrate", "master"}, "auto | integrate | master (default: master where valid)"),
  };
}

ParameterSpec tolerance(std::string name, double lo, double fallback, std::string help) {
  return with_default(real_parameter(std::move(name), "tolerance", "", open_interval(lo, 1e-3), std::move(help)), fallback);
}

// What the traits add: convex shapes, the engine's settings.
std::vector<ParameterSpec> by_traits(bool convex, Engine engine) {
  std::vector<ParameterSpec> out = every_model();
  if (convex) {
    const auto shape = contact::convex::shape_parameters();
    out.insert(out.end(), shape.begin(), shape.end());
  }
  if (engine != Engine::force_law) {
    out.push_back(tolerance("adhesive_tolerance", 1e-14, 1e-8,
                            "relative tolerance of the contact models' integration (krijt, jkr-viscoelastic, ...; "
                            "default 1e-8)"));
  } else {
    out.push_back(tolerance("tolerance", 1e-15, 1e-12,
                            "relative and absolute tolerance of direct integration (default 1e-12)"));
  }
  if (engine == Engine::crack) {
    out.push_back(choice_parameter("stiff_engine", {"rodas", "cvode"}, "krijt: rodas | cvode (default rodas; cvode cross-checks)"));
  }
  return out;
}

// The tangential law of the parameters (kappa of BSHP96 (8) from the pair's moments of
// inertia), when a friction coefficient or another of its parameters is given.
std::optional<TangentialModel> tangential_model(const Pair& pair, const Parameters& p) {
  const bool any = p.given("friction") || p.given("asperity") || p.given("shear_damping") ||
                   p.given("tangential_law") || p.given("asperity_form");
  if (!any) return std::nullopt;
  TangentialModel t;
  t.law = parse_tangential_law(p.text("tangential_law"));
  t.form = parse_asperity_form(p.text("asperity_form"));
  t.kappa = pair.tangential_mass_factor();
  t.friction = p.require_real("friction", "a friction coefficient mu >= 0 (BSHP96 (36))");
  if (t.law == TangentialLaw::asperity) {
    p.refuse_given(std::array{"shear_damping"}, "none with the asperity law (gamma_s is the step law's, BSHP96 (39))");
    t.asperity_size = p.require_real("asperity", "an asperity size zeta0 > 0 m (BSHP96 (32))");
  } else {
    p.refuse_given(std::array{"asperity", "asperity_form"},
                   "none with the step law (the asperity law's, BSHP96 (32)-(35))");
    t.shear_damping = p.require_real("shear_damping", "a shear damping gamma_s >= 0 1/s (BSHP96 (39))");
  }
  validate(t);
  return t;
}

// Y above the softer body's E is a yield strain above 1: no collision below c_t yields, and K13
// (29)'s yield velocity overflowed at Y = 1e300 Pa. K13 Fig 7 finds Y / E_soft from 1e-3 to 0.2;
// `bounce fit`'s grid ends at 1 (its end, exp(log E_soft), may round above E_soft: 1e-12 spare).
void require_yield_within_modulus(const Pair& pair, double yield) {
  const double soft = pair.soft_modulus();
  if (yield <= soft * (1.0 + 1e-12)) return;
  throw InvalidArgument("yield", format_value(yield),
                        fmt::format("a yield strength Y <= E_soft = {:g} Pa, the softer body's Young modulus (a yield "
                                    "strain above 1 describes no material; K13 Fig 7 finds Y / E_soft of 1e-3 to 0.2)",
                                    soft));
}

// The end rule given, if the model declares it (Traits::end_rules).
EndRule checked_end_rule(const ModelRow& row, const std::string& text) {
  const EndRule rule = parse_end_rule(text);
  const auto& rules = row.traits.end_rules;
  if (std::find(rules.begin(), rules.end(), rule) != rules.end()) return rule;
  throw InvalidArgument("contact_end", text, fmt::format("{} for model {}", row.traits.end_rules_why, row.name));
}

}  // namespace

const ModelRow& ModelRegistry::add(ModelRow row) {
  if (std::any_of(rows_.begin(), rows_.end(), [&](const ModelRow& r) { return r.name == row.name; })) {
    throw InvalidArgument("model", row.name, "a keyword no other model has");
  }
  if (row.traits.end_rules.empty() || row.traits.end_rules_why.empty()) {
    throw std::logic_error("model " + row.name + " declares no end rules");
  }
  for (ParameterSpec& s : by_traits(row.traits.convex, row.traits.engine)) row.parameters.push_back(std::move(s));
  for (std::size_t i = 0; i < row.parameters.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (row.parameters[i].name == row.parameters[j].name) {
        throw InvalidArgument("parameter", row.parameters[i].name, "declared once per model");
      }
    }
  }
  rows_.push_back(std::move(row));
  return rows_.back();
}

// BSHP96's and BP04's model, the one most users of a COR mean.
const char* ModelRegistry::default_name() { return "viscoelastic"; }

const ModelRow& ModelRegistry::at(std::string_view name) const { return find_named(rows_, name, "model"); }

std::vector<std::string> ModelRegistry::names() const {
  std::vector<std::string> out;
  for (const ModelRow& row : rows_) out.push_back(row.name);
  return out;
}

ModelRegistry& model_registry() {
  static ModelRegistry registry = [] {
    ModelRegistry r;
    for (ModelRow& row : builtin_rows()) r.add(std::move(row));
    return r;
  }();
  return registry;
}

Parameters bind_model_parameters(std::string_view name, const ParameterInputs& inputs) {
  const ModelRow& row = model_registry().at(name);
  return bind_parameters(row.parameters, inputs, fmt::format("model {}", row.name));
}

namespace {

// What every factory gets beside its model's own parameters: the end rule it declares and, for a
// model that takes convex bodies, their curvatures where given.
ModelContext context(const ModelRow& row, const Pair& pair, const Parameters& p) {
  ModelContext c;
  c.end_rule = checked_end_rule(row, p.text("contact_end"));
  if (row.traits.convex) c.shape = contact::convex::curvatures_from(p, pair.body2().is_wall());
  return c;
}

}  // namespace

Model make_model(const Pair& pair, std::string_view name, const Parameters& p) {
  const ModelRow& row = model_registry().at(name);
  for (const ParameterRule& rule : row.rules) rule.check(p, "model " + row.name);
  const ModelContext c = context(row, pair, p);
  Model m = row.factory(pair, p, c);
  const bool dem = std::visit([](const auto& kind) { return kind.dem != nullptr; }, m.normal);
  if (!dem) throw std::logic_error("model " + row.name + ": its factory made no DEM law");
  m.name = row.name;
  m.traits = row.traits;
  m.end_rule = c.end_rule;
  m.yield_strength = p.real("yield");
  if (m.yield_strength) require_yield_within_modulus(pair, *m.yield_strength);
  m.tangential = tangential_model(pair, p);
  return m;
}

DemModel make_dem_model(const Pair& pair, std::string_view name, const Parameters& p) {
  Model m = make_model(pair, name, p);
  DemModel out;
  out.name = m.name;
  out.end_rule = m.end_rule;
  out.tangential = m.tangential;
  std::visit(
      [&](const auto& kind) {
        if constexpr (std::is_same_v<std::decay_t<decltype(kind)>, CrackContact>) out.crack = kind.dem;
        else out.normal = kind.dem;
      },
      m.normal);
  return out;
}

Model make_model(const Pair& pair, std::string_view name, const ParameterInputs& inputs) {
  return make_model(pair, name, bind_model_parameters(name, inputs));
}

double dissipative_constant_from_viscosities(double eta1, double eta2, double e, double nu) {  // BP04 (8.38)
  const double difference = 3.0 * eta2 - eta1;
  return difference * difference / (3.0 * (3.0 * eta2 + 2.0 * eta1)) * (1.0 - nu * nu) *
         (1.0 - 2.0 * nu) / (e * nu * nu);
}

}  // namespace bounce::models
