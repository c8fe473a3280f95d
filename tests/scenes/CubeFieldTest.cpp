// The scale scene: its layout, and that it builds and runs at every size.

#include "scenes/CubeField.h"

#include <cmath>

#include <gtest/gtest.h>

#include "support/RunScene.h"

namespace tabletop {
namespace {

// n cubes, every other column pushed, all on a table that holds them; the
// push is longer than the gap, so the pushed cubes strike their neighbours.
TEST(CubeField, LaysOutNCubesAndPushesEveryOtherColumn) {
  for (int n : {1, 2, 7, 16, 100}) {
    const Scenario s = CubeField::make(n);
    ASSERT_EQ(static_cast<int>(s.entities.size()), n);
    const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
    int pushed = 0;
    for (int i = 0; i < n; ++i) pushed += (i % columns) % 2 == 0;
    EXPECT_EQ(static_cast<int>(s.script.size()), pushed) << n;
    for (const EntitySpec& e : s.entities) {
      EXPECT_LT(std::abs(e.position.x) + CubeField::kSide, 0.5 * s.table.width) << e.name;
      EXPECT_LT(std::abs(e.position.z) + CubeField::kSide, 0.5 * s.table.depth) << e.name;
    }
  }
  EXPECT_GT(CubeField::kStep, CubeField::kPitch - CubeField::kSide);
}

// It builds without overlaps and runs its fixed duration at the defaults:
// exactly kDuration / dt steps, and the first pushed cube has moved on.
TEST(CubeField, RunsItsFixedDuration) {
  const Scenario s = CubeField::make(16);
  const RunResult r = test::runScene(s);
  EXPECT_TRUE(r.complete);
  EXPECT_EQ(r.steps, std::lround(CubeField::kDuration / s.settings.timestep));
  EXPECT_GT(r.entities[0].position.x - s.entities[0].position.x, 0.1);  // m
}

}  // namespace
}  // namespace tabletop
