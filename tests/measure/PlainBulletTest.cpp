// The yardstick really runs the scene: in Bullet's own pipeline the
// analytic sliding cube is pushed and slides to rest near v0^2 / (2 mu g)
// (Bullet's Euler steps and 0.85 warm start leave it a few percent short:
// within 10%), and stays on the table.

#include "measure/PlainBullet.h"

#include <cmath>

#include <gtest/gtest.h>

#include "scenario/ScenarioLoader.h"

namespace tabletop {
namespace {

TEST(PlainBullet, SlidesTheAnalyticCubeNearItsClosedForm) {
  const Scenario s =
      ScenarioLoader::loadFile(std::string(TABLETOP_SOURCE_DIR) + "/scenarios/analytic/cube_slides_to_rest.json");
  const double v0 = 2.0, mu = 0.25, g = 9.81, expected = v0 * v0 / (2 * mu * g);  // the scene's own numbers
  for (const double rate : {60.0, 240.0}) {
    const PlainRun r = runPlainBullet(s, 1.0 / rate, 3.0, 1);
    ASSERT_EQ(r.centres.size(), 1u);
    const double travelled = r.centres[0].x - s.entities[0].position.x;
    EXPECT_NEAR(travelled, expected, 0.1 * expected) << rate << " Hz";
    EXPECT_NEAR(r.centres[0].y, s.table.height + 0.05, 1e-3) << rate << " Hz";
    EXPECT_GT(r.costMsPerSecond, 0.0);
  }
}

}  // namespace
}  // namespace tabletop
