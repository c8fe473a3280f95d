// Resting load, solved per island (IslandSolver, the default `auto`): a tower
// of cubes (or of standing cylinders) at rest on the table or the floor
// stays where statics puts it, body k's centre at support + (k + 1/2) size,
// for any height, size, mass ratio and rate from 10 Hz, with no setting but
// the rate. Tolerances:
// 0.1 mm on every centre, at the end and at worst over 10 s (the goal is
// 1 mm over 60 s at 60 Hz). That the slow rates hold too is what lets
// `bench --hard` compare a stack's cost with a peer's at the same drift
// (lowestRateHolding).

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "core/Simulation.h"
#include "scenario/ScenarioLoader.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"

namespace tabletop {
namespace {

constexpr double kTableTop = 0.75;  // m, the scenario's default table height

struct Tower {
  int bodies;         // how many, stacked
  double size;        // m
  double baseMass;    // kg, the bottom body
  double topMass;     // kg, every body above it
  const char* support;  // "table" or "ground"
  double rate;        // Hz
  double radius = 0;  // m: a cylinder's, standing, `size` high; 0: cubes
};

// The scenario's "size": a cube's edge, or a cylinder's [radius, radius,
// height].
std::string shapeSize(const Tower& t) {
  std::ostringstream s;
  if (t.radius > 0) {
    s << "[" << t.radius << ", " << t.radius << ", " << t.size << "]";
  } else {
    s << t.size;
  }
  return s.str();
}

std::string describe(const Tower& t) {
  std::ostringstream s;
  s << t.bodies << (t.radius > 0 ? " cylinders " : " cubes of ") << shapeSize(t) << " m (" << t.baseMass
    << " kg under " << t.topMass << " kg) on the " << t.support << ", " << t.rate << " Hz";
  return s.str();
}

// Runs the tower 10 s; returns the farthest any centre got from where
// statics puts it, over every step, m.
double worstOffset(const Tower& t) {
  const bool table = std::string(t.support) == "table";
  const double x = table ? 0.1 : 3.0;
  std::ostringstream text;
  text << R"({"version": 1, "name": "tower", "settings": {"timestep": )" << 1.0 / t.rate
       << R"(, "duration": 10, "end_at_rest": false}, "entities": [)";
  for (int k = 0; k < t.bodies; ++k) {
    text << (k ? "," : "") << R"({"name": "C)" << k << R"(", "shape": ")" << (t.radius > 0 ? "cylinder" : "cube")
         << R"(", "size": )" << shapeSize(t) << R"(, "position": [)" << x << R"(, 0], "on": ")"
         << (k ? "C" + std::to_string(k - 1) : t.support)
         << R"(", "mass": )" << (k ? t.topMass : t.baseMass) << R"(, "material": {"friction": 0.5}})";
  }
  text << "]}";
  const Scenario s = ScenarioLoader::loadText(text.str(), "tower.json");
  auto sim = buildSimulation(s, s.settings, SimulationMode::Bullet);
  const double base = table ? kTableTop : 0.0;
  double worst = 0.0;
  const RunResult r = runScript(s, s.settings, *sim, [&](const Simulation& now) {
    const auto states = now.snapshot();
    for (std::size_t k = 0; k < states.size(); ++k) {
      const Vec3& p = states[k].position;
      const double height = base + (static_cast<double>(k) + 0.5) * t.size;
      worst = std::max(worst, std::hypot(p.x - x, p.y - height, p.z));
    }
  });
  EXPECT_TRUE(r.complete) << describe(t) << ": " << r.failure;
  return worst;
}

// One piece on the table, turned `yaw` degrees: its shape and its
// scenario size.
struct Piece {
  const char* shape;
  const char* size;
  double yaw = 0.0;
  double x = 0.1, z = 0.0;  // m, where it is put on the table's top
};

