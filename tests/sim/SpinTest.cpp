// Coulomb friction against a spin: a body standing on a face (or its base)
// and spun about the vertical at w0 is slowed by the friction of its
// contact points, mu m g at a distance rho from the axis (the corners of a
// box's face, the rim points of a cylinder's base), at
// alpha = mu g rho / k^2 (k^2 = I / m about the vertical). It turns
// w0^2 / (2 alpha) and stops where it stands, at every rate: the spin
// changes linearly until it stops, inside a step (DynamicsWorld turns a
// body slipping on a face by its mean rate about the face's normal, and
// by the share of the step it slipped for).
//
// rho is the model's, not a pressed patch's: a uniformly pressed square
// face would resist with mu m g times 0.383 of its edge (the mean distance
// of its area from the centre), not 0.707 (its corners'), and turn 1.85
// times as far (docs/bullet-corrections.md).

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/Simulation.h"
#include "scenes/LawScenes.h"
#include "support/RunScene.h"

namespace tabletop {
namespace {

constexpr double kG = 9.81;  // m/s^2

struct Spun {
  const char* shape;
  const char* size;
  double rho;  // m, the contact points' distance from the axis
  double k2;   // m^2, I / m about the vertical
};

// Every shape standing on a face or its base whose points lie at one
// distance from its axis.
const Spun kSpun[] = {
    {"cube", "0.1", std::sqrt(2.0) * 0.05, 0.1 * 0.1 / 6.0},
    {"cube", "0.06", std::sqrt(2.0) * 0.03, 0.06 * 0.06 / 6.0},
    {"box", "[0.2, 0.05, 0.12]", std::hypot(0.1, 0.06), (0.2 * 0.2 + 0.12 * 0.12) / 12.0},
    {"cylinder", "[0.05, 0.05, 0.1]", 0.05, 0.05 * 0.05 / 2.0},
    {"cylinder", "[0.08, 0.08, 0.03]", 0.08, 0.08 * 0.08 / 2.0},
};

TEST(Spin, TurnsTheClosedFormAngleAndStopsWhereItStands) {
  for (const Spun& spun : kSpun) {
    for (const char* support : kLawSupports) {
      for (const double mu : {0.25, 0.6}) {
        for (const double w0 : {5.0, -12.0}) {
          const double alpha = mu * kG * spun.rho / spun.k2;
          const double expected = w0 * std::abs(w0) / (2.0 * alpha);
          for (const double rate : {30.0, 60.0, 240.0, 1000.0}) {
            PushCase c{spun.shape, spun.size, support, 0.0, rate, mu};
            c.spin = w0;
            const RunResult r = test::runScene(pushScene(c));
            EXPECT_TRUE(r.complete) << describe(c);
            const EntityState& a = r.entities.back();
            const auto [x0, z0] = pushStart(c);
            const double turned = a.yawDegrees * M_PI / 180.0;
            EXPECT_NEAR(turned, expected, 1e-4 * std::abs(expected)) << describe(c) << ", mu " << mu;
            EXPECT_LT(std::hypot(a.position.x - x0, a.position.z - z0), 1e-6) << describe(c) << ", mu " << mu;
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace tabletop
