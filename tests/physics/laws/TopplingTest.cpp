// A tall box or cylinder set turning about a horizontal axis through its
// centre topples and lands on a side: the support holds it out at every
// step (its lowest point never more than 0.1 mm under the table top or the
// floor; see tolerated() for a cylinder at 60 Hz), and it comes to rest on
// that side (a box lying flat, its centre that face's half extent above
// the support, within 0.1 mm; a cylinder on its rims). Over box and
// cylinder shapes (truncated cones both ways up) x support (table, floor)
// x the axis it turns about x rate (60, 240 and 1000 Hz). At 30 Hz a box's
// landing corner goes 0.11 to 0.25 mm deep: it swings on an arc inside the
// step, and the step's contact closes on a straight line.
//
// Before a corner closing on the support counted as on it (CornerChoice),
// the far corners of a falling box, swinging down through the band of
// corners taken as the face, were found only once they were under it:
// eight of the box cases sank 1.0 to 6.3 mm at 60 and 240 Hz. Before each
// end's lowest corner was kept and Bullet's full manifold could no longer
// drop a chosen corner, the cylinders' landing ends sank 3 to 15 mm.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/Simulation.h"
#include "physics/collision/SolidCorners.h"
#include "physics/World.h"
#include "scenario/ScenarioLoader.h"
#include "sim/SceneBuilder.h"
#include "support/TestName.h"

namespace tabletop {
namespace {

constexpr double kTolerance = 1e-4;  // m
constexpr double kDuration = 2.0;    // s: every case has toppled and settled by then

struct Topple {
  const char* shape;  // "box" or "cylinder"
  double size[3];   // box: x, y (up at the start), z; cylinder: base and top radii, height: m
  double spin[3];   // rad/s, world frame
  bool onTable;
  double rate;      // Hz
};

std::string describe(const Topple& c) {
  char text[160];
  std::snprintf(text, sizeof text, "%s [%g, %g, %g] spun [%g, %g, %g] on the %s at %g Hz", c.shape, c.size[0], c.size[1],
                c.size[2], c.spin[0], c.spin[1], c.spin[2], c.onTable ? "table" : "floor", c.rate);
  return text;
}

Scenario toppleScene(const Topple& c) {
  char text[512];
  std::snprintf(text, sizeof text,
                R"({"version": 1, "name": "topple", "settings": {"timestep": %.17g, "duration": %g,
                    "end_at_rest": false}, "entities": [{"name": "A", "shape": "%s", "size": [%g, %g, %g],
                    "position": [%g, 0.0], "on": "%s", "mass": 1.0, "spin": [%g, %g, %g]}]})",
                1.0 / c.rate, kDuration, c.shape, c.size[0], c.size[1], c.size[2], c.onTable ? 0.0 : 3.0,
                c.onTable ? "table" : "ground", c.spin[0], c.spin[1], c.spin[2]);
  return ScenarioLoader::loadText(text, "topple.json");
}

// How far the body's lowest corner is under the support, m: a box's
// corner, or the lowest point of a cylinder's rims (solidCorners puts it
// first on each rim).
double depthUnder(const Shape& body, double support) {
  const btTransform& pose = body.body()->getWorldTransform();
  const auto& solid = static_cast<const btConvexShape&>(body.collisionShape());
  double lowest = BT_LARGE_FLOAT;
  for (const btVector3& corner : solidCorners(solid, pose.getBasis().transpose() * btVector3(0, -1, 0))) {
    lowest = std::min(lowest, double((pose * corner).y()));
  }
  return support - lowest;
}

// How deep the lowest corner may go, m. A cylinder rolling on its rims at
// 60 Hz goes 0.08 to 0.26 mm under (0.02 to 0.05 mm at 240 Hz, 0.01 mm at
// 1 kHz: it converges with the step). Before a body whose rows are held at
// the mean also turned by its mean rate (DynamicsWorld), 0.11 to 0.51 mm.
// These depths, and the boxes' 0.1 mm at 60 Hz, hold at the shipped
// rounding: a change at the rounding level took a cone to 0.54 mm and the
// box spun about a diagonal to 0.31 mm (docs/bullet-corrections.md,
// "Left", with the box's cause traced).
double tolerated(const Topple& c) {
  return std::string(c.shape) == "cylinder" && c.rate < 100 ? 3e-4 : kTolerance;
}

