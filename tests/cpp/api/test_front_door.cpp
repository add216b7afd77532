// The front door (api/front_door.hpp) and the model registry behind it: a model added as
// one row works through the front door with no other edit; every input a model or a
// command does not take is refused, naming it.
#include <cmath>
#include <memory>
#include <numbers>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "bounce/api/front_door.hpp"
#include "bounce/contact/hertz.hpp"
#include "bounce/core/error.hpp"
#include "bounce/core/fields.hpp"
#include "bounce/models/registry.hpp"

using namespace bounce;

namespace {

// A toy normal force for the test only: the linear spring-dashpot F = k xi + c xi'
// (Cundall & Strack's normal law), whose COR under the overlap end rule is exact:
// e = exp(-pi zeta / sqrt(1 - zeta^2)), zeta = c / (2 sqrt(k m)).
class LinearSpring final : public models::NormalForceModel {
 public:
  LinearSpring(double k, double c, double m, double r) : k_(k), c_(c), m_(m), r_(r) {}
  std::string_view name() const override { return "test-linear-spring"; }
  double force(double xi, double rate) const override { return xi <= 0.0 ? 0.0 : k_ * xi + c_ * rate; }
  double elastic_force(double xi) const override { return xi <= 0.0 ? 0.0 : k_ * xi; }
  double elastic_energy(double xi) const override { return xi <= 0.0 ? 0.0 : 0.5 * k_ * xi * xi; }
  double contact_radius(double xi) const override { return contact::hertz::contact_radius(r_, xi); }
  double reference_overlap(double speed) const override { return speed * std::sqrt(m_ / k_); }  // (1/2) k xi0^2 = (1/2) m g^2

 private:
  double k_, c_, m_, r_;
};

// The same law per DEM contact: it does not depend on R_eff or m_eff.
class LinearSpringDem final : public models::DemLaw {
 public:
  LinearSpringDem(double k, double c) : k_(k), c_(c) {}
  double force(const models::ContactGeometry&, double xi, double rate) const override {
    return xi <= 0.0 ? 0.0 : k_ * xi + c_ * rate;
  }
  double energy(const models::ContactGeometry&, double xi) const override { return xi <= 0.0 ? 0.0 : 0.5 * k_ * xi * xi; }

 private:
  double k_, c_;
};

// Its parameters: a struct and its field table (name, unit, range, default, help, member).
struct LinearSpringParameters {
  double stiffness = 0.0;  // k [N/m], required
  double damping = 0.0;    // c [N s/m]
};
const FieldTable<LinearSpringParameters>& toy_fields() {
  using S = LinearSpringParameters;
  static const FieldTable<S> table{
      {real_parameter("stiffness", "spring stiffness k", "N/m", positive(), "spring stiffness k [N/m]"), &S::stiffness},
      {with_default(real_parameter("damping", "dashpot c", "N s/m", non_negative(), "dashpot c [N s/m]"), 0.0),
       &S::damping}};
  return table;
}

// The one row: keyword, summary, references, traits, the field table, the factory.
models::Traits toy_traits() {
  models::Traits t;
  t.adhesion = models::Adhesion::unchecked;
  t.end_rules_why = "overlap or force";
  return t;
}

const models::ModelRow& register_toy() {
  static const models::ModelRow& row = models::model_registry().add(models::model_row(
      "test-linear-spring", "linear spring-dashpot (test only)", "Cundall & Strack (1979)", toy_traits(), toy_fields(),
      [](const Pair& pair, const LinearSpringParameters& p, const models::ModelContext&) {
        models::Made<models::ForceLaw> m;
        m.normal = models::ForceLaw{
            std::make_shared<LinearSpring>(p.stiffness, p.damping, pair.effective_mass(), pair.effective_radius()),
            std::make_shared<LinearSpringDem>(p.stiffness, p.damping)};
        return m;
      }));
  return row;
}

api::Inputs steel(api::Inputs more) {
  more.insert({{"material", std::string("steel")}, {"radius", 1e-3}});
  return more;
}

}  // namespace

