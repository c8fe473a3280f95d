// run --tolerance: the kinds of motion a scene holds, the choice from a
// front, the front file's errors, and the shipped front against the
// physics it was measured from.

#include "measure/ToleranceFront.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include <gtest/gtest.h>

#include "scenario/ScenarioError.h"
#include "scenario/ScenarioLoader.h"
#include "measure/AnalyticCase.h"
#include "support/TempFiles.h"

namespace tabletop {
namespace {

const std::string kScenarios = std::string(TABLETOP_SOURCE_DIR) + "/scenarios/";
const std::string kData = std::string(TABLETOP_SOURCE_DIR) + "/data/";

BenchPoint point(const char* scene, double rate, int iterations, double cost, double error) {
  BenchPoint p;
  p.scene = scene;
  p.timestep = 1.0 / rate;
  p.iterations = iterations;
  p.costMs = cost;
  p.error = error;
  return p;
}

bool has(const std::vector<std::string>& v, const std::string& x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

TEST(ToleranceFront, MotionsFollowTheSceneShapesAndStacking) {
  const auto m1 = motionsOf(ScenarioLoader::loadFile(kScenarios + "example1_single_cube.json"));
  EXPECT_TRUE(has(m1, "sliding") && has(m1, "leaving the table") && has(m1, "flight"));
  EXPECT_FALSE(has(m1, "rolling") || has(m1, "collision") || has(m1, "stacking"));
  const auto m3 = motionsOf(ScenarioLoader::loadFile(kScenarios + "example3_stacked_cubes.json"));
  EXPECT_TRUE(has(m3, "stacking") && has(m3, "collision"));
  const auto m4 = motionsOf(ScenarioLoader::loadFile(kScenarios + "example4_two_spheres.json"));
  EXPECT_TRUE(has(m4, "rolling") && has(m4, "collision"));
  EXPECT_FALSE(has(m4, "sliding"));
}

// Each motion takes its cheapest front point within the tolerance; the
// scene gets the finest timestep and the most iterations of those. A
// motion no point reaches is reported and takes its most accurate point.
TEST(ToleranceFront, ChoosesTheCheapestSettingsMeetingTheTolerancePerMotion) {
  const ToleranceFront front = ToleranceFront::fromBench(
      {point("cube_slides_to_rest", 60, 4, 0.1, 2e-3), point("cube_slides_to_rest", 240, 10, 0.4, 1e-4),
       point("free_flight", 30, 4, 0.05, 0.0), point("projectile_off_the_edge", 120, 20, 0.3, 5e-4),
       point("projectile_off_the_edge", 1000, 20, 3.0, 1e-5), point("projectile_off_the_edge", 2000, 50, 9.0, 2e-5)});
  EXPECT_EQ(front.cases().at("projectile_off_the_edge").size(), 2u);  // the 2000 Hz point is beaten
  const Scenario cube = ScenarioLoader::loadFile(kScenarios + "analytic/cube_slides_to_rest.json");
  ToleranceChoice c = front.choose(cube, 1e-3);
  EXPECT_TRUE(c.met);
  EXPECT_DOUBLE_EQ(c.settings.timestep, 1.0 / 240);  // sliding needs 240 Hz, leaving the table 120 Hz
  EXPECT_EQ(c.settings.iterations, 20);             // leaving the table needs 20
  EXPECT_EQ(c.reasons.size(), 3u);                  // flight, leaving the table, sliding
  EXPECT_EQ(c.settings.integrator, Integrator::Trapezoid);
  c = front.choose(cube, 1e-6);
  EXPECT_FALSE(c.met);
  EXPECT_DOUBLE_EQ(c.settings.timestep, 1.0 / 1000);
  EXPECT_EQ(cube.settings.duration, c.settings.duration);
}

TEST(ToleranceFront, ABadFrontFileIsOneLineNamingFileAndPlace) {
  const std::string file = ::tabletop::testing::tempDir() + "bad_front.json";
  std::ofstream(file) << R"({"version": 1, "cases": {"free_flight": {"front": [{"timestep": 0.01,
      "iterations": 10, "integrator": "midpoint", "cost_ms_per_s": 0.1, "error_m": 0}]}}})";
  try {
    ToleranceFront::load(file);
    FAIL() << "accepted a bad integrator";
  } catch (const ScenarioError& e) {
    ASSERT_EQ(e.lines().size(), 1u);
    EXPECT_NE(e.lines()[0].find(file), std::string::npos) << e.lines()[0];
    EXPECT_NE(e.lines()[0].find("/cases/free_flight/front/0/integrator"), std::string::npos) << e.lines()[0];
  }
  EXPECT_THROW(ToleranceFront::load(::tabletop::testing::tempDir() + "no_such_front.json"), ScenarioError);
}

// The shipped front holds every analytic case, and each of its errors is
// what the physics gives at that setting today (the double build is
// deterministic), to 1 nm: when the physics changes, regenerate it with
// `tabletop bench --modes bullet --write-front data/tolerance_front.json`.
TEST(ToleranceFront, TheShippedFrontMatchesThePhysics) {
#ifndef BT_USE_DOUBLE_PRECISION
  GTEST_SKIP() << "the shipped front is measured with the double-precision build";
#endif
  const ToleranceFront front = ToleranceFront::load(kData + "tolerance_front.json");
  for (const std::string& name : AnalyticCase::names()) {
    ASSERT_TRUE(front.cases().count(name)) << name;
    const Scenario s = ScenarioLoader::loadFile(kScenarios + "analytic/" + name + ".json");
    for (const ToleranceFront::Point& p : front.cases().at(name)) {
      Settings settings = s.settings;
      settings.timestep = p.timestep;
      settings.iterations = p.iterations;
      settings.integrator = p.integrator;
      const double error = AnalyticCase::forScenario(s)->run(s, settings, SimulationMode::Bullet).positionError;
      EXPECT_NEAR(error, p.error, 1e-9) << name << " at " << 1.0 / p.timestep << " Hz, " << p.iterations
                                        << " iterations, " << toString(p.integrator);
    }
  }
}

}  // namespace
}  // namespace tabletop
