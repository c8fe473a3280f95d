// The work limit of a run (ScriptPlayer, WorkCount): counted where the cost
// is, the same on every run, and a located refusal once passed.

#include "sim/ScriptPlayer.h"

#include <string>

#include <gtest/gtest.h>

#include "scenario/ScenarioError.h"
#include "scenario/ScenarioLoader.h"
#include "sim/SceneBuilder.h"

namespace tabletop {
namespace {

// A tower of `n` cubes of `side` m, 0.01 kg each, standing for `seconds`.
Scenario tower(int n, double side, double seconds) {
  std::string entities;
  for (int i = 0; i < n; ++i) {
    if (i > 0) entities += ",\n";
    entities += R"({"name": "C)" + std::to_string(i) + R"(", "shape": "cube", "size": )" + std::to_string(side) +
                R"(, "position": [0, 0], "mass": 0.01, "on": )" +
                (i == 0 ? std::string("\"table\"") : "\"C" + std::to_string(i - 1) + "\"") + "}";
  }
  return ScenarioLoader::loadText(R"({"version": 1, "name": "tower",
      "settings": {"duration": )" + std::to_string(seconds) + R"(, "end_at_rest": false},
      "entities": [)" + entities + "]}",
                                  "tower.json");
}

WorkCount workOf(const Scenario& s, SimulationMode mode) {
  auto sim = buildSimulation(s, s.settings, mode);
  ScriptPlayer player(s, s.settings, *sim);
  player.runToEnd();
  return sim->work();
}

// The count is of what the run does: the same on every run, and growing
// with the bodies. In full physics each body in contact adds contacts to
// one island, so a tower of 2N cubes does more than twice the work of N;
// compat keeps resting bodies out of the solver, and its count is linear.
TEST(WorkLimit, TheCountIsTheSameOnEveryRunAndGrowsWithTheBodies) {
  for (const SimulationMode mode : {SimulationMode::Bullet, SimulationMode::Compat, SimulationMode::Rules}) {
    const WorkCount a = workOf(tower(5, 0.05, 0.5), mode);
    const WorkCount b = workOf(tower(5, 0.05, 0.5), mode);
    const WorkCount c = workOf(tower(10, 0.05, 0.5), mode);
    EXPECT_EQ(a.units(), b.units()) << toString(mode);
    EXPECT_GT(a.units(), 0.0) << toString(mode);
    EXPECT_GT(c.units(), (mode == SimulationMode::Bullet ? 2.0 : 1.0) * a.units()) << toString(mode);
  }
  const WorkCount bullet = workOf(tower(5, 0.05, 0.5), SimulationMode::Bullet);
  EXPECT_GT(bullet.contactPoints, 0.0);
  EXPECT_GT(bullet.pairs, 0.0);
  const WorkCount rules = workOf(tower(5, 0.05, 0.5), SimulationMode::Rules);
  EXPECT_GT(rules.ruleChecks, 0.0);
  EXPECT_EQ(rules.partBodies, 0.0);
}

// Past the limit the run stops with one line located at the duration,
// naming the limit and the time it stopped at; it stops at the same step
// every time, whatever the machine.
TEST(WorkLimit, ARunPastItStopsWithALocatedRefusal) {
  for (const SimulationMode mode : {SimulationMode::Bullet, SimulationMode::Compat, SimulationMode::Rules}) {
    const Scenario s = tower(20, 0.02, 5.0);
    const double limit = 0.2 * workOf(s, mode).units();
    long stoppedAt[2] = {0, 0};
    for (long& at : stoppedAt) {
      auto sim = buildSimulation(s, s.settings, mode);
      ScriptPlayer player(s, s.settings, *sim);
      player.setWorkLimit(limit);
      try {
        player.runToEnd();
        ADD_FAILURE() << "ran past the limit in mode " << toString(mode);
      } catch (const ScenarioError& e) {
        const std::string line = e.what();
        EXPECT_NE(line.find("tower.json:"), std::string::npos) << line;
        EXPECT_NE(line.find("at /settings/duration: expected at most"), std::string::npos) << line;
        EXPECT_NE(line.find("units of work"), std::string::npos) << line;
        EXPECT_EQ(line.find('\n'), std::string::npos) << line;
      }
      at = sim->steps();
      EXPECT_LT(sim->time(), s.settings.duration);
    }
    EXPECT_EQ(stoppedAt[0], stoppedAt[1]);
  }
}

// Restarting the count (each stepping call from Python, each viewer step)
// lets a long session go on as long as each call stays under the limit.
TEST(WorkLimit, RestartingTheCountBoundsEachCallNotTheSession) {
  const Scenario s = tower(10, 0.05, 2.0);
  auto sim = buildSimulation(s, s.settings, SimulationMode::Bullet);
  ScriptPlayer player(s, s.settings, *sim);
  const double perStep = [&] {
    auto probe = buildSimulation(s, s.settings, SimulationMode::Bullet);
    ScriptPlayer p(s, s.settings, *probe);
    for (int k = 0; k < 10; ++k) p.step();
    return probe->work().units() / 10.0;
  }();
  player.setWorkLimit(20.0 * perStep);
  for (int call = 0; call < 10; ++call) {
    player.restartWorkCount();
    for (int k = 0; k < 10; ++k) EXPECT_NO_THROW(player.step());
  }
  EXPECT_EQ(sim->steps(), 100);
}

}  // namespace
}  // namespace tabletop
