// The collision atlas (docs/atlas.md): lookups against direct collisions within the stated
// error at random pairs of radii (walls included), sticking velocities against bisections,
// the file's round trip and its refusals (changed, another model, not an atlas), queries
// outside the table, the resume from a cache, the C API.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "bounce/analysis/atlas.hpp"
#include "bounce/analysis/sticking.hpp"
#include "bounce/api/atlas.hpp"
#include "bounce/atlas.h"
#include "bounce/core/error.hpp"
#include "bounce/models/registry.hpp"

using namespace bounce;
using namespace bounce::analysis;

namespace {

const double inf = std::numeric_limits<double>::infinity();

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("bounce-test-atlas-" + std::to_string(::getpid()) + "-" + name)).string();
}

// Small atlases that build in seconds: viscoelastic (master curve) and krijt over a range
// of radii where its v_s is smooth (1-10 um ice: 0.9-4.2 m/s).
AtlasRequest viscoelastic_request() {
  return api::atlas_request({{"model", "viscoelastic"}, {"A", "1e-10"}, {"materials", "water-ice,quartz"},
                             {"radius", "1e-6:1e-4:5"}, {"velocity", "0.01:10:5"}, {"tol", "1e-4"}});
}
AtlasRequest krijt_request() {
  return api::atlas_request({{"model", "krijt"}, {"tvis", "1e-11"}, {"materials", "water-ice"},
                             {"radius", "1e-6:1e-5:4"}, {"velocity", "0.3:20:5"}, {"tol", "1e-3"}});
}

const Atlas& viscoelastic_atlas() {
  static const Atlas a = build_atlas(viscoelastic_request());
  return a;
}
const Atlas& krijt_atlas() {
  static const Atlas a = build_atlas(krijt_request());
  return a;
}

Pair pair_of(const Atlas& a, double r1, double r2) {
  return std::isinf(r2) ? Pair(sphere(a.material1, r1), wall(a.material2))
                        : Pair(sphere(a.material1, r1), sphere(a.material2, r2));
}

// Random radii whose R_eff lies in the atlas's range: R1 log-uniform, R2 = R1 times a
// log-uniform ratio in [1e-2, 1e2], or a wall one time in eight.
struct RandomPair {
  std::mt19937_64 rng{7};
  std::array<double, 2> operator()(const Atlas& a) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (;;) {
      const double r1 = a.radius_min * std::pow(a.radius_max / a.radius_min * 4.0, u(rng));
      const double r2 = u(rng) < 0.125 ? inf : r1 * std::pow(10.0, 4.0 * u(rng) - 2.0);
      const double r = std::isinf(r2) ? r1 : r1 * r2 / (r1 + r2);
      if (r >= a.radius_min && r <= a.radius_max) return {r1, r2};
    }
  }
};

// |eps_atlas - eps_collide| within the stated error at n random (R1, R2, v); the outcome
// agrees outside the v_stick band. Returns the largest error seen.
double largest_error(const Atlas& a, const AtlasRequest& request, int n) {
  RandomPair radii;
  std::uniform_real_distribution<double> u(std::log(a.velocity_min), std::log(a.velocity_max));
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    const auto [r1, r2] = radii(a);
    const double v = std::exp(u(radii.rng));
    const Pair pair = pair_of(a, r1, r2);
    const auto model = models::make_model(pair, request.model, request.model_parameters);
    const auto direct = collide(pair, model, v, request.options);
    const AtlasValue got = a.at({r1, r2, v});
    const bool direct_sticks = direct.outcome == dynamics::Outcome::stick;
    if (got.sticks != direct_sticks) {
      EXPECT_LE(std::abs(v / got.v_stick - 1.0), a.errors.v_stick) << "outcome differs outside the v_stick band at R1 = "
                                                                   << r1 << ", R2 = " << r2 << ", v = " << v;
      continue;
    }
    const double e = std::abs(got.cor - (direct_sticks ? 0.0 : direct.cor));
    EXPECT_LE(e, a.errors.cor) << "R1 = " << r1 << ", R2 = " << r2 << ", v = " << v;
    worst = std::max(worst, e);
  }
  return worst;
}

}  // namespace

