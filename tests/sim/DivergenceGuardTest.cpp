// The divergence check: its bounds against the energy they follow from,
// and a run forced to diverge.

#include "sim/DivergenceGuard.h"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "scenario/ScenarioLoader.h"
#include "support/RunScene.h"

namespace tabletop {
namespace {

// A 1 kg cube of 0.1 m and a 4 kg sphere of radius 0.05 m.
Scenario twoBodies() {
  return ScenarioLoader::loadText(R"({"version": 1, "name": "two", "entities": [
      {"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1},
      {"name": "S", "shape": "sphere", "size": 0.05, "position": [0.3, 0], "mass": 4}]})",
                                  "two.json");
}

// The motion of the entity `name` (A first, S second, as in the scene).
BodyMotion at(const std::string& name, double y, Vec3 v = {}, Vec3 w = {}) {
  (void)name;
  BodyMotion s;
  s.position = {0.0, y, 0.0};
  s.linearVelocity = v;
  s.angularVelocity = w;
  return s;
}

// E = sum m g y over the bodies at the start (J); the speed bound is
// 2 sqrt(2 E / m_min) + 0.5 m/s, the angular bound that times sqrt(5) over
// r_min, with the slack, where r_min = 0.05 m (both bodies).
TEST(DivergenceGuard, BoundsFollowFromTheSceneEnergy) {
  const Scenario s = twoBodies();
  const DivergenceGuard g(s, s.settings, {at("A", 0.8), at("S", 0.8)});
  const double e = (1.0 + 4.0) * 9.81 * 0.8;
  EXPECT_NEAR(g.energyBound(), e, 1e-12);
  const double v = 2.0 * std::sqrt(2.0 * e / 1.0) + 0.5;
  EXPECT_NEAR(g.speedBound(), v, 1e-12);
  EXPECT_NEAR(g.angularSpeedBound(), (2.0 * std::sqrt(5.0) * std::sqrt(2.0 * e) + 0.5) / 0.05, 1e-9);

  EXPECT_NO_THROW(g.check({at("A", 0.8, {0.99 * v, 0, 0}), at("S", 0.8)}, 1.0));
  try {
    g.check({at("A", 0.8), at("S", 0.8, {0, 0, 1.01 * v})}, 1.25);
    FAIL() << "a speed above the bound passed";
  } catch (const DivergenceError& d) {
    EXPECT_EQ(d.entity(), "S");
    EXPECT_EQ(d.quantity(), "speed");
    EXPECT_DOUBLE_EQ(d.time(), 1.25);
    EXPECT_NE(std::string(d.what()).find("diverged at t = 1.25 s: entity 'S': speed"), std::string::npos)
        << d.what();
  }
  EXPECT_THROW(g.check({at("A", 0.8, {}, {0, 1.01 * g.angularSpeedBound(), 0}), at("S", 0.8)}, 1.0),
               DivergenceError);
}

TEST(DivergenceGuard, APushRaisesTheBoundByTheEnergyItGave) {
  const Scenario s = twoBodies();
  DivergenceGuard g(s, s.settings, {at("A", 0.8), at("S", 0.8)});
  const double before = g.energyBound();
  g.pushed({at("A", 0.8), at("S", 0.8)}, {at("A", 0.8, {30, 0, 0}), at("S", 0.8)});
  EXPECT_NEAR(g.energyBound() - before, 0.5 * 1.0 * 30.0 * 30.0, 1e-9);
  EXPECT_NO_THROW(g.check({at("A", 0.8, {30, 0, 0}), at("S", 0.8)}, 0.1));
}

TEST(DivergenceGuard, NonFiniteFarAndUnderTheFloorAreCaught) {
  const Scenario s = twoBodies();
  const DivergenceGuard g(s, s.settings, {at("A", 0.8), at("S", 0.8)});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto quantity = [&](const BodyMotion& a) {
    try {
      g.check({a, at("S", 0.8)}, 0.5);
    } catch (const DivergenceError& d) {
      return d.quantity();
    }
    return std::string("none");
  };
  EXPECT_EQ(quantity(at("A", nan)), "position");
  EXPECT_EQ(quantity(at("A", 0.8, {0, nan, 0})), "velocity");
  EXPECT_EQ(quantity(at("A", 0.8, {}, {nan, 0, 0})), "angular velocity");
  EXPECT_EQ(quantity(at("A", 2e5)), "position");
  // The cube's bounding radius is sqrt(3)/2 * 0.1 = 0.0866 m.
  EXPECT_EQ(quantity(at("A", -0.08)), "none");
  EXPECT_EQ(quantity(at("A", -0.09)), "position");
}

// An absurd impulse (1e6 N s on 0.1 g) at the largest timestep: the cube
// is 1e9 m away after one step. The run stops there, marked incomplete,
// with the state it had.
TEST(DivergenceGuard, AnAbsurdPushStopsTheRunIncomplete) {
  const Scenario s = ScenarioLoader::loadText(R"({"version": 1, "name": "absurd",
      "settings": {"timestep": 0.1, "duration": 5},
      "entities": [{"name": "A", "shape": "cube", "size": 0.01, "position": [0, 0], "mass": 0.0001}],
      "script": [{"push": {"entity": "A", "direction": "Left", "impulse": 1e6}}]})",
                                              "absurd.json");
  const RunResult r = test::runScene(s);
  EXPECT_FALSE(r.complete);
  EXPECT_EQ(r.steps, 1);
  EXPECT_NE(r.failure.find("entity 'A': position"), std::string::npos) << r.failure;
  EXPECT_NEAR(r.entities.at(0).position.x, 1e10 * 0.1, 1.0);
}

// The report's examples and every scenario the project ships stay well
// inside the bounds in every mode.
TEST(DivergenceGuard, ShippedScenariosNeverTripIt) {
  for (const char* name : {"example1_single_cube", "example2_two_cubes", "example3_stacked_cubes",
                           "example4_two_spheres", "misaligned_cubes", "sphere_bounces_back"}) {
    const Scenario s =
        ScenarioLoader::loadFile(std::string(TABLETOP_SOURCE_DIR) + "/scenarios/" + name + ".json");
    for (SimulationMode mode : kAllModes) {
      const RunResult r = test::runScene(s, mode);
      EXPECT_TRUE(r.complete) << name << " " << toString(mode) << ": " << r.failure;
    }
  }
}

}  // namespace
}  // namespace tabletop
