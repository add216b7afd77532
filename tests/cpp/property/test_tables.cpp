// Restitution tables (docs/tables.md) against direct collisions at random speeds: a table
// answers within its stated bound wherever it is asked inside its range.
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "bounce/analysis/collide.hpp"
#include "bounce/analysis/tables.hpp"
#include "bounce/models/registry.hpp"
#include "bounce/pair/materials_table.hpp"
#include "property/checks.hpp"
#include "property/generators.hpp"

using namespace bounce;
using namespace bounce::property;

namespace {

// The speeds a property asks a table for: log-uniform inside [g_min, g_max].
constexpr int lookups_per_table = 4;

std::vector<std::string> non_adhesive_force_laws() {
  std::vector<std::string> out;
  for (const models::ModelRow& row : models::model_registry().rows()) {
    if (!row.traits.adhesive && row.traits.engine == models::Engine::force_law) out.push_back(row.name);
  }
  return out;
}

// A table built once and the pair and model it was built for (the adhesive and tangential
// tables take 0.1-0.3 s to build: a few are built once and asked 500 times).
struct NormalCase {
  Pair pair;
  ModelCase model;
  analysis::NormalTable table;
};
struct TangentialCase {
  Pair pair;
  ModelCase model;
  analysis::TangentialTable table;
};

Pair material_pair(const char* name1, double r1, const char* name2, double r2) {
  const MaterialTable& t = MaterialTable::builtin();
  return Pair(sphere(t.at(name1), r1), sphere(t.at(name2), r2));
}

// Adhesive eps^N tables: K13's 1 um water-ice grains (krijt, T_vis = 1e-11 s, sticking
// below 4.2 m/s; docs/tables.md), an unlike micron pair (quartz on silicon) with BP04's
// estimate (sticking below ~0.1 m/s), and the water-ice grains with an instantaneous crack.
const std::vector<NormalCase>& adhesive_tables() {
  static const std::vector<NormalCase> tables = [] {
    std::vector<NormalCase> out;
    auto add = [&](Pair pair, ModelCase c, double lo, double hi) {
      const ModelAndOptions m = make(pair, c);
      analysis::NormalTable t = analysis::build_normal_table(pair, m.model, lo, hi, m.options);
      out.push_back({std::move(pair), std::move(c), std::move(t)});
    };
    add(material_pair("water-ice", 1e-6, "water-ice", 1e-6), {"krijt", {{"tvis", 1e-11}}}, 0.1, 20.0);
    add(material_pair("quartz", 2e-6, "silicon", 5e-6), {"adhesive-viscoelastic", {{"A", 1e-10}}}, 1e-3, 1.0);
    // jkr-viscoelastic above its sticking velocity (2.213 m/s) only: a range that holds v_s
    // takes 40 s to build (~1e4 nodes within 1e-8 m/s above v_s), more than this whole file.
    add(material_pair("water-ice", 1e-6, "water-ice", 1e-6), {"jkr-viscoelastic", {{"tvis", 1e-11}}}, 2.5, 20.0);
    return out;
  }();
  return tables;
}

// eps^T tables of the asperity law (BSHP96 (35), published form) for the three non-adhesive
// normal models a table takes: BSHP96 fig. 2's ice grains (A = 1 us, mu = sqrt(zeta0/R_eff),
// zeta0 = 2e-4 and 1e-3 R_eff) and an unlike steel-on-glass pair with Hertz contact.
const std::vector<TangentialCase>& tangential_tables() {
  static const std::vector<TangentialCase> tables = [] {
    std::vector<TangentialCase> out;
    auto add = [&](Pair pair, ModelCase c, double gn_lo, double gn_hi, double gt_lo, double gt_hi) {
      const ModelAndOptions m = make(pair, c);
      analysis::TangentialTable t =
          analysis::build_tangential_table(pair, m.model, gn_lo, gn_hi, gt_lo, gt_hi, m.options);
      out.push_back({std::move(pair), std::move(c), std::move(t)});
    };
    const Pair ice = material_pair("ice-bshp96", 0.01, "ice-bshp96", 0.01);
    const double r = ice.effective_radius();
    const ParameterInputs::value_type published{"asperity_form", "published"};  // the tabulated form
    add(ice, {"viscoelastic", {{"A", 1e-6}, {"asperity", 2e-4 * r}, {"friction", std::sqrt(2e-4)}, published}}, 0.01,
        10.0, 1e-3, 1.0);
    add(ice, {"viscoelastic-shifted", {{"A", 1e-6}, {"asperity", 1e-3 * r}, {"friction", std::sqrt(1e-3)}, published}},
        0.01, 10.0, 1e-3, 1.0);
    const Pair steel_glass = material_pair("steel", 1e-3, "ag-coated-glass", 3e-3);
    add(steel_glass, {"hertz", {{"asperity", 1e-7}, {"friction", 0.3}, published}}, 0.01, 1.0, 1e-3, 0.3);
    return out;
  }();
  return tables;
}

void check_normal_lookup(const analysis::NormalTable& t, const Pair& pair, const ModelCase& c, double g) {
  log_case(pair, g, c);
  const auto direct = collide(pair, c, g);
  RC_ASSERT(t.outcome(g) == direct.outcome);
  require_near(t.cor(g), direct.cor, t.bound, "table e^N vs direct at g = " + full(g));
}

}  // namespace