// docs/architecture.md, "Adding a model": a toy normal-force model registered as one row (in this test
// binary only) collides through the front door, with no other edit, and its COR is the
// exact one of a damped linear oscillator to the integration tolerance (1e-12: the
// default tolerance of direct integration, in the scaled units).
TEST(FrontDoor, ToyModelAddedAsOneRow) {
  const auto& row = register_toy();
  EXPECT_EQ(row.name, "test-linear-spring");
  const Pair pair = api::make_pair(steel({}));
  const double k = 1e6, m = pair.effective_mass(), c = 0.2 * 2.0 * std::sqrt(k * m);  // zeta = 0.2
  const Record r = api::collide(steel({{"model", std::string("test-linear-spring")}, {"stiffness", k}, {"damping", c},
                                       {"velocity", 0.5}}));
  const double zeta = 0.2, exact = std::exp(-std::numbers::pi * zeta / std::sqrt(1.0 - zeta * zeta));
  EXPECT_NEAR(r.at("cor").number(), exact, 1e-10);
  EXPECT_EQ(r.at("model").text(), "test-linear-spring");
  EXPECT_EQ(r.at("method").text(), "integrate");
  EXPECT_NEAR(r.at("contact_time").number(), std::numbers::pi / std::sqrt(k / m * (1.0 - zeta * zeta)), 1e-12);
  // The shared parameters come with the row: an oblique collision, plastic losses.
  const Record oblique = api::collide(steel({{"model", std::string("test-linear-spring")}, {"stiffness", k},
                                             {"velocity", 0.5}, {"tangential_velocity", 0.1}, {"friction", 0.3},
                                             {"asperity", 1e-7}}));
  EXPECT_TRUE(oblique.contains("cor_tangential"));
  // Its parameters are checked like any other: a foreign one is refused, a bad value too.
  EXPECT_THROW(api::collide(steel({{"model", std::string("test-linear-spring")}, {"stiffness", k}, {"A", 1e-6},
                                   {"velocity", 0.5}})),
               InvalidArgument);
  EXPECT_THROW(api::collide(steel({{"model", std::string("test-linear-spring")}, {"stiffness", -1.0},
                                   {"velocity", 0.5}})),
               InvalidArgument);
  // A keyword is taken once.
  EXPECT_THROW(models::model_registry().add(row), InvalidArgument);
  // Its engine is the kind its factory makes; its DEM law came from the same factory.
  EXPECT_EQ(row.traits.engine, models::Engine::force_law);
  const models::DemModel dem =
      api::dem_model({{"model", std::string("test-linear-spring")}, {"material", std::string("steel")}, {"stiffness", k}});
  EXPECT_EQ(dem.normal->force({1e-3, 1e-3}, 2e-6, 0.0), k * 2e-6);  // exact: one product
}

