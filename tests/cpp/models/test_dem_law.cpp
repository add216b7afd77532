// The models as DEM contact laws (models/dem_law.hpp, LAMMPS's pair_style bounce): the same
// physics as each model's force for the same pair, the JKR neck's end, BSHP96's tangential laws
// over a step, and pair_coeff's inputs checked by the CLI's rules.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "bounce/api/front_door.hpp"
#include "bounce/contact/jkr.hpp"
#include "bounce/core/error.hpp"
#include "bounce/models/registry.hpp"
#include "bounce/pair/materials_table.hpp"

using namespace bounce;

namespace {

Pair pair_of(const char* material, double r1, double r2) {
  const Material m = MaterialTable::builtin().at(material);
  return Pair(sphere(m, r1), sphere(m, r2));
}

models::DemModel law(const Pair& pair, const char* model, const ParameterInputs& inputs) {
  return models::make_dem_model(pair, model, models::bind_model_parameters(model, inputs));
}

std::string refusal(const api::Inputs& inputs) {
  try {
    (void)api::dem_model(inputs);
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace

// For the pair it was made for, each contact law gives the model's own force and potential:
// one formula, two callers. Bit for bit, since both evaluate the same expression.
TEST(DemLaw, EqualsTheModelsForceForItsPair) {
  struct Case {
    const char* model;
    const char* material;
    ParameterInputs inputs;
  };
  const Case cases[] = {
      {"hertz", "ice-bshp96", {}},
      {"viscoelastic", "ice-bshp96", {{"A", 1e-5}}},
      {"viscoelastic-shifted", "ice-bshp96", {{"A", 1e-5}}},
      {"power-law", "ice-bshp96", {{"power_d1", 1e9}, {"power_d2", 3e3}, {"power_beta", 0.7}}},
      {"adhesive-viscoelastic", "water-ice", {{"A", 1e-9}}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.model);
    const Pair pair = pair_of(c.material, 0.01, 0.004);  // unlike radii
    const models::Model model = models::make_model(pair, c.model, c.inputs);
    const models::DemModel dem = law(pair, c.model, c.inputs);
    const models::ContactGeometry g{pair.effective_radius(), pair.effective_mass()};
    for (double xi : {0.0, 1e-9, 3e-7, 2e-5}) {
      for (double rate : {-0.7, 0.0, 0.4}) {
        EXPECT_EQ(dem.normal->force(g, xi, rate), model.force_law()->force(xi, rate)) << xi << " " << rate;
      }
      EXPECT_EQ(dem.normal->energy(g, xi), model.force_law()->elastic_energy(xi)) << xi;
    }
    EXPECT_EQ(dem.normal->release_overlap(g), 0.0);
  }
}

// jkr-viscoelastic: K13 (2) + (19) on the JKR branch, held down to the fold or the pull-off point.
TEST(DemLaw, JkrViscoelasticFollowsTheJkrBranchAndEndsAtTheRule) {
  const Pair pair = pair_of("water-ice", 1e-6, 2e-6);
  const models::ContactGeometry g{pair.effective_radius(), pair.effective_mass()};
  const contact::jkr::Parameters j{pair.effective_radius(), pair.effective_modulus(), pair.surface_energy().value()};
  const models::DemModel fold = law(pair, "jkr-viscoelastic", {{"tvis", 1e-11}});
  const models::DemModel pull = law(pair, "jkr-viscoelastic", {{"tvis", 1e-11}, {"contact_end", std::string("pull-off")}});
  EXPECT_EQ(fold.normal->release_overlap(g), contact::jkr::separation_overlap(j));
  EXPECT_EQ(pull.normal->release_overlap(g), contact::jkr::overlap(j, contact::jkr::pull_off_contact_radius(j)));
  EXPECT_GT(pull.normal->release_overlap(g), fold.normal->release_overlap(g));  // pull-off comes first
  // With no rate, the force is JKR's (9) at a(delta): at the pull-off point it is -(3/2) pi w R.
  const double delta_p = pull.normal->release_overlap(g);
  EXPECT_NEAR(pull.normal->force(g, delta_p, 0.0), contact::jkr::pull_off_force(j), 1e-9 * std::abs(contact::jkr::pull_off_force(j)));
  for (double delta : {-1e-9, 0.0, 1e-9, 1e-8}) {
    const double a = contact::jkr::contact_radius_from_overlap(j, delta);
    EXPECT_NEAR(fold.normal->force(g, delta, 0.0), contact::jkr::force(j, a), 1e-9 * std::abs(contact::jkr::force(j, a)))
        << delta;
  }
  // The bulk force (19): 2 A E* a delta', with A = T_vis / nu^2 (K13 after (18)).
  const double delta = 5e-9, rate = -0.3;
  const double a = contact::jkr::contact_radius_from_overlap(j, delta);
  const double a_const = 1e-11 / (0.25 * 0.25);
  EXPECT_NEAR(fold.normal->force(g, delta, rate) - fold.normal->force(g, delta, 0.0),
              2.0 * a_const * pair.effective_modulus() * a * rate, 1e-9 * std::abs(2.0 * a_const * pair.effective_modulus() * a * rate));
}

// contact::jkr::DisplacementBranch (the engine's and the DEM's fast inverse of K13 (8)) agrees
// with the bracketing solver to round-off, on both sides of delta = 0 and at the fold.
TEST(DemLaw, FastJkrBranchAgreesWithTheBracketingSolver) {
  const contact::jkr::Parameters j{5e-7, 3.9e9, 0.74};
  const contact::jkr::DisplacementBranch branch(j);
  const double delta_c = contact::jkr::separation_overlap(j);
  for (double f : {0.999999, 0.9, 0.5, 0.0, -1.0, -10.0, -1e3}) {
    const double delta = f * delta_c;
    EXPECT_NEAR(branch.radius(delta), contact::jkr::contact_radius_from_overlap(j, delta),
                1e-12 * contact::jkr::contact_radius_from_overlap(j, delta))
        << delta;
  }
}

// BSHP96 (35)-(36) over DEM steps: the force never exceeds mu F^N; the spring's extension
// restarts at each break; the passive form keeps the stored energy when k changes.
TEST(DemLaw, AsperityLawOverSteps) {
  models::TangentialModel t;
  t.form = models::AsperityForm::published;
  t.friction = 0.3;
  t.asperity_size = 1e-6;
  double h[3] = {0.0, 0.0, 0.0}, f[3];
  const double sliding[3] = {0.0, 0.01, 0.0}, dt = 1e-5;  // 1e-7 m per step
  for (int step = 1; step <= 25; ++step) {
    models::tangential_step(t, 2.0, 2.0, 1.0, sliding, dt, true, h, f);
    EXPECT_LE(std::abs(f[1]), t.friction * 2.0 * (1.0 + 1e-12));
    const double extension = std::fmod(step * 1e-7, 1e-6);  // breaks every 10 steps
    EXPECT_NEAR(h[1], extension < 1e-13 || 1e-6 - extension < 1e-13 ? 0.0 : extension, 1e-12) << step;
    EXPECT_NEAR(f[1], -t.friction * 2.0 / t.asperity_size * h[1], 1e-12);
  }
  // Published: the extension stays when F^N doubles, so the force doubles; passive: the energy
  // |F|^2 / (2k) stays, so the force grows by sqrt(2) only.
  const double none[3] = {0.0, 0.0, 0.0};
  double pub[3] = {0.0, 5e-7, 0.0}, fp[3];
  models::tangential_step(t, 4.0, 4.0, 1.0, none, dt, true, pub, fp);
  EXPECT_NEAR(fp[1], -0.3 * 4.0 * 0.5, 1e-12);
  t.form = models::AsperityForm::passive;
  double passive[3] = {0.0, 0.0, 0.0}, fq[3];
  const double push[3] = {0.0, 0.05, 0.0};
  models::tangential_step(t, 2.0, 2.0, 1.0, push, dt, true, passive, fq);  // extension 5e-7 at k = 6e5
  EXPECT_NEAR(fq[1], -0.3, 1e-12);
  models::tangential_step(t, 4.0, 4.0, 1.0, none, dt, true, passive, fq);
  EXPECT_NEAR(fq[1], -0.3 * std::sqrt(2.0), 1e-12);
  models::tangential_step(t, -1.0, -1.0, 1.0, push, dt, true, passive, fq);  // attractive: no shear
  EXPECT_EQ(fq[1], 0.0);
  // Setup (update = false) leaves the history alone.
  double kept[3] = {1e-7, 2e-7, 0.0};
  models::tangential_step(t, 2.0, 2.0, 1.0, push, dt, false, kept, fq);
  EXPECT_EQ(kept[0], 1e-7);
  EXPECT_EQ(kept[1], 2e-7);
}

// BSHP96 (39): the step law, Coulomb-limited viscous sliding.
TEST(DemLaw, StepLaw) {
  models::TangentialModel t;
  t.law = models::TangentialLaw::step;
  t.friction = 0.5;
  t.shear_damping = 100.0;
  double h[3] = {0.0, 0.0, 0.0}, f[3];
  const double slow[3] = {0.003, 0.004, 0.0};  // |v| = 0.005: viscous, 100 * 2 * 0.005 = 1 N
  models::tangential_step(t, 10.0, 10.0, 2.0, slow, 1e-6, true, h, f);
  EXPECT_NEAR(f[0], -0.6, 1e-12);
  EXPECT_NEAR(f[1], -0.8, 1e-12);
  const double fast[3] = {3.0, 4.0, 0.0};  // Coulomb: mu F^N = 5 N
  models::tangential_step(t, 10.0, 10.0, 2.0, fast, 1e-6, true, h, f);
  EXPECT_NEAR(std::hypot(f[0], f[1]), 5.0, 1e-12);
}

// pair_coeff's inputs: the CLI's names and rules; what LAMMPS supplies or never uses is refused
// with the reason.
TEST(DemLaw, PairCoeffInputsAreCheckedByTheClisRules) {
  const models::DemModel ok = api::dem_model({{"model", std::string("viscoelastic")},
                                                {"material", std::string("ice-bshp96")},
                                                {"A", std::string("1e-5")},
                                                {"friction", std::string("0.3")},
                                                {"asperity", std::string("1e-6")}});
  EXPECT_EQ(ok.name, "viscoelastic");
  ASSERT_TRUE(ok.tangential.has_value());
  EXPECT_EQ(ok.tangential->friction, 0.3);
  // Both bodies' materials by value, and unlike ones by name.
  EXPECT_EQ(refusal({{"model", std::string("hertz")}, {"E", std::string("1e9")}, {"nu", std::string("0.3")},
                     {"E2", std::string("7e10")}, {"nu2", std::string("0.2")}}),
            "(accepted)");
  EXPECT_EQ(refusal({{"model", std::string("hertz")}, {"material", std::string("steel")},
                     {"material2", std::string("quartz")}}),
            "(accepted)");

  const auto base = [](api::Inputs extra) {
    api::Inputs in{{"model", std::string("viscoelastic")}, {"material", std::string("ice-bshp96")},
                   {"A", std::string("1e-5")}};
    for (auto& [k, v] : extra) in[k] = v;
    return in;
  };
  EXPECT_NE(refusal(base({{"radius", std::string("0.01")}})).find("atom_style sphere"), std::string::npos);
  EXPECT_NE(refusal(base({{"density", std::string("900")}})).find("atom_style sphere"), std::string::npos);
  EXPECT_NE(refusal(base({{"yield", std::string("1e7")}})).find("after a collision"), std::string::npos);
  EXPECT_NE(refusal(base({{"tolerance", std::string("1e-9")}})).find("time step"), std::string::npos);
  EXPECT_NE(refusal(base({{"A", std::string("-1")}})).find("A = -1 is invalid"), std::string::npos);
  EXPECT_NE(refusal(base({{"contact_end", std::string("pull-off")}})).find("overlap or force"), std::string::npos);
  EXPECT_NE(refusal(base({{"k", std::string("0.1")}})).find("krijt"), std::string::npos);  // the model that takes it
  EXPECT_NE(refusal(base({{"bogus", std::string("1")}})).find("bogus"), std::string::npos);
  // krijt: a crack law with its own contact radius, between atoms only.
  const api::Inputs krijt{{"model", std::string("krijt")}, {"material", std::string("water-ice")},
                          {"tvis", std::string("1e-11")}};
  const models::DemModel k13 = api::dem_model(krijt);
  EXPECT_TRUE(k13.crack && !k13.normal);
  EXPECT_NE(refusal({{"model", std::string("krijt")}, {"material", std::string("water-ice")}}).find("tvis"),
            std::string::npos);
  EXPECT_NE(refusal({{"model", std::string("krijt")}, {"material", std::string("water-ice")},
                     {"tvis", std::string("1e-11")}, {"k", std::string("1.5")}})
                .find("k = 1.5 is invalid"),
            std::string::npos);
  EXPECT_NE(refusal({{"model", std::string("krijt")}, {"material", std::string("water-ice")},
                     {"tvis", std::string("1e-11")}, {"z0", std::string("-2e-10")}})
                .find("z0 = -2e-10 is invalid"),
            std::string::npos);
  try {
    api::wall_dem_model(krijt);
    ADD_FAILURE() << "krijt against a wall was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("krijt acts between atoms only"), std::string::npos) << e.what();
  }
  EXPECT_NE(refusal({{"model", std::string("nonsense")}, {"material", std::string("water-ice")}}).find("nonsense"),
            std::string::npos);
  EXPECT_NE(refusal({{"model", std::string("jkr-viscoelastic")}, {"material", std::string("ice-bshp96")},
                     {"tvis", std::string("1e-11")}})
                .find("gamma"),
            std::string::npos);  // no surface energy in that material
}
