// Coulomb friction against a spin: a body standing on a face (or its base)
// and spun about the vertical turns the closed-form angle (spinLaw, in
// scenes/LawScenes) and stops where it stands, at every rate: the spin
// changes linearly until it stops, inside a step (DynamicsWorld turns a
// body slipping on a face by its mean rate about the face's normal, and
// by the share of the step it slipped for).

#include <cmath>
#include <optional>

#include <gtest/gtest.h>

#include "core/Simulation.h"
#include "scenes/LawScenes.h"
#include "support/RunScene.h"

namespace tabletop {
namespace {

struct Spun {
  const char* shape;
  const char* size;
};

// Every shape standing on a face or its base. A truncated cone turned 5.3%
// beyond the closed form while its base's contact points were its hull's
// ring, drawn in by its margin (Cylinder.cpp); they are on its true rim
// now (rimCorners).
const Spun kSpun[] = {
    {"cube", "0.1"},
    {"cube", "0.06"},
    {"box", "[0.2, 0.05, 0.12]"},
    {"cylinder", "[0.05, 0.05, 0.1]"},
    {"cylinder", "[0.08, 0.08, 0.03]"},
    {"cylinder", "[0.05, 0.03, 0.1]"},
    {"cylinder", "[0.03, 0.05, 0.1]"},
};

TEST(Spin, TurnsTheClosedFormAngleAndStopsWhereItStands) {
  for (const Spun& spun : kSpun) {
    for (const char* support : kLawSupports) {
      for (const double mu : {0.25, 0.6}) {
        for (const double w0 : {5.0, -12.0}) {
          for (const double rate : {30.0, 60.0, 240.0, 1000.0}) {
            PushCase c{spun.shape, spun.size, support, 0.0, rate, mu};
            c.spin = w0;
            const std::optional<SpinLaw> law = spinLaw(c);
            ASSERT_TRUE(law) << describe(c);
            const double expected = law->angle;
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