// The rules between a model's parameters are its table's, checked where the model is made, and
// refused by the one-line rule naming the input that breaks them.
TEST(FrontDoor, RulesBetweenParametersNameTheInput) {
  const auto refusal = [](api::Inputs in) {
    try {
      api::collide(steel(std::move(in)));
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const auto model = [](const char* name) { return api::Inputs{{"model", std::string(name)}, {"velocity", 0.5}}; };
  api::Inputs two = model("viscoelastic");
  two.insert({{"A", 1e-9}, {"tvis", 1e-11}});
  EXPECT_EQ(refusal(two), "tvis = 1e-11 is invalid: expected one of A, the viscosities eta1 and eta2, or T_vis, not "
                          "two (model viscoelastic)");
  api::Inputs half = model("viscoelastic-shifted");
  half.insert({"eta1", 1.0});
  EXPECT_EQ(refusal(half), "eta2 = (not given) is invalid: expected eta2 given with eta1 (model viscoelastic-shifted)");
  EXPECT_EQ(refusal(model("viscoelastic")),
            "A = (not given) is invalid: expected one of A, the viscosities eta1 and eta2, or T_vis (model viscoelastic)");
  api::Inputs krijt = model("krijt");
  krijt.insert({{"gamma", 0.1}, {"A", 1e-9}});
  EXPECT_EQ(refusal(krijt),
            "tvis = (not given) is invalid: expected a viscous relaxation time T_vis > 0 s for the crack law K13 (16) "
            "(model krijt)");
  api::Inputs both = model("jkr-viscoelastic");  // A and T_vis: A damps the bulk, T_vis is the viscous time
  both.insert({{"gamma", 0.1}, {"A", 1e-9}, {"tvis", 1e-11}});
  EXPECT_EQ(refusal(both), "accepted");
}

// Every model refuses a parameter that only other models take, naming it and the models
// that take it; the front door's listing of each model is what its row declares.
TEST(FrontDoor, EachModelRefusesWhatItDoesNotTake) {
  std::set<std::string> all;
  for (const auto& row : models::model_registry().rows()) {
    for (const auto& s : row.parameters) all.insert(s.name);
  }
  for (const auto& row : models::model_registry().rows()) {
    std::set<std::string> own;
    for (const auto& s : row.parameters) own.insert(s.name);
    int refused = 0;
    for (const auto& name : all) {
      if (own.count(name)) continue;
      try {
        api::collide(steel({{"model", row.name}, {name, 1.0}, {"velocity", 1.0}}));
        ADD_FAILURE() << row.name << " took " << name;
      } catch (const InvalidArgument& e) {
        EXPECT_EQ(e.parameter(), name) << e.what();
        EXPECT_NE(e.allowed().find("no " + name + " with model " + row.name), std::string::npos) << e.what();
        ++refused;
      }
    }
    EXPECT_GT(refused, 0) << row.name;
  }
}

// Inputs of another command, and inputs nobody takes, are refused with the same rule.
TEST(FrontDoor, CommandsRefuseForeignInputs) {
  try {
    api::collide(steel({{"A", 1e-7}, {"velocity", 1.0}, {"velocities", std::string("1:2:3")}}));
    ADD_FAILURE();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "velocities");
    EXPECT_NE(e.allowed().find("bounce curve"), std::string::npos) << e.what();
  }
  try {
    api::collide(steel({{"A", 1e-7}, {"velocity", 1.0}, {"nonsense", 1.0}}));
    ADD_FAILURE();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "nonsense");
  }
  // The tangential law without a tangential velocity is unused in a head-on collision.
  EXPECT_THROW(api::collide(steel({{"A", 1e-7}, {"velocity", 1.0}, {"friction", 0.3}, {"asperity", 1e-7}})),
               InvalidArgument);
  // A follow time is for the models that integrate the settling.
  EXPECT_THROW(api::collide(steel({{"A", 1e-7}, {"velocity", 1.0}, {"follow", 1e-3}})), InvalidArgument);
  // Numerical settings of another engine.
  EXPECT_THROW(api::collide(steel({{"A", 1e-7}, {"velocity", 1.0}, {"stiff_engine", std::string("cvode")}})),
               InvalidArgument);
}

// The Records carry the CLI's JSON keys (docs/cli.md).
TEST(FrontDoor, CollideRecordKeys) {
  const Record r = api::collide(steel({{"A", 1e-7}, {"velocity", 1.0}}));
  for (const char* key : {"cor", "outcome", "contact_time", "max_overlap", "time_of_max_overlap", "method", "steps",
                          "energy", "warnings", "notes", "model", "contact_end", "velocity", "kappa", "pair"}) {
    EXPECT_TRUE(r.contains(key)) << key;
  }
  for (const char* key : {"initial_kinetic", "final_kinetic", "bulk_dissipated", "crack_dissipated",
                          "plastic_dissipated", "elastic_remaining", "surface_remaining", "closure_error"}) {
    EXPECT_TRUE(r.at("energy").record().contains(key)) << key;
  }
}
