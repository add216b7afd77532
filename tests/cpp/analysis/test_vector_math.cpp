// The atlas batch's vector logarithms and exponentials (analysis/vector_math.hpp) against
// std::log and std::exp.
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "analysis/vector_math.hpp"

namespace {

using bounce::analysis::vector_exp;
using bounce::analysis::vector_log;

// glibc's manual bounds libmvec's log and exp within 4 ulp of the exact value; std::log and
// std::exp are within 1, so 5 ulp apart at most.
double ulps_apart(double a, double b) { return std::abs(a - b) / (std::numeric_limits<double>::epsilon() * std::abs(b)); }

TEST(VectorMath, LogarithmsAndExponentialsAreThoseOfStdWithinFiveUlp) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> exponent(-300.0, 300.0);
  for (std::size_t n : {0, 1, 2, 3, 4, 5, 7, 32, 1001}) {  // every tail length of 2 and 4 lanes
    std::vector<double> x(n), logs, exps(n);
    for (double& v : x) v = std::pow(10.0, exponent(rng));
    logs = x;
    vector_log(logs.data(), n);
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_LE(ulps_apart(logs[i], std::log(x[i])), 5.0) << x[i];
      exps[i] = std::log(x[i]) * 0.99;  // arguments inside exp's finite range
    }
    std::vector<double> expected(exps);
    vector_exp(exps.data(), n);
    for (std::size_t i = 0; i < n; ++i) EXPECT_LE(ulps_apart(exps[i], std::exp(expected[i])), 5.0) << expected[i];
  }
}

TEST(VectorMath, EdgeValuesAreThoseOfStd) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  double logs[] = {0.0, 1.0, inf, -1.0, nan};
  vector_log(logs, 5);
  EXPECT_EQ(logs[0], -inf);
  EXPECT_EQ(logs[1], 0.0);
  EXPECT_EQ(logs[2], inf);
  EXPECT_TRUE(std::isnan(logs[3]) && std::isnan(logs[4]));
  double exps[] = {-inf, 0.0, 1000.0, -1000.0, nan};
  vector_exp(exps, 5);
  EXPECT_EQ(exps[0], 0.0);
  EXPECT_EQ(exps[1], 1.0);
  EXPECT_EQ(exps[2], inf);
  EXPECT_EQ(exps[3], 0.0);
  EXPECT_TRUE(std::isnan(exps[4]));
}

// A value's logarithm is the same wherever it stands in the array (a tail goes through the same
// vector function), so a batched lookup does not depend on its neighbours.
TEST(VectorMath, AValueGetsTheSameLogarithmAtEveryPosition) {
  for (std::size_t n = 1; n <= 9; ++n) {
    std::vector<double> x(n, 3.7e-6);
    vector_log(x.data(), n);
    double one = 3.7e-6;
    vector_log(&one, 1);
    for (double v : x) EXPECT_EQ(v, one) << n;
  }
}

}  // namespace