// Runs `top` seated on `base` on the table for `duration` s at `rate`;
// returns the farthest the top got from where it was put, m.
double topDrift(const Piece& base, const Piece& top, double rate, double duration) {
  std::ostringstream text, what;
  // A place to the bit: a nudge of 1 nm must reach the scenario.
  const auto exact = [](double v) {
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
  };
  text << R"({"version": 1, "name": "pair", "settings": {"timestep": )" << 1.0 / rate << R"(, "duration": )"
       << duration << R"(, "end_at_rest": false}, "entities": [)"
       << R"({"name": "A", "shape": ")" << base.shape << R"(", "size": )" << base.size
       << R"(, "position": [)" << exact(base.x) << ", " << exact(base.z) << R"(], "on": "table", "yaw": )" << base.yaw
       << R"(, "mass": 0.5},)"
       << R"({"name": "B", "shape": ")" << top.shape << R"(", "size": )" << top.size << R"(, "position": [)" << exact(top.x)
       << ", " << exact(top.z) << R"(], "on": "A", "yaw": )" << top.yaw << R"(, "mass": 0.3}]})";
  what << top.shape << " " << top.size << " at " << top.yaw << " deg on " << base.shape << " " << base.size << " at "
       << base.yaw << " deg, " << rate << " Hz";
  const Scenario s = ScenarioLoader::loadText(text.str(), "pair.json");
  auto sim = buildSimulation(s, s.settings, SimulationMode::Bullet);
  const Vec3 start = sim->snapshot().back().position;
  double worst = 0.0;
  const RunResult r = runScript(s, s.settings, *sim, [&](const Simulation& now) {
    const Vec3 p = now.snapshot().back().position;
    worst = std::max(worst, std::hypot(p.x - start.x, p.y - start.y, p.z - start.z));
  });
  EXPECT_TRUE(r.complete) << what.str() << ": " << r.failure;
  return worst;
}

TEST(RestingLoad, TowersOfEqualCubesStandAtTheirStaticHeights) {
  for (int cubes : {2, 5, 10}) {
    for (double size : {0.05, 0.2}) {
      for (const char* support : {"table", "ground"}) {
        for (double rate : {10.0, 20.0, 30.0, 60.0, 240.0}) {
          const Tower t{cubes, size, 1.0, 1.0, support, rate};
          EXPECT_LE(worstOffset(t), 1e-4) << describe(t);
        }
      }
    }
  }
}

// Standing cylinders, each on the end of the one below, equal or flat: on
// Bullet's points (GJK at three small turns) the top of a tower of five
// leaned at its first step and ended 0.34 mm aside at 240 Hz; they rest
// on their rims' corners as on a box (SolidOnFaceAlgorithm).
TEST(RestingLoad, TowersOfEqualCylindersStandAtTheirStaticHeights) {
  for (int cylinders : {2, 5}) {
    for (const auto& [radius, height] : {std::pair{0.04, 0.06}, std::pair{0.05, 0.02}}) {
      for (const char* support : {"table", "ground"}) {
        for (double rate : {30.0, 60.0, 240.0}) {
          Tower t{cylinders, height, 0.5, 0.5, support, rate};
          t.radius = radius;
          EXPECT_LE(worstOffset(t), 1e-4) << describe(t);
        }
      }
    }
  }
}

// Every shape standing on every flat top on the table: a cube, a box, a
// standing cylinder, a flat one and a truncated cone, each under a small
// cube, cylinder and cone. Each top stays where it was put, within 1 um
// over 2 s at 30 to 240 Hz. On Bullet's points (GJK, clipping) a cube on a
// cone's top stood 0.4 mm aside at 60 Hz, a cylinder on a smaller cube 88
// um, a cone on a cylinder 22 um, each tipping at its first step.
TEST(RestingLoad, EveryShapeStandsOnEveryFlatTop) {
  const Piece bases[] = {{"cube", "0.1"},
                         {"box", "[0.2, 0.05, 0.12]"},
                         {"cylinder", "[0.05, 0.05, 0.06]"},
                         {"cylinder", "[0.08, 0.08, 0.02]"},
                         {"cylinder", "[0.06, 0.04, 0.06]"}};
  const Piece tops[] = {{"cube", "0.05"}, {"cylinder", "[0.03, 0.03, 0.05]"}, {"cylinder", "[0.035, 0.02, 0.05]"}};
  for (const Piece& base : bases) {
    for (const Piece& top : tops) {
      for (double rate : {30.0, 60.0, 240.0}) {
        EXPECT_LE(topDrift(base, top, rate, 2.0), 1e-6)
            << top.shape << " " << top.size << " on " << base.shape << " " << base.size << ", " << rate << " Hz";
      }
    }
  }
}

