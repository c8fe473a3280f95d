#include "sim/Benchmark.h"

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

}  // namespace
}  // namespace tabletop
