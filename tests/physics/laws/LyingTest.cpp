// A solid cylinder lying on its side, over sizes x support x direction x
// rate, against its closed forms:
//  - pushed through its centre across its axis, it slips, then rolls at
//    v1 = v0 - mu g t1 (2/3 v0 without rolling friction) and stops against
//    its rolling resistance rf (a lever arm):
//    d = (v0 + v1) t1 / 2 + v1^2 / (2 a), t1 = k v0 / (g ((1 + k) mu - rf / r)),
//    a = g rf / (r (1 + k)), with k = 1/2 (rollingDistance);
//  - pushed along its axis, it slides d = v0^2 / (2 mu g).
// Either way its axis keeps its direction within 0.01 degree, level, and
// its centre stays a radius above the support. Tolerances as the sliding
// law's: 0.1 mm from 60 Hz up, growing at second order below it.
//
// Before the island of a body whose slip stopped was pivoted in the next
// part (IslandSolver), the wheel (0.08 m in radius, 0.06 m long) pushed
// along its axis at 30 Hz pitched by 0.05 degree as it stopped: its
// leading rim carried more of it while it slid, and the sweeps started
// from that share.
//
// Before a rim touched a plane at its lowest point alone (rimCorners), the
// rims were 32 fixed points each: a rolling cylinder was a polygon whose
// points ahead of the lowest closed on the plane each step, and it slowed
// to 0.14 m/s where the closed form rolls on at 0.33 (60 Hz).

#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/Angle.h"
#include "core/Simulation.h"
#include "physics/StepPush.h"
#include "scenes/LawScenes.h"
#include "support/RunScene.h"

namespace tabletop {
namespace {

constexpr double kG = 9.81;  // m/s^2

struct Lying {
  const char* size;  // a cylinder's [radius, radius, length], m
  double radius;
};

const Lying kCylinders[] = {{"[0.05, 0.05, 0.1]", 0.05}, {"[0.03, 0.03, 0.2]", 0.03}, {"[0.08, 0.08, 0.06]", 0.08}};

// The support's top, m (scenes/LawScenes.h).
double top(const std::string& support) { return support == "table" ? 0.75 : support == "ground" ? 0.0 : 0.1; }

// The body's axis (its y) in the world at the end of a run.
Vec3 axisOf(const EntityState& e) {
  const auto [w, x, y, z] = e.orientation;
  return {2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)};
}

double tolerance(double rate) { return 1e-4 * std::max(1.0, std::pow(60.0 / rate, 2)); }

// Runs `c` to its end and checks what both laws share: the distance
// travelled, the axis kept level and in its direction, the centre a
// radius up.
void expectTravels(const PushCase& c, double radius, double expected) {
  const Scenario s = pushScene(c);
  const RunResult r = test::runScene(s);
  EXPECT_TRUE(r.complete) << describe(c);
  const EntityState& a = r.entities.back();
  const auto [x0, z0] = pushStart(c);
  EXPECT_NEAR(std::hypot(a.position.x - x0, a.position.z - z0), expected, tolerance(c.rate)) << describe(c);
  EXPECT_NEAR(a.position.y, top(c.support) + radius, tolerance(c.rate)) << describe(c);
  const double angle = convertAngle(c.angle);
  const Vec3 u = c.lying == PushCase::Lying::Across ? Vec3{std::sin(angle), 0, std::cos(angle)}
                                                     : Vec3{std::cos(angle), 0, -std::sin(angle)};
  const Vec3 axis = axisOf(a);
  const double along = std::abs(axis.x * u.x + axis.y * u.y + axis.z * u.z);
  EXPECT_GT(along, std::cos(convertAngle(0.01))) << describe(c) << ": the axis turned " << std::acos(std::min(1.0, along)) * 180 / kPi << " deg";
}

TEST(Lying, ACylinderPushedAcrossItsAxisSlipsThenRollsTheClosedFormDistance) {
  const double mu = 0.25;
  for (const Lying& body : kCylinders) {
    for (const double rf : {0.002, 0.005}) {
      for (const double v0 : {0.2, 0.4}) {
        const double expected = rollingDistance(v0, mu, rf, body.radius, kG, 0.5);
        for (const char* support : kLawSupports) {
          for (const double angle : {0.0, 77.0}) {
            for (const double rate : {30.0, 60.0, 240.0, 1000.0}) {
              PushCase c{"cylinder", body.size, support, angle, rate, mu, rf};
              c.impulse = v0 * kPushedMass;
              c.lying = PushCase::Lying::Across;
              SCOPED_TRACE("rf " + std::to_string(rf) + " m, v0 " + std::to_string(v0) + " m/s");
              expectTravels(c, body.radius, expected);
            }
          }
        }
      }
    }
  }
}

TEST(Lying, ACylinderPushedAlongItsAxisSlidesTheClosedFormDistance) {
  const double mu = 0.25;
  for (const Lying& body : kCylinders) {
    for (const double v0 : {0.4, 1.2}) {
      const double expected = v0 * v0 / (2.0 * mu * kG);
      for (const char* support : kLawSupports) {
        for (const double angle : {0.0, 77.0}) {
          for (const double rate : {30.0, 60.0, 240.0, 1000.0}) {
            PushCase c{"cylinder", body.size, support, angle, rate, mu};
            c.impulse = v0 * kPushedMass;
            c.lying = PushCase::Lying::Along;
            SCOPED_TRACE("v0 " + std::to_string(v0) + " m/s");
            expectTravels(c, body.radius, expected);
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace tabletop