class Toppling : public testing::TestWithParam<Topple> {};

TEST_P(Toppling, LandsOnASideWithoutSinking) {
  const Topple c = GetParam();
  const Scenario s = toppleScene(c);
  std::unique_ptr<Simulation> sim = buildSimulation(s, s.settings, SimulationMode::Bullet);
  const auto& world = dynamic_cast<const World&>(*sim);
  const double support = c.onTable ? world.table().spec().height : 0.0;
  const Shape& body = *world.entities().at(0);
  double deepest = 0.0, deepestAt = 0.0;
  while (sim->time() + 0.5 / c.rate < kDuration) {
    sim->step();
    const double below = depthUnder(body, support);
    if (below > deepest) deepest = below, deepestAt = sim->time();
  }
  const double tolerance = tolerated(c);
  EXPECT_LE(deepest, tolerance) << describe(c) << ": " << deepest * 1e3 << " mm deep at t = " << deepestAt << " s";
  const btMatrix3x3& basis = body.body()->getWorldTransform().getBasis();
  if (std::string(c.shape) == "cylinder") {
    // Toppled onto its side (the axis nearer level than upright) and
    // resting on the support: a rim face or corner on it.
    EXPECT_LT(std::abs(basis.getColumn(1).y()), 0.5) << describe(c) << ": did not topple";
    EXPECT_NEAR(depthUnder(body, support), 0.0, tolerance) << describe(c);
    return;
  }
  // At rest on the face that ends down: the body axis nearest the vertical
  // is that face's normal, and the centre is its half extent up.
  int up = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(basis.getColumn(k).y()) > std::abs(basis.getColumn(up).y())) up = k;
  }
  ASSERT_GT(std::abs(basis.getColumn(up).y()), 1 - 1e-6) << describe(c) << ": not lying flat";
  EXPECT_NE(up, 1) << describe(c) << ": did not topple";
  EXPECT_NEAR(body.position().y() - support, 0.5 * c.size[up], kTolerance) << describe(c);
}

std::vector<Topple> cases() {
  const struct {
    const char* shape;
    double size[3];
    double spin[3];
  } bodies[] = {{"box", {0.05, 0.2, 0.05}, {0, 0, 14}},
                {"box", {0.03, 0.3, 0.1}, {0, 0, 14}},
                {"box", {0.08, 0.24, 0.05}, {10, 0, 0}},
                {"box", {0.06, 0.18, 0.06}, {12, 0, -12}},
                {"cylinder", {0.04, 0.04, 0.2}, {0, 0, 14}},
                {"cylinder", {0.0355, 0.021, 0.1921}, {0, 0, 14}},   // narrower at the top
                {"cylinder", {0.03, 0.05, 0.15}, {14, 0, 0}},         // wider at the top
                {"cylinder", {0.035, 0.035, 0.16}, {12, 0, -12}}};
  std::vector<Topple> all;
  for (const auto& b : bodies) {
    for (const bool onTable : {true, false}) {
      for (const double rate : {60.0, 240.0, 1000.0}) {
        all.push_back({b.shape, {b.size[0], b.size[1], b.size[2]}, {b.spin[0], b.spin[1], b.spin[2]}, onTable, rate});
      }
    }
  }
  return all;
}

// box_0p05_0p2_0p05_spin_0_0_14_table_60Hz
std::string name(const testing::TestParamInfo<Topple>& p) {
  const Topple& c = p.param;
  return test::testName({c.shape, test::numbers({c.size[0], c.size[1], c.size[2]}), "spin",
                         test::numbers({c.spin[0], c.spin[1], c.spin[2]}), c.onTable ? "table" : "floor",
                         test::number(c.rate) + "Hz"});
}

INSTANTIATE_TEST_SUITE_P(BoxesAndCylindersOnTableAndFloor, Toppling, testing::ValuesIn(cases()), name);

}  // namespace
}  // namespace tabletop