TEST(Atlas, EffectiveDensityOfEqualSpheresIsFourTimesTheWalls) {
  // rho_eff = 3 m_eff / (4 pi R_eff^3): 4 rho for equal spheres (m/2 over (R/2)^3 / R^3 * ...), rho on a wall.
  EXPECT_DOUBLE_EQ(effective_density(1000.0, 1000.0, 1e-6, 1e-6), 4000.0);
  EXPECT_DOUBLE_EQ(effective_density(1000.0, 2650.0, 1e-6, inf), 1000.0);
  const double r1 = 2e-6, r2 = 3e-6, m1 = 4.0 / 3.0 * M_PI * 1000.0 * r1 * r1 * r1, m2 = 4.0 / 3.0 * M_PI * 2650.0 * r2 * r2 * r2;
  const double r = r1 * r2 / (r1 + r2), m = m1 * m2 / (m1 + m2);
  EXPECT_NEAR(effective_density(1000.0, 2650.0, r1, r2), 3.0 * m / (4.0 * M_PI * r * r * r), 1e-12 * 4000.0);
}

TEST(Atlas, ViscoelasticAgreesWithCollideWithinItsStatedError) {
  const Atlas& a = viscoelastic_atlas();
  EXPECT_LE(a.errors.cor, viscoelastic_request().tolerance);  // the build's promise: 2x measured <= tol
  EXPECT_FALSE(a.can_stick);
  EXPECT_GT(largest_error(a, viscoelastic_request(), 300), 0.0);  // a real comparison, not a copy
}

TEST(Atlas, KrijtAgreesWithCollideAndItsStickingVelocityWithBisections) {
  const Atlas& a = krijt_atlas();
  const AtlasRequest request = krijt_request();
  EXPECT_LE(a.errors.cor, request.tolerance);
  EXPECT_LE(a.errors.v_stick, 1e-6);
  largest_error(a, request, 300);
  RandomPair radii;
  for (int i = 0; i < 6; ++i) {
    const auto [r1, r2] = radii(a);
    const Pair pair = pair_of(a, r1, r2);
    const auto s = sticking_velocity(pair, models::make_model(pair, "krijt", request.model_parameters), request.options,
                                     1e-10);
    ASSERT_FALSE(s.sticks_up_to_sound_speed);
    EXPECT_NEAR(a.v_stick(r1, r2) / s.velocity, 1.0, a.errors.v_stick) << "R1 = " << r1 << ", R2 = " << r2;
  }
}

// Just above v_s, where random points rarely fall: under krijt eps rises linearly from the
// threshold (eps^2 ~ (v - v_s)^2), which the atlas must follow below its first z point too.
TEST(Atlas, KrijtJustAboveTheStickingVelocityWithinTheStatedError) {
  const Atlas& a = krijt_atlas();
  const AtlasRequest request = krijt_request();
  for (const auto& [r1, r2] : std::vector<std::array<double, 2>>{{2e-6, 2e-6}, {3e-6, inf}, {4e-6, 1.5e-5}}) {
    const Pair pair = pair_of(a, r1, r2);
    const auto model = models::make_model(pair, "krijt", request.model_parameters);
    const auto s = sticking_velocity(pair, model, request.options, 1e-10);
    for (double above : {3e-6, 1e-5, 1e-4, 1e-3, 1e-2}) {
      const double v = s.upper * (1.0 + above);
      const auto direct = collide(pair, model, v, request.options);
      ASSERT_EQ(direct.outcome, dynamics::Outcome::bounce);
      ASSERT_FALSE(a.sticks(r1, r2, v)) << "v = v_s (1 + " << above << ")";
      EXPECT_LE(std::abs(a.cor(r1, r2, v) - direct.cor), a.errors.cor) << "R1 = " << r1 << ", v = v_s (1 + " << above << ")";
    }
  }
}

TEST(Atlas, FileRoundTripGivesTheSameLookupsBitForBit) {
  const Atlas& a = krijt_atlas();
  const std::string path = temp_path("round.h5");
  write_atlas(a, path);
  const Atlas b = read_atlas(path, "krijt");
  EXPECT_EQ(b.model, "krijt");
  EXPECT_EQ(b.parameters.size(), a.parameters.size());
  for (double v : {0.3, 1.0, 3.0, 4.4, 19.9}) {
    EXPECT_EQ(a.cor(2e-6, 5e-6, v), b.cor(2e-6, 5e-6, v));
    EXPECT_EQ(a.cor(3e-6, inf, v), b.cor(3e-6, inf, v));
  }
  EXPECT_EQ(a.v_stick(2e-6, 2e-6), b.v_stick(2e-6, 2e-6));
  EXPECT_THROW(read_atlas(path, "viscoelastic"), InvalidArgument);  // another model
  std::filesystem::remove(path);
}

