// The rolling, sliding and twisting sub-model (dem/resistance.hpp) without LAMMPS: a dimer rolled,
// slid and twisted by imposed motions gives W07's elastic response below each critical
// displacement and the constant limit beyond it, the work dissipated per rolled (slid, twisted)
// distance is that limit, and a free elastic dimer keeps its energy over 1e6 steps.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <gtest/gtest.h>

#include "bounce/api/front_door.hpp"
#include "bounce/contact/jkr.hpp"
#include "bounce/contact/resistance.hpp"
#include "bounce/dem/contact.hpp"
#include "dem/two_spheres.hpp"

using namespace bounce;
namespace res = bounce::contact::resistance;

namespace {

// W07's ice, in the literature's per-surface gamma_s = 0.1 J/m^2, and an elastic JKR normal law.
api::Inputs ice(double radius) {
  return {{"E", 7e9}, {"nu", 0.25}, {"density", 1000.0}, {"surface_energy", 0.1}, {"radius", radius}};
}

models::DemModel law_with(double radius, bool rolling, bool sliding, bool twisting) {
  api::Inputs in = ice(radius);
  in.erase("density"), in.erase("radius");  // LAMMPS's, per atom
  in["model"] = std::string("jkr-viscoelastic");
  in["A"] = 0.0;
  models::DemModel law = api::dem_model(in);
  law.resistance = models::ResistanceModel{res::materials_of(api::make_pair(ice(radius))), 8e-10, rolling, sliding,
                                           twisting};
  return law;
}

double length(const double* v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// Two like spheres, body 2 fixed at the origin, body 1 at distance d in the direction at angle
// alpha in the xy plane: each step moves and turns body 1 as the test imposes, and steps the contact.
struct Imposed {
  Imposed(models::DemModel l, double radius, double distance) : law(std::move(l)), r(radius), d(distance) {}
  models::DemModel law;
  double r, d, alpha = 0.0, dt = 1e-9;
  dem::ContactState state;
  double dissipated[3] = {0, 0, 0};  // rolling, sliding, twisting, summed
  dem::ContactForce last;
  dem::ContactForce step(double turn_alpha, const double omega1[3]) {
    alpha += turn_alpha;
    const double x1[3] = {d * std::cos(alpha), d * std::sin(alpha), 0.0}, x2[3] = {0, 0, 0}, v[3] = {0, 0, 0};
    const double rest[3] = {0, 0, 0};
    const dem::Kinematics k = dem::pair_kinematics({x1, v, omega1, r}, {x2, v, rest, r}, d);
    const models::ContactGeometry g{r / 2.0, 1.0};
    state.touching = true;
    last = dem::step(law, g, k, {dt, true, false}, state);
    dissipated[0] += last.rolling_dissipated, dissipated[1] += last.sliding_dissipated;
    dissipated[2] += last.twisting_dissipated;
    return last;
  }
};

// The closed forms hold where the displacements are small against the radii: 1 mm grains at zero
// overlap (xi_crit / 2R = 8e-7, xi_s / 2r = 1e-4), so that W07's linear forms and bounce's exact
// springs (docs/resistance.md, In a DEM) agree to 1e-8; the tests ask 1e-6.
constexpr double mm = 1e-3;

}  // namespace

// Pure rolling of body 1 over body 2: its centre turns by alpha, and it spins by 2 alpha (equal
// spheres), so the contact points roll xi = d alpha / 2 over each other with no sliding.
TEST(DemResistance, RollingIsASpringThenAConstantMoment) {
  Imposed m(law_with(mm, true, true, true), mm, 2 * mm);
  const res::Resistance c = res::contact_resistance(res::materials_of(api::make_pair(ice(mm))), mm / 2, 8e-10);
  const double crit = c.rolling.critical_displacement, still[3] = {0, 0, 0};
  m.step(0.0, still);  // the contact forms
  // 1000 steps to 0.999 xi_crit, then steps of 1e-6 xi_crit to 1.2 xi_crit: each step's release
  // overshoots the work against the limit by half its excess, 5e-7.
  const auto roll = [&](double dxi, double to, auto check) {
    const double per = 2.0 * dxi / m.d, spin[3] = {0, 0, 2.0 * per / m.dt};
    while (m.d * m.alpha / 2.0 < to * (1.0 - 1e-12)) {
      const dem::ContactForce f = m.step(per, spin);
      check(m.d * m.alpha / 2.0, length(f.torque1));
      ASSERT_LT(length(f.tangential), 1e-9 * c.sliding.limit) << "rolling slides nothing";
    }
  };
  roll(0.999 * crit / 1000, 0.999 * crit, [&](double xi, double moment) {
    ASSERT_NEAR(moment, c.rolling.stiffness * (mm / 2) * xi, 1e-6 * c.rolling.limit) << "elastic, xi = " << xi;
  });
  roll(1e-6 * crit, 1.2 * crit, [&](double xi, double moment) {
    if (xi > crit * (1 + 1e-6)) {
      ASSERT_NEAR(moment, c.rolling.limit, 1e-6 * c.rolling.limit) << "beyond, xi = " << xi;
    }
  });
  // The work dissipated per distance the rolling grain's centre travelled beyond xi_crit is F_roll.
  const double travelled = m.d * m.alpha - 2.0 * crit;
  EXPECT_NEAR(m.dissipated[0] / travelled, c.rolling_force, 1e-6 * c.rolling_force);
  EXPECT_EQ(m.dissipated[1], 0.0);
  EXPECT_EQ(m.dissipated[2], 0.0);
}

// Pure sliding: body 1's centre turns by alpha about body 2 without spinning, so the contact
// points slide d sin(alpha) over each other with no rolling.
TEST(DemResistance, SlidingIsASpringThenAConstantForce) {
  Imposed m(law_with(mm, true, true, true), mm, 2 * mm);
  const res::Resistance c = res::contact_resistance(res::materials_of(api::make_pair(ice(mm))), mm / 2, 8e-10);
  const double crit = c.sliding.critical_displacement, still[3] = {0, 0, 0};
  m.step(0.0, still);
  const auto slide = [&](double dzeta, double to, auto check) {
    while (m.d * m.alpha < to * (1.0 - 1e-12)) {
      const dem::ContactForce f = m.step(dzeta / m.d, still);
      check(m.d * m.alpha, length(f.tangential));
      ASSERT_LT(length(f.torque1) - mm * length(f.tangential), 1e-6 * mm * c.sliding.limit) << "no rolling moment";
    }
  };
  slide(0.999 * crit / 1000, 0.999 * crit, [&](double zeta, double force) {
    ASSERT_NEAR(force, c.sliding.stiffness * zeta, 1e-6 * c.sliding.limit) << "elastic, zeta = " << zeta;
  });
  slide(1e-6 * crit, 1.2 * crit, [&](double zeta, double force) {
    if (zeta > crit * (1 + 1e-6)) {
      ASSERT_NEAR(force, c.sliding.limit, 1e-6 * c.sliding.limit) << "beyond, zeta = " << zeta;
    }
  });
  EXPECT_NEAR(m.dissipated[1] / (m.d * m.alpha - crit), c.sliding.limit, 1e-6 * c.sliding.limit);
  EXPECT_EQ(m.dissipated[0], 0.0);
  EXPECT_EQ(m.dissipated[2], 0.0);
}

// Twisting: body 1 spins about the line of centres (the x axis here), the centres still.
TEST(DemResistance, TwistingIsASpringThenAConstantMoment) {
  Imposed m(law_with(mm, true, true, true), mm, 2 * mm);
  const res::Resistance c = res::contact_resistance(res::materials_of(api::make_pair(ice(mm))), mm / 2, 8e-10);
  const double crit = c.twisting.critical_displacement, still[3] = {0, 0, 0};
  m.step(0.0, still);
  double phi = 0.0;
  const auto twist = [&](double dphi, double to, auto check) {
    const double spin[3] = {dphi / m.dt, 0, 0};
    while (phi < to * (1.0 - 1e-12)) {
      const dem::ContactForce f = m.step(0.0, spin);
      phi += dphi;
      check(phi, -f.torque1[0]);
      ASSERT_EQ(length(f.tangential), 0.0);
    }
  };
  twist(0.999 * crit / 1000, 0.999 * crit, [&](double angle, double moment) {
    ASSERT_NEAR(moment, c.twisting.stiffness * angle, 1e-9 * c.twisting.limit) << "elastic, phi = " << angle;
  });
  twist(1e-6 * crit, 1.2 * crit, [&](double angle, double moment) {
    if (angle > crit) {
      ASSERT_NEAR(moment, c.twisting.limit, 1e-9 * c.twisting.limit) << "beyond, phi = " << angle;
    }
  });
  EXPECT_NEAR(m.dissipated[2] / (phi - crit), c.twisting.limit, 1e-6 * c.twisting.limit);
  EXPECT_EQ(m.dissipated[0], 0.0);
  EXPECT_EQ(m.dissipated[1], 0.0);
}

// A free dimer of 0.1 um ice grains at the JKR contact's rest, set rolling, sliding and twisting
// against each other below every critical displacement, by the velocity Verlet pair_style bounce
// runs in: with the elastic JKR law (A = 0) its energy stays within 1e-6 of the initial kinetic
// energy over 1e6 steps. Verlet's energy error is ~(omega dt)^2 / 8 = 2e-7 here (dt = 1/5000 of
// the fastest period, the normal spring's ~1e-9 s); it does not grow.
TEST(DemResistance, ElasticDimerKeepsItsEnergy) {
  const double r = 1e-7;
  const models::DemModel law = law_with(r, true, true, true);
  const Pair pair = api::make_pair(ice(r));
  const contact::jkr::Parameters jp{pair.effective_radius(), pair.effective_modulus(), *pair.surface_energy()};
  const double rest = contact::jkr::overlap(jp, contact::jkr::equilibrium_contact_radius(jp));
  test::Sphere a, b;
  a.radius = b.radius = r;
  a.mass = b.mass = pair.body1().mass();
  a.x[0] = r - rest / 2, b.x[0] = -(r - rest / 2);  // n = +x from b to a
  a.v[1] = 2e-4, b.v[1] = -2e-4;                      // sliding along y
  a.omega[0] = 3e3, b.omega[0] = -3e3;                // twisting about n
  a.omega[2] = 1e3, b.omega[2] = 1e3;                 // rolling about z
  test::TwoSpheres<> run(law, a, b, 2e-13);
  const auto normal_energy = [&] {
    const double* x0 = run.sphere(0).x; const double* x1 = run.sphere(1).x; const double d = std::hypot(x0[0] - x1[0], x0[1] - x1[1], x0[2] - x1[2]);
    return law.normal->energy(run.geometry(), 2 * r - d);
  };
  run.setup();
  const double kinetic0 = run.kinetic(), energy0 = kinetic0 + normal_energy() + run.stored();
  double worst = 0.0;
  run.run(1000000, [&](int n) {
    if (n % 97 == 0) worst = std::max(worst, std::abs(run.kinetic() + normal_energy() + run.stored() - energy0));
  });
  EXPECT_EQ(run.dissipated(), 0.0) << "every spring stayed below its critical displacement";
  EXPECT_LT(worst / kinetic0, 1e-6);
  EXPECT_GT(run.stored(), 0.0);
}
