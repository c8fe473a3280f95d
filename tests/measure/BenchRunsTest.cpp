// The bench's measuring loops as a library: no terminal, no command line.

#include "measure/BenchRuns.h"

#include <algorithm>
#include <iterator>
#include <set>
#include <string>

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

// The grid on worker processes gives the points one process gives, in the
// same order, but for the timings: an analytic case (its error against the
// closed form) and a report example (against its reference run, made once
// in a worker and handed back).
TEST(BenchRuns, WorkersGiveTheSamePointsInTheSameOrder) {
  const auto points = [](int jobs) {
    std::vector<BenchScene> scenes;
    for (const char* file : {"/scenarios/analytic/free_flight.json", "/scenarios/example1_single_cube.json"}) {
      scenes.emplace_back(ScenarioLoader::loadFile(std::string(TABLETOP_SOURCE_DIR) + file));
    }
    const SweepGrid grid{{60.0, 120.0}, {10}, {Integrator::Trapezoid, Integrator::Euler}};
    long done = 0;
    MeasureHooks hooks;
    hooks.advance = [&done](const std::string&) { ++done; };
    std::map<std::string, std::vector<std::string>> skipped;
    auto out = measureSweep(scenes, grid, {SimulationMode::Bullet, SimulationMode::Rules}, 1, hooks, skipped, jobs);
    EXPECT_EQ(done, static_cast<long>(out.size())) << jobs;
    return out;
  };
  const std::vector<BenchPoint> one = points(1), two = points(2);
  ASSERT_EQ(one.size(), 10u);  // 4 settings each in full physics, example 1's 2 rates in the rules
  ASSERT_EQ(two.size(), one.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(two[i].scene, one[i].scene) << i;
    EXPECT_EQ(two[i].timestep, one[i].timestep) << i;
    EXPECT_EQ(two[i].iterations, one[i].iterations) << i;
    EXPECT_EQ(two[i].integrator, one[i].integrator) << i;
    EXPECT_EQ(two[i].mode, one[i].mode) << i;
    EXPECT_EQ(two[i].error, one[i].error) << i;
    EXPECT_EQ(two[i].complete, one[i].complete) << i;
    EXPECT_GT(two[i].costMs, 0.0) << i;
  }
  // The example's error is against a real reference run: not zero at 60 Hz.
  EXPECT_GT(one[4].error, 0.0);
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

Scenario hardCase(const std::string& name, double duration) {
  Scenario s = ScenarioLoader::loadFile(std::string(TABLETOP_SOURCE_DIR) + "/scenarios/hard/" + name + ".json");
  s.settings.duration = duration;
  return s;
}

// The lowest rate holding a drift: the one found holds it, the next lower
// one tried does not (or none is lower), for goals the 5 mm cube meets at
// different rates over 2 s; a stack of ten cubes holds MuJoCo's 0.7 mm
// down to the lowest rate tried; a case that moves more than the goal, or
// has no weight, gets none and its own run back untouched.
TEST(BenchRuns, FindsTheLowestRateThatHoldsADrift) {
  const Scenario tiny = hardCase("tiny_cube", 2.0);
  Settings own = tiny.settings;
  own.timestep = 1.0 / 60.0;
  Scenario at60 = tiny;
  at60.settings = own;
  const StabilityReport ownRun = probeStability(at60, own);
  std::set<double> found;  // Hz: the goals were chosen to be met at three different rates
  for (double goal : {5e-6, 1e-5, 3e-5}) {
    SCOPED_TRACE(goal);
    const DriftMatch m = lowestRateHolding(at60, ownRun, goal);
    ASSERT_GT(m.rate, 0.0);
    found.insert(m.rate);
    EXPECT_LE(m.report.worstDrift, goal);
    EXPECT_NEAR(1.0 / m.report.simulated * m.report.steps, m.rate, 1e-6 * m.rate);
    const double* lower = std::find_if(std::begin(kLowerRates), std::end(kLowerRates),
                                       [&](double r) { return r < m.rate * (1 - 1e-9); });
    if (lower != std::end(kLowerRates)) {
      Settings below = own;
      below.timestep = 1.0 / *lower;
      EXPECT_GT(probeStability(at60, below).worstDrift, goal) << *lower << " Hz held it too";
    }
  }
  EXPECT_EQ(found.size(), 3u);

  const Scenario stack = hardCase("tall_stack_10", 60.0);
  const DriftMatch held = lowestRateHolding(stack, probeStability(stack, stack.settings), kPeerDrift);
  EXPECT_EQ(held.rate, kLowerRates[std::size(kLowerRates) - 1]);
  EXPECT_LE(held.report.worstDrift, kPeerDrift);
  EXPECT_NEAR(held.report.simulated, 60.0, 1e-9);

  for (const char* name : {"fast_small_sphere", "free_rotation"}) {
    SCOPED_TRACE(name);
    const Scenario s = hardCase(name, 0.5);
    const DriftMatch none = lowestRateHolding(s, probeStability(s, s.settings), kPeerDrift);
    EXPECT_EQ(none.rate, 0.0);
  }
}

}  // namespace
}  // namespace tabletop