TEST(Atlas, AChangedFileIsRefusedByItsChecksum) {
  Atlas a = krijt_atlas();
  const std::string path = temp_path("changed.h5");
  write_atlas(a, path);
  // Flip one byte deep inside the file (in the values, the largest dataset).
  {
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(0, std::ios::end);
    const auto size = static_cast<long>(f.tellg());
    f.seekg(size * 3 / 4);
    char c = 0;
    f.read(&c, 1);
    f.seekp(size * 3 / 4);
    c = static_cast<char>(c ^ 0x5a);
    f.write(&c, 1);
  }
  try {
    read_atlas(path);
    ADD_FAILURE() << "a changed atlas was read";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("the file was changed after bounce wrote it"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

TEST(Atlas, AFileThatIsNoAtlasIsRefused) {
  const std::string path = temp_path("text.h5");
  std::ofstream(path) << "velocity,cor\n1,0.5\n";
  EXPECT_THROW(read_atlas(path), InvalidArgument);
  std::filesystem::remove(path);
  EXPECT_THROW(read_atlas(temp_path("missing.h5")), InvalidArgument);
}

// A radius of 1e300 m is a wall by another name: no overflow in R_eff or rho_eff.
TEST(Atlas, AHugeSecondRadiusIsAWall) {
  const Atlas& a = krijt_atlas();
  for (double r2 : {1e101, 1e103, 1e300}) {
    EXPECT_NEAR(a.v_stick(3e-6, r2), a.v_stick(3e-6, inf), 1e-12 * a.v_stick(3e-6, inf)) << r2;
    EXPECT_NEAR(a.cor(3e-6, r2, 10.0), a.cor(3e-6, inf, 10.0), 1e-12) << r2;
  }
  EXPECT_DOUBLE_EQ(effective_density(1000.0, 2650.0, 1e-6, 1e300), 1000.0);
}

// Outputs may be written over an input (out == v): every input is read before its output.
// The batch takes its logarithms four at a time from glibc's libmvec (within 4 ulp of std::log,
// glibc's manual) and may be compiled with FMA: ln R_eff ~ -13 then moves by ~1e-14, and eps,
// whose slope in the grid's coordinates is O(1), by as little, so 1e-13 is room, not slack.
TEST(Atlas, ManyLookupsMayWriteOverTheirSpeeds) {
  const Atlas& a = krijt_atlas();
  double r1[40], r2[40], v[40], expected[40];
  for (int i = 0; i < 40; ++i) {
    r1[i] = 2e-6 + 1e-7 * i;
    r2[i] = 5e-6;
    v[i] = 0.5 + 0.45 * i;
    expected[i] = a.cor(r1[i], r2[i], v[i]);
  }
  a.cor_many(40, r1, r2, v, v);
  for (int i = 0; i < 40; ++i) EXPECT_NEAR(v[i], expected[i], 1e-13) << i;
}

TEST(Atlas, AQueryOutsideTheTableNamesTheValueAndTheRange) {
  const Atlas& a = krijt_atlas();
  try {
    a.cor(2e-6, 2e-6, 50.0);
    ADD_FAILURE() << "50 m/s is outside 0.3 .. 20 m/s";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "velocity");
    EXPECT_EQ(e.value(), "50");
    EXPECT_NE(e.allowed().find("0.3 .. 20 m/s"), std::string::npos) << e.what();
  }
  EXPECT_THROW(a.cor(1e-7, 1e-7, 1.0), InvalidArgument);   // R_eff 5e-8 below 1e-6
  EXPECT_THROW(a.v_stick(1e-2, inf), InvalidArgument);     // R_eff above 1e-5
  EXPECT_THROW(a.cor(-1e-6, 2e-6, 1.0), InvalidArgument);
  EXPECT_THROW(a.cor(NAN, 2e-6, 1.0), InvalidArgument);
}

TEST(Atlas, BadBuildInputsAreRefusedNamingThem) {
  const auto refused = [](api::Inputs in, const char* name) {
    in.emplace("model", "krijt");
    in.emplace("tvis", "1e-11");
    try {
      api::atlas_request(in);
      ADD_FAILURE() << "accepted " << name;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.parameter(), name) << e.what();
    }
  };
  refused({{"materials", "water-ice"}, {"velocity", "0.1:10:5"}}, "radius");
  refused({{"materials", "water-ice"}}, "radius");  // neither range: the message says what an atlas needs
  refused({{"materials", "water-ice"}, {"radius", "1e-6:1e-5"}, {"velocity", "0.1:10:5"}}, "radius");
  refused({{"materials", "water-ice"}, {"radius", "1e-6:1e-5:5"}, {"velocity", "10:0.1:5"}}, "velocity");
  refused({{"materials", "water-ice"}, {"radius", "1e-6:1e-5:2"}, {"velocity", "0.1:10:5"}}, "radius");
  refused({{"materials", "water-ice"}, {"radius", "1e-6:1e-5:5"}, {"velocity", "0.1:1e4:5"}}, "velocity");  // > c_t
  refused({{"materials", "water-ice,,quartz"}, {"radius", "1e-6:1e-5:5"}, {"velocity", "0.1:10:5"}}, "materials");
  refused({{"materials", "water-ice"}, {"radius", "1e-6:1e-5:5"}, {"velocity", "0.1:10:5"}, {"wall", true}}, "wall");
  refused({{"materials", "water-ice"}, {"radius", "1e-6:1e-5:5"}, {"velocity", "0.1:10:5"}, {"tol", "0"}}, "tol");
}

TEST(Atlas, AnInterruptedBuildResumesFromItsCache) {
  const std::string cache = temp_path("cache.partial");
  AtlasRunner runner;
  runner.cache_path = cache;
  std::size_t computed = 0;
  runner.progress = [&](std::size_t done, const std::string&) { computed = done; };
  const Atlas first = build_atlas(viscoelastic_request(), runner);
  EXPECT_GT(computed, 100U);
  computed = 0;
  const Atlas again = build_atlas(viscoelastic_request(), runner);  // everything from the cache
  EXPECT_EQ(computed, 0U);
  EXPECT_EQ(first.values, again.values);
  // A cache of another build (other parameters) is refused, not mixed in.
  AtlasRequest other = viscoelastic_request();
  other.model_parameters = api::atlas_request({{"model", "viscoelastic"}, {"A", "2e-10"}, {"materials", "water-ice,quartz"},
                                               {"radius", "1e-6:1e-4:5"}, {"velocity", "0.01:10:5"}})
                               .model_parameters;
  EXPECT_THROW(build_atlas(other, runner), InvalidArgument);
  std::filesystem::remove(cache);
}

TEST(Atlas, CApiAgreesWithTheLibraryAndReturnsNanOutside) {
  const Atlas& a = krijt_atlas();
  const std::string path = temp_path("c.h5");
  write_atlas(a, path);
  char error[256];
  EXPECT_EQ(bounce_atlas_open(path.c_str(), "viscoelastic", error, sizeof error), nullptr);
  EXPECT_NE(std::string(error).find("krijt"), std::string::npos) << error;
  bounce_atlas* c = bounce_atlas_open(path.c_str(), "krijt", error, sizeof error);
  ASSERT_NE(c, nullptr) << error;
  for (double v : {0.5, 2.0, 5.0, 15.0}) {
    EXPECT_EQ(bounce_atlas_cor(c, 2e-6, 7e-6, v), a.cor(2e-6, 7e-6, v));
    EXPECT_EQ(bounce_atlas_sticks(c, 2e-6, inf, v), a.sticks(2e-6, inf, v) ? 1 : 0);
  }
  EXPECT_TRUE(std::isnan(bounce_atlas_cor(c, 2e-6, 7e-6, 100.0)));
  EXPECT_TRUE(std::isnan(bounce_atlas_cor(c, 2e-5, -3e-5, 1.0)));  // R_eff would be 6e-5 > 0: still refused
  EXPECT_TRUE(std::isnan(bounce_atlas_v_stick(c, NAN, 3e-6)));
  const double r1[] = {2e-6, 2e-5, 3e-6}, r2[] = {7e-6, -3e-5, inf}, v[] = {5.0, 1.0, 50.0};
  double many[3];
  bounce_atlas_cor_n(c, 3, r1, r2, v, many);
  EXPECT_NEAR(many[0], a.cor(2e-6, 7e-6, 5.0), 1e-13);  // the batch's vector logarithms: see above
  EXPECT_TRUE(std::isnan(many[1]) && std::isnan(many[2]));
  EXPECT_EQ(bounce_atlas_sticks(c, 1e-8, 1e-8, 1.0), -1);
  bounce_atlas_value value{};
  EXPECT_EQ(bounce_atlas_lookup(c, 2e-6, 7e-6, 100.0, &value), -1);
  ASSERT_EQ(bounce_atlas_lookup(c, 2e-6, 7e-6, 10.0, &value), 0);
  EXPECT_EQ(value.cor, a.cor(2e-6, 7e-6, 10.0));
  EXPECT_GT(value.contact_time, 0.0);
  bounce_atlas_grid grid{};
  bounce_atlas_get_grid(c, &grid);
  EXPECT_EQ(grid.nx, a.x.count);
  EXPECT_EQ(grid.nz, a.z.count);
  ASSERT_NE(grid.values, nullptr);
  EXPECT_EQ(grid.values[grid.nx * grid.ny * grid.nz * 4 - 1], a.values.back());  // the same grid, whole
  bounce_atlas_close(c);
  std::filesystem::remove(path);
}
