// BPCA and BCCA growth (src/aggregate/growth.cpp, docs/aggregates.md): the first touch against
// its closed form, the random transforms, the cell lists against plain loops, the refusals.
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "aggregate/geometry.hpp"
#include "aggregate/projected_grid.hpp"
#include "aggregate/random.hpp"
#include "bounce/aggregate/aggregate.hpp"
#include "bounce/core/error.hpp"

using namespace bounce;
using namespace bounce::aggregate;
using namespace bounce::aggregate::detail;

TEST(AggregateGeometry, FirstTouchIsTheSmallerRootOfTheRaySphereQuadratic) {
  // A line at distance h = 1.2 from a sphere 2 away (contact 2r = 2): s = 5 - sqrt(4 - 1.44).
  const Vector a{1.2, 0.0, -5.0}, u{0.0, 0.0, 1.0}, x{0.0, 0.0, 0.0};
  EXPECT_DOUBLE_EQ(first_touch(a, u, x, 2.0), 5.0 - std::sqrt(4.0 - 1.44));
  const Vector p = a + first_touch(a, u, x, 2.0) * u;
  EXPECT_NEAR(std::sqrt(dot(p - x, p - x)), 2.0, 4e-16 * 5.0);  // a few roundings of numbers ~5
  EXPECT_TRUE(std::isinf(first_touch(Vector{2.0001, 0.0, -5.0}, u, x, 2.0)));  // passes by
  EXPECT_DOUBLE_EQ(first_touch(Vector{2.0, 0.0, -5.0}, u, x, 2.0), 5.0);     // grazes
}

TEST(AggregateRandom, TheEngineIsTheStandardsMt19937_64) {
  std::mt19937_64 engine;  // C++ [rand.predef]: the 10000th output of a default-constructed one
  engine.discard(9999);
  EXPECT_EQ(engine(), 9981545732273789042ULL);
}

TEST(AggregateRandom, DirectionsAreUnitAndIsotropicRotationsOrthonormal) {
  Random random(7);
  Vector mean{0, 0, 0};
  const int n = 100000;
  for (int k = 0; k < n; ++k) {
    const Vector u = random.direction();
    ASSERT_NEAR(dot(u, u), 1.0, 1e-15);
    mean = mean + (1.0 / n) * u;
  }
  // Each component of an isotropic direction has variance 1/3: the mean of 1e5 is within
  // 5 standard deviations, 5 sqrt(1/3 / 1e5) = 0.0091.
  for (double m : mean) EXPECT_LT(std::abs(m), 0.0091);
  for (int k = 0; k < 100; ++k) {
    const Rotation q = random.rotation();
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(dot(q[i], q[j]), i == j ? 1.0 : 0.0, 1e-14);
    }
    EXPECT_NEAR(dot(q[0], cross(q[1], q[2])), 1.0, 1e-14);  // a rotation, not a reflection
  }
}

TEST(AggregateGeometry, ProjectedGridFindsThePlainLoopsFirstTouch) {
  const Aggregate cluster = build({Kind::bcca, 256, 1.0, 3});
  Random random(11);
  int hits = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vector u = random.direction();
    const Vector q{12.0 * random.symmetric(), 12.0 * random.symmetric(), 12.0 * random.symmetric()};
    const ProjectedGrid grid(cluster.centres, u, 2.0);
    double plain = std::numeric_limits<double>::infinity();
    for (const Vector& x : cluster.centres) plain = std::min(plain, first_touch(q, u, x, 2.0));
    EXPECT_EQ(grid.first_touch(q), plain);  // the same candidates' minimum, bit for bit
    hits += std::isinf(plain) ? 0 : 1;
  }
  EXPECT_GT(hits, 100);  // the comparison saw hits, not only misses
}

// BPCA written as plainly as it reads (every monomer tested on every shot): the library's cell
// list must give the same aggregate, bit for bit.
std::vector<Vector> plain_bpca(std::size_t n, double r, std::uint64_t seed) {
  Random random(seed);
  std::vector<Vector> xs{{0, 0, 0}};
  double extent = 0.0;
  while (xs.size() < n) {
    const Vector u = random.direction();
    Vector e1, e2;
    plane_basis(u, e1, e2);
    double x = 0, y = 0, s = 0;
    random.disk(x, y, s);
    const Vector through = ((extent + 2 * r) * x) * e1 + ((extent + 2 * r) * y) * e2;
    double first = std::numeric_limits<double>::infinity();
    for (const Vector& c : xs) first = std::min(first, first_touch(through, u, c, 2 * r));
    if (std::isinf(first)) continue;
    xs.push_back(through + first * u);
    extent = std::max(extent, std::sqrt(dot(xs.back(), xs.back())));
  }
  return xs;
}

TEST(AggregateGrowth, BpcaCellListIsThePlainLoop) {
  const Aggregate a = build({Kind::bpca, 600, 2.5e-7, 42});
  std::vector<Vector> plain = plain_bpca(600, 2.5e-7, 42);
  Vector sum{0, 0, 0};
  for (const Vector& x : plain) sum = sum + x;
  for (Vector& x : plain) x = x - (1.0 / 600.0) * sum;  // build() centres the aggregate
  EXPECT_EQ(a.centres, plain);
}

TEST(AggregateGrowth, HistoryHoldsEveryNForBpcaAndEveryLevelForBcca) {
  const Aggregate p = build({Kind::bpca, 50, 1.0, 1});
  ASSERT_EQ(p.history.size(), 50u);
  EXPECT_EQ(p.history.back().n, 50u);
  EXPECT_NEAR(p.history.back().radius_of_gyration, radius_of_gyration(p.centres), 1e-12);
  EXPECT_DOUBLE_EQ(p.history[1].radius_of_gyration, 1.0);  // a dimer: each centre r from the middle
  const Aggregate c = build({Kind::bcca, 64, 1.0, 1});
  ASSERT_EQ(c.history.size(), 7u);  // n = 1, 2, 4, ..., 64
  EXPECT_EQ(c.history.back().n, 64u);
  EXPECT_NEAR(c.history.back().radius_of_gyration, radius_of_gyration(c.centres), 1e-12);
}

TEST(AggregateGrowth, BadRequestsAreRefusedNamingTheValue) {
  const auto message = [](const BuildRequest& r) {
    try {
      build(r);
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message({Kind::bcca, 1000, 1.0, 1}).rfind("n = 1000 is invalid: expected a power of 2", 0), 0u);
  EXPECT_EQ(message({Kind::bpca, 0, 1.0, 1}).rfind("n = 0 is invalid", 0), 0u);
  EXPECT_EQ(message({Kind::bpca, max_monomers + 1, 1.0, 1}).rfind("n = 131073 is invalid", 0), 0u);
  EXPECT_EQ(message({Kind::bpca, 10, -1.0, 1}).rfind("radius = -1 is invalid", 0), 0u);
  EXPECT_EQ(message({Kind::bpca, 10, std::numeric_limits<double>::quiet_NaN(), 1}).rfind("radius = nan is invalid", 0), 0u);
  EXPECT_EQ(message({Kind::bcca, 1, 1.0, 1}), "accepted");  // one monomer: an aggregate of one
}
