// An event cuts the step for its own group only (StepGroups,
// DynamicsWorld::step): what a pair of cubes does does not depend on a
// second pair across the table, whose push and impact come at other
// times. Cube A (mu 0.5) pushed into cube B (mu 0.2) at t = 0 strikes it,
// and both slide to rest; cube C, pushed at t0 into cube D 5 cm ahead of
// it, strikes it later. A and B end where they end alone, to the bit,
// over push times x speeds x 30 Hz to 240 Hz. C is slow enough that no
// step is divided for its sake (World::substeps), which would divide it
// for every body.
//
// Before, every event cut the step for the whole world: the pair ended
// 3e-10 m from where it ends alone, and the world's cost grew with the
// events of every group (docs/bench.md, "Piles").

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/Simulation.h"
#include "scenario/ScenarioLoader.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"

namespace tabletop {
namespace {

constexpr double kDuration = 1.0;  // s: every body has come to rest

struct Case {
  double pushAt;  // s, when C is pushed (0: no second pair)
  double speed;   // m/s, C's speed from the push
  double rate;    // Hz
};

std::string describe(const Case& c) {
  return "C pushed at " + std::to_string(c.pushAt) + " s to " + std::to_string(c.speed) + " m/s, " +
         std::to_string(c.rate) + " Hz";
}

RunResult run(const Case& c, bool second) {
  char text[1400];
  std::snprintf(text, sizeof text, R"({"version": 1, "name": "locality", "table": {"size": [2.0, 2.0]},
      "settings": {"timestep": %.17g, "duration": %g, "end_at_rest": false},
      "entities": [
        {"name": "A", "shape": "cube", "size": 0.1, "mass": 1.0, "position": [-0.3, 0.0], "on": "table",
         "material": {"friction": 0.5, "restitution": 0}},
        {"name": "B", "shape": "cube", "size": 0.1, "mass": 1.0, "position": [-0.2, 0.0], "on": "table",
         "material": {"friction": 0.2, "restitution": 0}}%s],
      "script": [{"t": 0, "push": {"entity": "A", "angle": 0, "impulse": 1.6}}%s]})",
                1.0 / c.rate, kDuration,
                second ? R"(,
        {"name": "C", "shape": "cube", "size": 0.1, "mass": 1.0, "position": [0.3, 0.5], "on": "table",
         "material": {"friction": 0.4, "restitution": 0}},
        {"name": "D", "shape": "cube", "size": 0.1, "mass": 1.0, "position": [0.45, 0.5], "on": "table",
         "material": {"friction": 0.3, "restitution": 0}})"
                       : "",
                second ? (std::string(R"(, {"t": )") + std::to_string(c.pushAt) +
                          R"(, "push": {"entity": "C", "angle": 0, "impulse": )" + std::to_string(c.speed) + "}}")
                             .c_str()
                       : "");
  const Scenario s = ScenarioLoader::loadText(text, "locality.json");
  std::unique_ptr<Simulation> sim = buildSimulation(s, s.settings, SimulationMode::Bullet);
  return runScript(s, s.settings, *sim);
}

TEST(GroupLocality, APairEndsToTheBitAsItDoesAloneWhateverAnotherPairDoes) {
  for (const double rate : {30.0, 60.0, 240.0}) {
    const RunResult alone = run({0, 0, rate}, false);
    for (const double pushAt : {0.1, 0.3}) {
      for (const double speed : {0.7, 0.74}) {
        const Case c{pushAt, speed, rate};
        const RunResult both = run(c, true);
        ASSERT_TRUE(both.complete) << describe(c);
        // The second pair did strike: C ends past where it would alone.
        EXPECT_GT(both.entities[3].position.x, 0.45 + 1e-3) << describe(c);
        for (std::size_t k = 0; k < 2; ++k) {
          const EntityState &a = alone.entities[k], &b = both.entities[k];
          EXPECT_EQ(a.position.x, b.position.x) << describe(c) << ", " << a.name;
          EXPECT_EQ(a.position.y, b.position.y) << describe(c) << ", " << a.name;
          EXPECT_EQ(a.position.z, b.position.z) << describe(c) << ", " << a.name;
          EXPECT_EQ(a.linearVelocity.x, b.linearVelocity.x) << describe(c) << ", " << a.name;
        }
      }
    }
  }
}

}  // namespace
}  // namespace tabletop