// A cube or a box seated on another, of nearly the same size or wider, at
// relative yaws where neither top holds the other's corners: their contact
// is Bullet's clipping of the two faces, on the boxes' polyhedra. Bullet
// builds those a few micrometres small for some sizes (a 46 mm cube's 4.5
// um), so a rider seated 1 nm into its base read as apart, fell a step and
// stayed 2.2 mm into it at 30 Hz (initializeExactBoxFeatures). And of the
// eight corners of the octagon where they touch, Bullet's manifold kept
// four on one side of the centre, and the rider tipped (a 0.101 m cube
// turned 3 degrees on another, 39 um at 240 Hz; ContactResult keeps the
// widest four). Each rider stays where it was put within 1 um over 1 s at
// 30 Hz to 1 kHz.
TEST(RestingLoad, BoxesSeatedOnBoxesAtAnyYawStay) {
  const Piece bases[] = {{"cube", "0.048", 0}, {"cube", "0.101", 20}, {"box", "[0.092, 0.05, 0.083]", 0}};
  const Piece riders[] = {{"cube", "0.046", 7}, {"cube", "0.092", 30}, {"box", "[0.119, 0.023, 0.077]", 45},
                          {"cube", "0.101", 3}};
  for (const Piece& base : bases) {
    for (Piece rider : riders) {
      rider.yaw += base.yaw;
      for (double rate : {30.0, 60.0, 240.0, 1000.0}) {
        EXPECT_LE(topDrift(base, rider, rate, 1.0), 1e-6)
            << rider.shape << " " << rider.size << " turned " << rider.yaw - base.yaw << " deg on " << base.shape
            << " " << base.size << ", " << rate << " Hz";
      }
    }
  }
}

// A cube or a box seated off the centre of another, at any yaw, its centre
// over the base's face: statics holds it where it was put. Their faces
// meet in a polygon of up to eight corners (a rectangle where the two are
// aligned, whose shared edges rounding can cut anywhere), of which a
// manifold keeps four; kept one at a time, the four depended on the order
// and on rounding, and a rider left with four on one side of its centre
// tipped: two aligned 0.1 m cubes, the upper 2 cm aside, moved 1 mm at 30
// Hz after 2.9 s at rest. Each offset is also tried moved by 1 nm and
// 0.3 um, which changes nothing but rounding. Each rider stays within 1 um
// over 3 s at 30 to 240 Hz.
TEST(RestingLoad, RidersSeatedOffCentreStay) {
  const Piece bases[] = {{"cube", "0.1"}, {"box", "[0.14, 0.05, 0.09]"}};
  const Piece riders[] = {{"cube", "0.1"}, {"cube", "0.06"}};
  const std::pair<double, double> offsets[] = {{0.02, 0.0}, {0.03, 0.01}, {0.012, -0.02}};
  for (const Piece& base : bases) {
    for (Piece rider : riders) {
      for (double yaw : {0.0, 7.0, 30.0, 45.0}) {
        for (const auto& [dx, dz] : offsets) {
          for (double nudge : {0.0, 1e-9, 3e-7}) {
            for (double rate : {30.0, 60.0, 240.0}) {
              rider.yaw = yaw;
              rider.x = base.x + dx + nudge;
              rider.z = base.z + dz;
              EXPECT_LE(topDrift(base, rider, rate, 3.0), 1e-6)
                  << rider.shape << " " << rider.size << " turned " << yaw << " deg, " << dx + nudge << ", " << dz
                  << " m off the centre of " << base.shape << " " << base.size << ", " << rate << " Hz";
            }
          }
        }
      }
    }
  }
}

// A 1000 times heavier cube on a light one and the other way round: with
// one friction row a point (Bullet's default) the light base crept across
// its one frictionless axis, 11.5 mm in 10 s at 60 Hz.
TEST(RestingLoad, MassRatiosOfAThousandRestBothWays) {
  for (double ratio : {1e-3, 1e3}) {
    for (const char* support : {"table", "ground"}) {
      for (double rate : {10.0, 20.0, 30.0, 60.0, 240.0}) {
        const Tower t{2, 0.1, 1.0, ratio, support, rate};
        EXPECT_LE(worstOffset(t), 1e-4) << describe(t);
      }
    }
  }
}

}  // namespace
}  // namespace tabletop
