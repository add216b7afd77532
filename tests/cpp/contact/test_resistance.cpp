// The rolling, sliding and twisting resistance of a JKR contact against W07's closed forms, the
// break energy against a quadrature of bounce's own JKR curve, and a measured rolling force.
#include <cmath>
#include <numbers>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <gtest/gtest.h>

#include "bounce/contact/jkr.hpp"
#include "bounce/contact/resistance.hpp"
#include "bounce/core/error.hpp"
#include "bounce/pair/materials_table.hpp"
#include "bounce/pair/mixing.hpp"
#include "bounce/pair/pair.hpp"

using namespace bounce;
namespace res = bounce::contact::resistance;

namespace {
constexpr double pi = std::numbers::pi;

// W07's ice: gamma_s = 0.1 J/m^2 per surface (bounce's gamma = 0.2), E = 7 GPa, nu = 0.25.
Material w07_ice() { return Material{"w07-ice", 7e9, 0.25, 1000.0, 0.2, std::nullopt, "W07 §2"}; }

double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }
}  // namespace

// The closed form of break_energy_factor() against a 61-point Gauss-Kronrod quadrature of
// -F d(delta) along bounce's JKR curve (K13 (8), (9)) from a0 to the fold: the integrand is
// smooth there, so the quadrature is exact to round-off (1e-12). SPEC's 1.5426 to its digits.
TEST(Resistance, BreakEnergyIsTheWorkAlongTheJkrCurve) {
  const contact::jkr::Parameters p{0.5e-7, 3.7e9, 0.2};
  const double a0 = contact::jkr::equilibrium_contact_radius(p);
  const double fold = contact::jkr::separation_contact_radius(p);
  const auto work = [&](double a) {  // -F(a) d(delta)/da, K13 (8) differentiated
    const double d_overlap = 2.0 * a / p.effective_radius - 0.5 * std::sqrt(2.0 * pi * p.surface_energy / (p.effective_modulus * a));
    return -contact::jkr::force(p, a) * d_overlap;
  };
  const double w = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(work, fold, a0, 0);
  const double scale = -contact::jkr::pull_off_force(p) * -contact::jkr::separation_overlap(p);
  EXPECT_LT(relative(w / scale, res::break_energy_factor()), 1e-12);
  EXPECT_NEAR(res::break_energy_factor(), 1.5426, 5e-5);
}

// Every quantity of a like pair against W07 §2.2's closed forms, written in gamma_s = gamma/2:
// the code takes them through bounce's JKR and the mixing rules, so they agree to round-off.
TEST(Resistance, LikeSpheresMatchW07ClosedForms) {
  const double r = 0.1e-6, xi = 8e-10, nu = 0.25;
  const Pair pair = Pair::identical(w07_ice(), r);
  const res::Resistance c = res::contact_resistance(pair, xi);
  const double R = r / 2.0, gs = 0.1, e_star = pair.effective_modulus(), g = 7e9 / (2.0 * (1.0 + nu));
  const double a0 = std::cbrt(9.0 * pi * gs * R * R / e_star);
  const double f_c = 3.0 * pi * gs * R;
  const double tol = 1e-13;  // a few ulps of cube roots and products
  EXPECT_LT(relative(c.surface_energy, gs), tol);
  EXPECT_LT(relative(c.contact_radius, a0), tol);
  EXPECT_LT(relative(c.pull_off_force, f_c), tol);
  EXPECT_LT(relative(c.critical_overlap, a0 * a0 / (2.0 * std::cbrt(6.0) * R)), 1e-12);  // K13 (8) at the fold
  EXPECT_LT(relative(c.rolling.stiffness, 4.0 * f_c / R), tol);
  EXPECT_LT(relative(c.rolling_force, 6.0 * pi * gs * xi), tol);
  EXPECT_LT(relative(c.rolling.energy, 6.0 * pi * pi * gs * R * xi), tol);
  EXPECT_LT(relative(c.sliding.critical_displacement, (2.0 - nu) * a0 / (16.0 * pi)), tol);
  EXPECT_LT(relative(c.sliding.limit, g * a0 * a0 / (4.0 * pi)), tol);
  EXPECT_LT(relative(c.sliding.stiffness, 8.0 * a0 * g / (2.0 * (2.0 - nu))), tol);
  EXPECT_LT(relative(c.twisting.critical_displacement, 1.0 / (16.0 * pi)), tol);
  EXPECT_LT(relative(c.twisting.limit, g * a0 * a0 * a0 / (3.0 * pi)), tol);
  EXPECT_LT(relative(c.twisting.stiffness, 16.0 / 3.0 * g * a0 * a0 * a0), tol);
  EXPECT_LT(relative(c.break_energy, 1.5426 * f_c * c.critical_overlap), 5e-5);
}

