// A rider resting on a cube, the two dropped together from a few
// millimetres to a few centimetres onto the table or the floor: the cube
// lands and stops at once, and so does the rider on it. The rider must not
// go into the cube by more than 1 um at any step (GJK's depth between the
// two shapes; measured: 11 nm at most, 30 Hz). Over riders (a cube, a box, a cylinder, a truncated cone
// on its base), supports, drop heights and rates (30 Hz to 1 kHz).
//
// A body an impact stops moves by its end velocity over the part, not by
// the mean of its start and end velocities (DynamicsWorld), as it stops at
// once. The rider was moved by the mean whenever its own change of speed
// was below what the forces can give in a part (DynamicsWorld::stopSpeed's
// limit, about 0.37 m/s at 60 Hz): it went on at its falling speed for half
// the part, into the cube. Dropped 5 mm at 60 Hz, a 5 cm cube sank 1.6 mm
// into a 0.1 m cube, 0.9 mm from 2 mm. Now a body resting on one an impact
// stops, whose touching points' normal speed changed at once, stops with
// it (DynamicsWorld::spreadStops).

#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/ShapeGeometry.h"
#include "scenario/ScenarioLoader.h"
#include "support/DeepestOverlap.h"
#include "support/TestName.h"

namespace tabletop {
namespace {

constexpr double kDepthTolerance = 1e-6;  // m
constexpr double kBaseSize = 0.1;         // m, the cube the rider rests on

struct Drop {
  const char* shape;  // the rider's, as a scenario names it
  const char* size;   // its "size" in the scenario
  double height;      // its centre above its base, m
  bool floor;         // on the floor (else the table)
  double drop;        // m, from the cube's base to the support
  double rate;        // Hz
};

std::string describe(const Drop& c) {
  char text[256];
  std::snprintf(text, sizeof text, "%s %s on a %g m cube, dropped %g mm onto the %s at %g Hz", c.shape, c.size,
                kBaseSize, c.drop * 1e3, c.floor ? "floor" : "table", c.rate);
  return text;
}

void PrintTo(const Drop& c, std::ostream* out) { *out << describe(c); }

Scenario dropScene(const Drop& c) {
  const double support = c.floor ? 0.0 : 0.75;
  const double x = c.floor ? 1.2 : 0.0;  // the floor's point well clear of the table
  const double base = support + c.drop + kBaseSize / 2;
  char text[1024];
  std::snprintf(text, sizeof text,
                R"({"version": 1, "name": "stack_drop", "settings": {"timestep": %.17g, "duration": 0.5,
                    "end_at_rest": false}, "entities": [
                    {"name": "Base", "shape": "cube", "size": %g, "position": [%g, %.17g, 0.0], "mass": 1.0},
                    {"name": "Rider", "shape": "%s", "size": %s, "position": [%g, %.17g, 0.0], "mass": 0.3}]})",
                1.0 / c.rate, kBaseSize, x, base, c.shape, c.size, x, base + kBaseSize / 2 + c.height);
  return ScenarioLoader::loadText(text, "stack_drop.json");
}

class StackLanding : public testing::TestWithParam<Drop> {};

TEST_P(StackLanding, TheRiderStopsWithItsBase) {
  const Drop c = GetParam();
  const Scenario s = dropScene(c);
  const test::Overlap o = test::deepestOverlap(s, 1, 0);  // the rider into its base
  ASSERT_TRUE(o.report.complete) << describe(c) << ": " << o.report.failure;
  EXPECT_LE(o.deepest, kDepthTolerance) << describe(c) << ": " << o.deepest * 1e3 << " mm deep at t = " << o.at << " s";
}

std::vector<Drop> cases() {
  struct Rider {
    const char* shape;
    const char* size;
    double height;  // centre above its base, m
  };
  const Rider riders[] = {{"cube", "0.05", 0.025},
                          {"box", "[0.08, 0.03, 0.06]", 0.015},
                          {"cylinder", "[0.03, 0.03, 0.05]", 0.025},
                          {"cylinder", "[0.03, 0.02, 0.05]",
                           ShapeGeometry::cylinder(0.03, 0.02, 0.05).centroidHeight()}};
  std::vector<Drop> all;
  for (const Rider& rider : riders) {
    for (const bool floor : {false, true}) {
      for (const double drop : {0.002, 0.005, 0.02}) {
        for (const double rate : {30.0, 60.0, 240.0, 1000.0}) {
          all.push_back({rider.shape, rider.size, rider.height, floor, drop, rate});
        }
      }
    }
  }
  return all;
}

// box_0p08_0p03_0p06_floor_drop5mm_240Hz
std::string name(const testing::TestParamInfo<Drop>& p) {
  const Drop& c = p.param;
  return test::testName({c.shape, c.size, c.floor ? "floor" : "table", "drop" + test::number(c.drop * 1e3) + "mm",
                         test::number(c.rate) + "Hz"});
}

INSTANTIATE_TEST_SUITE_P(RidersDroppedWithTheirBase, StackLanding, testing::ValuesIn(cases()), name);

}  // namespace
}  // namespace tabletop
