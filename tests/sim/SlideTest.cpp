// Coulomb sliding on every support, in every direction: a body given v0
// along the floor or the table top slides d = v0^2 / (2 mu g) and stops,
// without turning, whatever the shape (a cube, a box, a cylinder standing
// on its base, a flat one, a truncated cone), the direction (off the axes
// too), the size and the rate. Tolerances: 0.1 mm on the distance from
// 60 Hz up, growing at second order below it (0.4 mm at 30 Hz), and 0.01
// degree of turn.

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "core/Angle.h"
#include "core/Simulation.h"
#include "scenario/ScenarioLoader.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"

namespace tabletop {
namespace {

constexpr double kG = 9.81;  // m/s^2

struct Case {
  const char* shape;
  const char* size;
  const char* support;  // "table" or "ground"
  double angle;         // degrees, the push's world angle
  double rate;          // Hz
};

std::string describe(const Case& c) {
  std::ostringstream s;
  s << c.shape << " " << c.size << " on the " << c.support << ", at " << c.angle << " deg, " << c.rate << " Hz";
  return s.str();
}

TEST(Slide, TravelsTheClosedFormDistanceWithoutTurning) {
  const struct {
    const char* shape;
    const char* size;
  } shapes[] = {{"cube", "0.1"},
                {"cube", "0.06"},
                {"box", "[0.2, 0.05, 0.12]"},
                {"cylinder", "[0.05, 0.05, 0.1]"},
                {"cylinder", "[0.08, 0.08, 0.03]"},
                {"cylinder", "[0.05, 0.03, 0.1]"}};
  const double mu = 0.25, mass = 1.5, impulse = 2.4;  // v0 = 1.6 m/s: d = 0.522 m
  const double v0 = impulse / mass, expected = v0 * v0 / (2.0 * mu * kG);
  for (const auto& shape : shapes) {
    for (const char* support : {"table", "ground"}) {
      for (double angle : {0.0, 30.0, 45.0, 77.0, 90.0}) {
        for (double rate : {30.0, 60.0, 240.0, 1000.0}) {
          const Case c{shape.shape, shape.size, support, angle, rate};
          // From the table's centre, or on the floor 3 m from it; the push
          // sends it towards open space.
          const bool table = std::string(support) == "table";
          const double x0 = table ? -0.3 * std::cos(convertAngle(angle)) : 3.0;
          const double z0 = table ? 0.3 * std::sin(convertAngle(angle)) : 0.0;
          std::ostringstream text;
          text << R"({"version": 1, "name": "slide", "table": {"size": [2.0, 2.0], "material": {"friction": 1}},
            "ground": {"material": {"friction": 1}},
            "settings": {"timestep": )"
               << 1.0 / rate << R"(, "duration": 3},
            "entities": [{"name": "A", "shape": ")"
               << shape.shape << R"(", "size": )" << shape.size << R"(, "position": [)" << x0 << ", " << z0
               << R"(], "on": ")" << support << R"(", "mass": )" << mass << R"(, "material": {"friction": )" << mu
               << R"(}}],
            "script": [{"push": {"entity": "A", "angle": )"
               << angle << R"(, "impulse": )" << impulse << "}}]}";
          const Scenario s = ScenarioLoader::loadText(text.str(), "slide.json");
          auto sim = buildSimulation(s, s.settings, SimulationMode::Bullet);
          const RunResult r = runScript(s, s.settings, *sim);
          ASSERT_TRUE(r.complete) << describe(c);
          const EntityState& a = r.entities.at(0);
          const double travelled = std::hypot(a.position.x - x0, a.position.z - z0);
          EXPECT_NEAR(travelled, expected, 1e-4 * std::max(1.0, std::pow(60.0 / rate, 2))) << describe(c);
          EXPECT_NEAR(a.yawDegrees, 0.0, 0.01) << describe(c);
        }
      }
    }
  }
}

}  // namespace
}  // namespace tabletop
