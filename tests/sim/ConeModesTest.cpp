// A cone in the report's modes (rules, and compat, Bullet held to them): it
// is a frustum there, a body standing on its base whose footprint is its
// base circle (RuleBody: a round body's footprint is its larger radius).
// Standing point up on the table its centroid is h/4 above the top; pushed
// along X into a cube, it strikes where its base circle meets the cube's
// face, after gap = d - R - a/2, and the cube moves the rest of the step
// (report 3.7). Rules: exact kinematics, to 1e-9 m. Compat finds the strike
// by GJK on the Bullet shapes: it agrees with the rules within
// kAgreeDistance (1 mm), as on every other scene (ModeAgreementTest).

#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "scenario/ScenarioLoader.h"
#include "sim/ModeComparison.h"
#include "support/RunScene.h"

namespace tabletop {
namespace {

constexpr double kTableTop = 0.75;  // m, the scenario's default table height
constexpr double kExact = 1e-9;     // m, the rules' kinematics in double
constexpr double kSide = 0.1;       // m, the struck cube's side
constexpr double kConeX = -0.3;     // m, the cone's centre; the cube's is at 0
constexpr double kStep = 0.5;       // m, the push's step

struct Body {
  double base, top, height;  // a cylinder's size, m
};

// The cone (or frustum) K at kConeX and the cube B at the origin, on the
// table; K is pushed one step along +X.
Scenario pushInto(const Body& k) {
  std::ostringstream text;
  text << R"({"version": 1, "name": "cone strikes", "settings": {"timestep": 0.004166666666666667},)"
       << R"( "entities": [{"name": "K", "shape": "cylinder", "size": [)" << k.base << ", " << k.top << ", "
       << k.height << R"(], "position": [)" << kConeX << R"(, 0], "mass": 0.4},)"
       << R"( {"name": "B", "shape": "cube", "size": )" << kSide << R"(, "position": [0, 0], "mass": 0.4}],)"
       << R"( "script": [{"push": {"entity": "K", "angle": 0, "step": )" << kStep << "}}]}";
  return ScenarioLoader::loadText(text.str(), "strike.json");
}

std::string describe(const Body& k, SimulationMode mode) {
  std::ostringstream s;
  s << "cylinder [" << k.base << ", " << k.top << ", " << k.height << "] in " << toString(mode);
  return s.str();
}

// Where the rules put K and B after the push: K a whole step on, B struck
// after the gap between K's base circle and B's face, moved the rest.
void expectStrike(const RunResult& r, const Body& k, double tolerance, const std::string& what) {
  ASSERT_TRUE(r.complete) << what << ": " << r.failure;
  ASSERT_EQ(r.entities.size(), 2u);
  const double gap = -kConeX - k.base - 0.5 * kSide;
  EXPECT_NEAR(r.entities[0].position.x, kConeX + kStep, tolerance) << what;
  EXPECT_NEAR(r.entities[1].position.x, kStep - gap, tolerance) << what;
  EXPECT_NEAR(r.entities[1].position.z, 0.0, tolerance) << what;
}

const Body kCones[] = {{0.03, 0.0, 0.05}, {0.05, 0.0, 0.3}, {0.1, 0.0, 0.08}};

TEST(ConeModes, APointUpConeStandsWithItsCentroidAQuarterUp) {
  for (const Body& k : kCones) {
    for (const SimulationMode mode : {SimulationMode::Rules, SimulationMode::Compat}) {
      const Scenario s = pushInto(k);
      auto sim = buildSimulation(s, s.settings, mode);
      EXPECT_NEAR(sim->snapshot().front().position.y, kTableTop + k.height / 4, kExact) << describe(k, mode);
    }
  }
}

TEST(ConeModes, APushedConeStrikesWithItsBaseCircleAsAFrustumDoes) {
  for (const Body& k : kCones) {
    const Scenario s = pushInto(k);
    const RunResult rules = test::runScene(s, SimulationMode::Rules);
    expectStrike(rules, k, kExact, describe(k, SimulationMode::Rules));
    EXPECT_NEAR(rules.entities[0].position.y, kTableTop + k.height / 4, kExact) << describe(k, SimulationMode::Rules);
    // A frustum of the same base strikes at the same place.
    const Body frustum{k.base, 0.5 * k.base, k.height};
    expectStrike(test::runScene(pushInto(frustum), SimulationMode::Rules), frustum, kExact,
                 describe(frustum, SimulationMode::Rules));
    const RunResult compat = test::runScene(s, SimulationMode::Compat);
    expectStrike(compat, k, kAgreeDistance, describe(k, SimulationMode::Compat));
  }
}

}  // namespace
}  // namespace tabletop