// Each mode is a spring up to its critical displacement: limit = stiffness x critical, with the
// rolling moment's lever R (the moment k_r R xi), and each energy the limit over a quarter turn.
TEST(Resistance, LimitsAreTheSpringsAtTheirCriticalDisplacements) {
  const auto& t = MaterialTable::builtin();
  const Pair pair(sphere(t.at("water-ice"), 1e-6), sphere(t.at("quartz"), 3e-6));
  const res::Resistance c = res::contact_resistance(pair, 2e-10);
  const double R = pair.effective_radius();
  EXPECT_LT(relative(c.rolling.limit, c.rolling.stiffness * R * c.rolling.critical_displacement), 1e-15);
  EXPECT_LT(relative(c.sliding.limit, c.sliding.stiffness * c.sliding.critical_displacement), 1e-15);
  EXPECT_LT(relative(c.twisting.limit, c.twisting.stiffness * c.twisting.critical_displacement), 1e-15);
  EXPECT_LT(relative(c.rolling.energy, pi / 2.0 * c.rolling.limit), 1e-15);
  EXPECT_LT(relative(c.sliding.energy, c.sliding.limit * pi / 2.0 * R), 1e-15);
  EXPECT_LT(relative(c.twisting.energy, pi / 2.0 * c.twisting.limit), 1e-15);
}

// Unlike bodies: the springs take the moduli in series, the limits the weaker body (docs), so
// the contact is the same seen from either body, and a rigid wall is the limit of a stiff one.
TEST(Resistance, UnlikeBodiesAreSymmetricAndARigidWallIsTheStiffLimit) {
  const auto& t = MaterialTable::builtin();
  const res::Resistance ab = res::contact_resistance(Pair(sphere(t.at("psl"), 1e-6), sphere(t.at("steel"), 2e-6)), 8e-10);
  const res::Resistance ba = res::contact_resistance(Pair(sphere(t.at("steel"), 2e-6), sphere(t.at("psl"), 1e-6)), 8e-10);
  for (auto [x, y] : {std::pair{ab.sliding.limit, ba.sliding.limit}, {ab.sliding.stiffness, ba.sliding.stiffness},
                      {ab.twisting.limit, ba.twisting.limit}, {ab.twisting.stiffness, ba.twisting.stiffness},
                      {ab.rolling.limit, ba.rolling.limit}, {ab.break_energy, ba.break_energy}}) {
    EXPECT_LT(relative(x, y), 1e-14);
  }
  Material stiff = t.at("psl");
  stiff.youngs_modulus = 1e30;
  const Material psl = t.at("psl");
  const res::Resistance rigid = res::contact_resistance(Pair(sphere(psl, 1e-6), rigid_wall(psl)), 8e-10);
  const res::Resistance near = res::contact_resistance(Pair(sphere(psl, 1e-6), wall(stiff)), 8e-10);
  EXPECT_LT(relative(near.twisting.stiffness, rigid.twisting.stiffness), 1e-15);  // G1/G2 ~ 1e-21
  EXPECT_LT(relative(near.sliding.stiffness, rigid.sliding.stiffness), 1e-15);
  EXPECT_LT(relative(rigid.twisting.limit, shear_modulus(psl.youngs_modulus, psl.poisson_ratio) *
                                               std::pow(rigid.contact_radius, 3) / (3.0 * pi)), 1e-14);
}

// Heim et al. 1999 measured F_roll = 8.5e-10 N for SiO2 spheres of 0.95 um with xi_crit = 3.2 nm
// and gamma_s = 0.014 J/m^2: DT95's 6 pi gamma_s xi_crit gives 8.44e-10 N, within the 1 % of
// the measurement's two digits.
TEST(Resistance, RollingForceMatchesHeim1999) {
  Material silica = MaterialTable::builtin().at("quartz");
  silica.surface_energy = 2.0 * 0.014;
  const res::Resistance c = res::contact_resistance(Pair::identical(silica, 0.95e-6), 3.2e-9);
  EXPECT_NEAR(c.rolling_force, 8.5e-10, 0.01 * 8.5e-10);
}

TEST(Resistance, RefusesACriticalDisplacementOutsideTheContact) {
  const Pair pair = Pair::identical(w07_ice(), 0.1e-6);
  for (double xi : {0.0, -1e-10, 1e-6, std::nan("")}) {
    try {
      (void)res::contact_resistance(pair, xi);
      ADD_FAILURE() << "xi_crit = " << xi << " was taken";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.parameter(), "xi_crit");
      EXPECT_NE(std::string(e.what()).find("a0 ="), std::string::npos) << e.what();
    }
  }
  Material dry = w07_ice();
  dry.surface_energy.reset();
  EXPECT_THROW((void)res::contact_resistance(Pair::identical(dry, 1e-6), 8e-10), InvalidArgument);
}
