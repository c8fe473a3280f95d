// A cone lying on its side, set rolling, rolls in a circle about its apex
// (a truncated cone about where its slant side's line meets the support):
// over cones and truncated cones both ways up x support (table, floor,
// slab, drum) x precession (both ways) x rate (30 Hz to 1 kHz), for 3 s,
// against the closed form computed in scenes/ConeRoll:
//  - its centre of mass within 0.1 mm of its level circle about the apex,
//    at every step (measured: 0.45 um at most);
//  - on a fixed support, within 0.1 mm of its place on the circle, the
//    closed form taken from its state once seated after its first step
//    (its angle, and a precession in proportion to its spin; measured
//    2.2 um), and its energy kept to 1e-4 (measured 1.2e-5: no rolling
//    resistance, none should go);
//  - on the slab or the drum, 100 kg bodies resting on the floor that it
//    moves a little, its energy kept to 1e-3 (measured 5e-4).
// Before a rolling body's velocity was carried round with its line of
// contact and its step turned it as its axis precesses and spins
// (physics/step/RollingLines.h), and before Bullet's friction rows saw
// the gyroscopic term (solver/IslandSolver.h), the centre strayed 1.3 to
// 11 mm from its circle at 60 Hz.

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "physics/World.h"
#include "scenes/ConeRoll.h"
#include "sim/SceneBuilder.h"
#include "support/TestName.h"

namespace tabletop {
namespace {

constexpr double kTolerance = 1e-4;  // m

class ConeRoll : public testing::TestWithParam<RollCase> {};

TEST_P(ConeRoll, RollsInACircleAboutItsApex) {
  const RollCase c = GetParam();
  const Scenario s = rollScene(c);
  const std::unique_ptr<World> world = buildWorld(s, s.settings);
  const Shape& body = *world->entities().back();
  const Vec3 apex = rollApex(c);
  const Vec3 start = rollCentre(c, 0);
  const double radius = std::hypot(start.x - apex.x, start.z - apex.z);
  // Kinetic and potential, from the start's height.
  const auto energy = [&] {
    const btRigidBody& b = *body.body();
    const btVector3 w = b.getAngularVelocity();
    const double m = 1.0 / b.getInvMass();
    return 0.5 * m * b.getLinearVelocity().length2() + 0.5 * w.dot(b.getInvInertiaTensorWorld().inverse() * w) +
           m * s.settings.gravity * (b.getCenterOfMassPosition().y() - start.y);
  };
  // Its place on the circle follows the closed form from its state once
  // seated, after its first step: its angle about the apex then, and a
  // precession in proportion to its spin then.
  world->step();
  const auto angleOf = [&](const btVector3& x) { return std::atan2(-(x.z() - apex.z), x.x() - apex.x); };
  const double angle1 = angleOf(body.body()->getCenterOfMassPosition());
  const double precession = c.precession * body.body()->getAngularVelocity().length() / std::abs(rollSpin(c));
  const double e0 = energy();
  const bool fixed = c.support == "table" || c.support == "ground";
  double offCircle = 0, offPlace = 0, gained = 0, lost = 0;
  const int steps = static_cast<int>(std::lround(kRollDuration * c.rate));
  for (int i = 1; i < steps; ++i) {
    world->step();
    const btVector3 x = body.body()->getCenterOfMassPosition();
    offCircle = std::max(offCircle, std::hypot(std::hypot(x.x() - apex.x, x.z() - apex.z) - radius, x.y() - start.y));
    const double lag = std::remainder(angleOf(x) - angle1 - precession * i / c.rate, 2 * std::acos(-1.0));
    offPlace = std::max(offPlace, std::abs(lag) * radius);
    const double change = energy() / e0 - 1;
    gained = std::max(gained, change);
    lost = std::max(lost, -change);
  }
  EXPECT_LE(offCircle, kTolerance) << describe(c) << ": " << offCircle * 1e3 << " mm off its circle";
  if (fixed) {
    EXPECT_LE(offPlace, kTolerance) << describe(c) << ": " << offPlace * 1e3 << " mm from its place";
    EXPECT_LE(std::max(gained, lost), 1e-4) << describe(c) << ": its energy changed by " << std::max(gained, lost);
  } else {
    EXPECT_LE(std::max(gained, lost), 1e-3) << describe(c) << ": its energy changed by " << std::max(gained, lost);
  }
}

std::vector<RollCase> cases() {
  const struct {
    double base, top, height;
  } bodies[] = {{0.05, 0, 0.1}, {0.03, 0, 0.12}, {0.05, 0.03, 0.1}, {0.03, 0.05, 0.1}};
  std::vector<RollCase> out;
  for (const auto& b : bodies) {
    for (const char* support : {"table", "ground", "slab", "drum"}) {
      for (const double precession : {-2.0, 3.0}) {
        for (const double rate : {30.0, 60.0, 240.0, 1000.0}) {
          RollCase c;
          c.support = support;
          c.baseRadius = b.base, c.topRadius = b.top, c.height = b.height;
          c.precession = precession;
          c.rate = rate;
          out.push_back(c);
        }
      }
    }
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(ConesAndTruncatedCones, ConeRoll, testing::ValuesIn(cases()),
                         [](const testing::TestParamInfo<RollCase>& param) {
                           const RollCase& c = param.param;
                           return test::testName({test::numbers({c.baseRadius, c.topRadius, c.height}), c.support,
                                                  "precession", test::number(c.precession),
                                                  test::number(c.rate) + "Hz"});
                         });

}  // namespace
}  // namespace tabletop
