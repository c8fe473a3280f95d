// Landings, contacts and report 3.4's moment, at their own time. A body
// dropped kDropHeight onto the floor, the table, a slab or a drum (e = 0,
// and bouncing at e = 0.5) is reported landing once, at t0 = sqrt(2 h / g),
// within 1e-4 s at every rate from 30 Hz to 1 kHz; two bodies meeting
// begin their contact at the impact. And a body sliding under friction off
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
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "core/Simulation.h"
#include "scenario/ScenarioLoader.h"
#include "scenes/LawScenes.h"
#include "support/RunScene.h"

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
        const RunResult r = test::runScene(s);
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

// Two balls meeting head on (or two cubes face to face) inside a step
// begin their contact at the time of impact, gap / v, within 1e-4 s, also
// where they are apart again by the step's end (at 30 Hz the balls' contact
// was not reported at all).
TEST(EventTime, AContactBeginsAtTheImpactInsideTheStep) {
  const double gap = 0.3, v = 0.75;  // m, between the facing surfaces; m/s
  for (const char* shape : {R"("shape": "sphere", "size": 0.05)", R"("shape": "cube", "size": 0.1)"}) {
    for (const double rate : {30.0, 60.0, 240.0, 1000.0}) {
      std::ostringstream text;
      text.precision(17);
      text << R"({"version": 1, "name": "meet", "settings": {"timestep": )" << 1.0 / rate
           << R"(, "duration": 1.0}, "entities": [{"name": "A", )" << shape << R"(, "mass": 1.0, "position": [)"
           << -0.05 - gap << R"(, 0.0], "on": "table", "material": {"friction": 0, "restitution": 0.8}},)"
           << R"({"name": "B", )" << shape << R"(, "mass": 1.0, "position": [0.05, 0.0], "on": "table",)"
           << R"( "material": {"friction": 0, "restitution": 0.8}}],)"
           << R"( "script": [{"push": {"entity": "A", "angle": 0, "impulse": )" << v << "}}]}";
      const Scenario s = ScenarioLoader::loadText(text.str(), "meet.json");
      const RunResult r = test::runScene(s);
      int begins = 0;
      for (const Event& e : r.events) {
        if (e.type != EventType::ContactBegin) continue;
        if (++begins == 1) {
          EXPECT_NEAR(e.t, gap / v, 1e-4) << shape << ", " << rate << " Hz";
        }
      }
      EXPECT_EQ(begins, 1) << shape << ", " << rate << " Hz";
    }
  }
}

TEST(EventTime, ALandingIsPlacedInsideTheStep) {
  const double t0 = std::sqrt(2.0 * kDropHeight / kG);
  struct Shape { const char* shape; const char* size; double below; };
  for (const Shape& shape : {Shape{"cube", "0.1", 0.05}, Shape{"sphere", "0.05", 0.05},
                             Shape{"cylinder", "[0.05, 0.05, 0.1]", 0.05}, Shape{"box", "[0.2, 0.05, 0.12]", 0.025}}) {
    for (const char* support : kLawSupports) {
      for (const double e : {0.0, 0.5}) {
        for (const double rate : {30.0, 60.0, 240.0, 1000.0}) {
          const DropCase c{shape.shape, shape.size, shape.below, support, e, rate};
          const Scenario s = dropScene(c);
          const RunResult r = test::runScene(s);
          int landings = 0;
          for (const Event& event : r.events) {
            if (event.type != EventType::Lands || event.entity != "A") continue;
            if (++landings == 1) {
              EXPECT_NEAR(event.t, t0, 1e-4) << describe(c);
            }
          }
          // A bouncing body lands once: it comes down again on what it
          // landed on.
          EXPECT_EQ(landings, 1) << describe(c);
        }
      }
    }
  }
}

