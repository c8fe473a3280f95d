// The bench's measuring loops as a library: no terminal, no command line.

#include "measure/BenchRuns.h"

#include <gtest/gtest.h>

#include "scenario/ScenarioLoader.h"

namespace tabletop {
namespace {

// One point per setting of the grid in full physics; the rules' modes are
// skipped with their reason (free flight starts with an impulse); the
// analytic error of free flight is the trapezoid's zero; a stop ends the
// sweep at once; the hooks hear of every unit.
TEST(BenchRuns, SweepsTheGridAndStopsWhenAsked) {
  std::vector<BenchScene> scenes;
  scenes.emplace_back(ScenarioLoader::loadFile(std::string(TABLETOP_SOURCE_DIR) + "/scenarios/analytic/free_flight.json"));
  const SweepGrid grid{{60.0, 240.0}, {10}, {Integrator::Trapezoid, Integrator::Euler}};
  long total = 0, done = 0;
  MeasureHooks hooks;
  hooks.start = [&](long n) { total = n; };
  hooks.advance = [&](const std::string&) { ++done; };
  std::map<std::string, std::vector<std::string>> skipped;
  const auto points = measureSweep(scenes, grid, {SimulationMode::Bullet, SimulationMode::Rules}, 1, hooks, skipped);
  ASSERT_EQ(points.size(), 4u);
  EXPECT_EQ(total, 4);
  EXPECT_EQ(done, 4);
  EXPECT_EQ(skipped["free_flight"].size(), 1u);
  for (const BenchPoint& p : points) {
    if (p.integrator == Integrator::Trapezoid) {
      EXPECT_LT(p.error, 1e-9) << 1.0 / p.timestep;
    } else {
      EXPECT_GT(p.error, 1e-3) << 1.0 / p.timestep;
    }
  }
  hooks.stop = [] { return true; };
  EXPECT_TRUE(measureSweep(scenes, grid, {SimulationMode::Bullet}, 1, hooks, skipped).empty());
}

// The baseline times the scene both ways over tabletop's own run (free
// flight never rests: its whole 0.4 s), a point per scene and rate.
TEST(BenchRuns, TimesEachSceneAgainstBulletsOwnPipeline) {
  std::vector<BenchScene> scenes;
  scenes.emplace_back(ScenarioLoader::loadFile(std::string(TABLETOP_SOURCE_DIR) + "/scenarios/analytic/free_flight.json"));
  const auto points = measureBaseline(scenes, {60.0, 240.0}, 1, MeasureHooks{});
  ASSERT_EQ(points.size(), 2u);
  for (const BaselinePoint& p : points) {
    EXPECT_EQ(p.scene, "free_flight");
    EXPECT_NEAR(p.simulated, 0.4, 1.0 / p.rate) << p.rate;
    EXPECT_GT(p.tabletopMs, 0.0);
    EXPECT_GT(p.bulletMs, 0.0);
  }
}

}  // namespace
}  // namespace tabletop
