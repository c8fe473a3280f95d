#include "measure/Benchmark.h"

#include <cmath>

#include <gtest/gtest.h>

namespace tabletop {
namespace {

BenchPoint point(const char* scene, double cost, double error) {
  BenchPoint p;
  p.scene = scene;
  p.costMs = cost;
  p.error = error;
  return p;
}

// A point is on the front unless another of its scene is no worse in both
// cost and error and better in one; diverged runs are never on it.
TEST(Benchmark, ParetoFrontKeepsOnlyUnbeatenPoints) {
  std::vector<BenchPoint> p{point("a", 1, 10), point("a", 2, 5), point("a", 3, 5), point("a", 4, 1),
                            point("a", 0.5, 20), point("b", 9, 9), point("a", 5, 0.5)};
  p[6].complete = false;
  markParetoFronts(p);
  EXPECT_TRUE(p[0].front);
  EXPECT_TRUE(p[1].front);
  EXPECT_FALSE(p[2].front);  // as accurate as p[1], dearer
  EXPECT_TRUE(p[3].front);
  EXPECT_TRUE(p[4].front);
  EXPECT_TRUE(p[5].front);   // alone in its scene
  EXPECT_FALSE(p[6].front);  // diverged
}

// The growth exponent is the slope of log y on log x: exact for a power
// law (to 1e-12), the least-squares slope for a noisy one, NaN with one
// size.
TEST(Benchmark, GrowthExponentFitsAPowerLaw) {
  std::vector<double> x{10, 100, 1000, 10000}, y;
  for (double n : x) y.push_back(3.0 * std::pow(n, 1.5));
  EXPECT_NEAR(growthExponent(x, y), 1.5, 1e-12);
  // y = n times 2, 1/2, 2, 1/2: with u = log10 n - 2.5 = -1.5 .. 1.5 the
  // slope is 1 + sum(u e) / (sum(u^2) log 10), e = +-log 2, which is
  // 1 - 2 log 2 / (5 log 10) = 0.880.
  const std::vector<double> noisy{20, 50, 2000, 5000};
  EXPECT_NEAR(growthExponent(x, noisy), 1.0 - 2.0 * std::log(2.0) / (5.0 * std::log(10.0)), 1e-12);
  EXPECT_TRUE(std::isnan(growthExponent({10}, {1})));
}

}  // namespace
}  // namespace tabletop