// A frictionless ball faster than sqrt(g r) leaves the edge the moment its
// centre passes it and flies: at tc = d / v (d from its centre to the
// edge), then at T past that its centre is v (T - tc) beyond the edge and
// g (T - tc)^2 / 2 below where it was, within 0.1 mm, for each edge, two
// radii, two speeds, three distances (so the edge comes at different
// points of a step) and every rate from 30 Hz to 1 kHz. Before, the step
// in which the centre passed the edge held it level to the step's end (up
// to 17 mm long at 60 Hz), and the table top's edge, rounded by GJK's 1 mm
// margin, dropped it a millimetre early.
TEST(EventTime, ABallLeavesTheEdgeWhenItsCentrePasses) {
  struct Edge { const char* direction; double x, z; };  // the push, and the axis it runs along
  for (const Edge& edge : {Edge{"Left", 1, 0}, Edge{"Right", -1, 0}, Edge{"Back", 0, 1}, Edge{"Front", 0, -1}}) {
    const double half = edge.x != 0 ? 0.6 : 0.4;  // m, the table's half extent along the push
    for (const double r : {0.03, 0.08}) {
      for (const double v : {1.5, 3.2}) {  // m/s, above sqrt(g r) = 0.89 m/s
        for (const double d : {0.2, 0.2071, 0.3313}) {
          for (const double rate : {30.0, 60.0, 240.0, 1000.0}) {
            const double start = half - d;
            const std::string text = R"({"version": 1, "name": "ball",
                "settings": {"timestep": )" + std::to_string(1.0 / rate) + R"(, "duration": )" +
                                     std::to_string(d / v + 0.2) + R"(, "end_at_rest": false},
                "table": {"size": [1.2, 0.8], "material": {"friction": 0.0}},
                "entities": [{"name": "A", "shape": "sphere", "size": )" + std::to_string(r) +
                                     R"(, "mass": 1.0, "position": [)" + std::to_string(start * edge.x) + ", " +
                                     std::to_string(start * edge.z) + R"(], "on": "table", "material": {"friction": 0.0}}],
                "script": [{"push": {"entity": "A", "direction": ")" + edge.direction + R"(", "impulse": )" +
                                     std::to_string(v) + "}}]}";
            const Scenario s = ScenarioLoader::loadText(text, "ball.json");
            const RunResult run = test::runScene(s);
            const double flight = run.simTime - d / v;  // s since the centre passed the edge
            ASSERT_GT(flight, 0.15);
            const Vec3& p = run.entities.at(0).position;
            const double beyond = p.x * edge.x + p.z * edge.z - half;
            const std::string what = std::string(edge.direction) + " push, r " + std::to_string(r) + " m, v " +
                                     std::to_string(v) + " m/s, d " + std::to_string(d) + " m, " +
                                     std::to_string(rate) + " Hz";
            EXPECT_NEAR(beyond, v * flight, 1e-4) << what;
            EXPECT_NEAR(p.y, s.table.height + r - 0.5 * kG * flight * flight, 1e-4) << what;
          }
        }
      }
    }
  }
}

// A ball at rest on the table top with its centre half a millimetre inside
// the edge stands on the flat top and stays there (1 um over 2 s, awake);
// on GJK's edge, rounded by a 1 mm margin, it rolled off.
TEST(EventTime, ABallJustInsideTheEdgeStays) {
  for (const double rate : {60.0, 240.0}) {
    const std::string text = R"({"version": 1, "name": "ball",
        "settings": {"timestep": )" + std::to_string(1.0 / rate) + R"(, "duration": 2, "end_at_rest": false, "sleeping": false},
        "table": {"size": [1.2, 0.8]},
        "entities": [{"name": "A", "shape": "sphere", "size": 0.05, "mass": 1.0, "position": [0.5995, 0.0], "on": "table"}]})";
    const Scenario s = ScenarioLoader::loadText(text, "ball.json");
    const RunResult run = test::runScene(s);
    EXPECT_NEAR(run.entities.at(0).position.x, 0.5995, 1e-6) << rate << " Hz";
    EXPECT_NEAR(run.entities.at(0).position.y, s.table.height + 0.05, 1e-6) << rate << " Hz";
  }
}

}  // namespace
}  // namespace tabletop