// docs/tables.md: an eps^N table (piecewise cubic Hermite in ln g, refined until the cubic
// misses the direct value at every interval's midpoint by less than bound/4) answers within
// its stated bound (1e-6, TableOptions) at any speed of its range, and with the direct
// outcome. Built per case for a random unlike pair, a non-adhesive force-law model of the
// registry (drawn from its rows; a table of the power law, integrated, costs ~50 ms, so not
// all of them every case) with its parameters valid over the range, and a range of 0.5 to 6
// decades of valid speeds; asked at random speeds inside.
RC_GTEST_PROP(Tables, NormalTableWithinBoundAtRandomSpeeds, ()) {
  const Pair pair = *sphere_pair();
  const double hi = max_valid_speed(pair);
  const double lo = hi * *log_uniform(1e-6, std::pow(10.0, -0.5));
  const std::string name = *rc::gen::elementOf(non_adhesive_force_laws());
  const auto parameters = model_parameters(name, pair, lo, hi);
  if (!parameters) RC_FAIL("no parameter generator for registry model '" + name + "'");
  const ModelCase c = *(*parameters);
  log_case(pair, hi, c);
  const ModelAndOptions m = make(pair, c);
  const analysis::NormalTable t = analysis::build_normal_table(pair, m.model, lo, hi, m.options);
  for (int i = 0; i < lookups_per_table; ++i) check_normal_lookup(t, pair, c, *log_uniform(lo, hi));
}

// The same for adhesive models, whose tables hold a sticking velocity v_s (e^N = 0 below,
// ~sqrt(g - v_s) above, tabulated in ln(g - v_s)): within the bound and with the direct
// outcome at random speeds. Speeds within the sticking search's bracket (1e-13 relative) of
// v_s may legitimately differ in outcome (docs/tables.md); a random speed falls there with
// probability ~1e-13.
RC_GTEST_PROP(Tables, AdhesiveNormalTableWithinBoundAtRandomSpeeds, ()) {
  const auto& tables = adhesive_tables();
  const NormalCase& c = tables[*rc::gen::inRange<std::size_t>(0, tables.size())];
  check_normal_lookup(c.table, c.pair, c.model, *log_uniform(c.table.g_min, c.table.g_max));
}

// docs/tables.md, "Tables of eps^T(g^N, g^T)": the table's replay of the asperity breaks on
// the interpolated fundamental solutions gives eps^T within its stated bound (1e-6) of the
// direct integration (BSHP96 (10) with (35)) at random points of its rectangle. (Next to a
// jump curve of eps^T the two can put the jump on different sides of a point; those bands
// are far narrower than the chance of a random point hitting them, docs/tables.md.)
RC_GTEST_PROP(Tables, TangentialTableWithinBoundAtRandomPoints, ()) {
  const auto& tables = tangential_tables();
  const TangentialCase& c = tables[*rc::gen::inRange<std::size_t>(0, tables.size())];
  const analysis::TangentialTable& t = c.table;
  const double gn = *log_uniform(t.gn_min, t.gn_max);
  const double gt = *log_uniform(t.gt_min, t.gt_max);
  log_case(c.pair, gn, c.model);
  RC_LOG() << "g^T = " << full(gt) << " m/s\n";
  ModelAndOptions m = make(c.pair, c.model);
  m.options.tangential_velocity = gt;
  const auto direct = analysis::collide(c.pair, m.model, gn, m.options);
  RC_ASSERT(direct.tangential.has_value());
  require_near(t.cor(gn, gt), direct.tangential->cor, t.bound, "table e^T vs direct");
}
