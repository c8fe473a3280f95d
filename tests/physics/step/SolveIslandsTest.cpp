// Islands on every thread (step/SolveIslands.cpp): a scene stepped with
// its islands shared among 2, 3 or 5 threads ends, step by step, in the
// same state to the bit as stepped on one; also with kinematic bodies,
// which islands share, and with the solver counts summed alike.

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/StateHash.h"
#include "physics/World.h"
#include "physics/shapes/Cube.h"
#include "physics/shapes/Cylinder.h"
#include "physics/shapes/SolidBox.h"
#include "physics/shapes/Sphere.h"
#include "support/TestName.h"

namespace tabletop {
namespace {

constexpr double kRate = 60.0;  // Hz, the default scenes' rate

// A heap of `n` mixed bodies (cubes, balls, boxes, standing cylinders and
// cones, sizes from `seed`) dropped in a grid 2 cm apart onto the table,
// so that they land, collide and settle in many islands; with `kinematic`
// every fifth body held still as a kinematic body.
std::unique_ptr<World> heap(int n, std::uint64_t seed, int threads, bool kinematic) {
  Settings s;
  s.timestep = 1.0 / kRate;
  s.threads = threads;
  auto w = std::make_unique<World>(s, TableSpec{});
  std::mt19937_64 words(seed);
  const auto draw = [&words](double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(words() >> 11) * 0x1.0p-53;
  };
  const double top = w->table().spec().height;
  for (int i = 0; i < n; ++i) {
    const std::string name = "b" + std::to_string(i);
    const double size = draw(0.03, 0.07);
    const btVector3 at(-0.45 + 0.09 * (i % 10), top + 0.05 + 0.09 * (i / 30), -0.25 + 0.09 * ((i / 10) % 3));
    const Material material{draw(0.2, 0.6), 0.001, 0.001, draw(0.0, 0.5)};
    std::unique_ptr<Shape> shape;
    switch (i % 5) {
      case 0: shape = std::make_unique<Cube>(name, size); break;
      case 1: shape = std::make_unique<Sphere>(name, size / 2); break;
      case 2: shape = std::make_unique<SolidBox>(name, size, size / 2, size * 0.8); break;
      case 3: shape = std::make_unique<Cylinder>(name, size / 2, size / 2, size); break;
      default: shape = std::make_unique<Cylinder>(name, size / 2, 0.0, size); break;
    }
    w->addEntity(std::move(shape), draw(0.05, 1.0), material, at, draw(0.0, 90.0));
    if (kinematic && i % 5 == 0) w->makeKinematic(static_cast<std::size_t>(i));
  }
  return w;
}

struct Case {
  int bodies;
  std::uint64_t seed;
  bool kinematic;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.bodies << " bodies, seed " << c.seed << (c.kinematic ? ", kinematic" : "");
}

class SolveIslands : public ::testing::TestWithParam<Case> {};

TEST_P(SolveIslands, AnyThreadCountEndsToTheBit) {
  const Case& c = GetParam();
  constexpr int kSteps = 90;  // 1.5 s: the drop, the landings, the settling
  std::vector<std::uint64_t> one;
  {
    const auto w = heap(c.bodies, c.seed, 1, c.kinematic);
    for (int k = 0; k < kSteps; ++k) {
      w->step();
      one.push_back(stateHash(w->snapshot()));
    }
  }
  for (const int threads : {2, 3, 5}) {
    const auto w = heap(c.bodies, c.seed, threads, c.kinematic);
    for (int k = 0; k < kSteps; ++k) {
      w->step();
      ASSERT_EQ(stateHash(w->snapshot()), one[static_cast<std::size_t>(k)])
          << threads << " threads: step " << k + 1 << " differs from one thread's";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Heaps, SolveIslands,
                         ::testing::Values(Case{30, 1, false}, Case{60, 2, false}, Case{75, 3, false},
                                           Case{60, 4, true}),
                         [](const ::testing::TestParamInfo<Case>& p) {
                           const Case& c = p.param;
                           return test::testName({std::to_string(c.bodies) + "_bodies",
                                                  "seed_" + std::to_string(c.seed),
                                                  c.kinematic ? "kinematic" : "dynamic"});
                         });

// The solver's counts are the same however the islands were shared out.
TEST(SolveIslandsCounts, AreSummedAsOnOneThread) {
  const auto count = [](int threads) {
    const auto w = heap(60, 7, threads, false);
    for (int k = 0; k < 60; ++k) w->step();
    return std::make_pair(w->solverUse(), w->work());
  };
  const auto [one, oneWork] = count(1);
  const auto [two, twoWork] = count(2);
  EXPECT_GT(one.direct + one.swept, 0);
  EXPECT_EQ(two.direct, one.direct);
  EXPECT_EQ(two.guessed, one.guessed);
  EXPECT_EQ(two.swept, one.swept);
  EXPECT_EQ(two.longSwept, one.longSwept);
  EXPECT_EQ(two.fallbacks, one.fallbacks);
  EXPECT_EQ(two.largestIsland, one.largestIsland);
  EXPECT_EQ(two.parts, one.parts);
  EXPECT_EQ(twoWork.sweptRows, oneWork.sweptRows);
  EXPECT_EQ(twoWork.pivotedRows, oneWork.pivotedRows);
}

}  // namespace
}  // namespace tabletop
