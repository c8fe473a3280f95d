// Push-to-impulse conversion: the closed forms, and Bullet bodies pushed by
// a step travelling that step.

#include "physics/StepPush.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "physics/shapes/Cube.h"
#include "physics/shapes/Seating.h"
#include "physics/shapes/Sphere.h"
#include "support/PhysicsFixture.h"
#include "support/TestName.h"

namespace tabletop {
namespace {

using test::kG;

// d = v0^2 / (2 mu g): 2 m/s at mu = 0.25 slides 0.8155 m.
TEST(StepPush, SlidingDistanceClosedForm) {
  EXPECT_NEAR(slidingDistance(2.0, 0.25, kG), 4.0 / (2 * 0.25 * kG), 1e-15);
}

// The slip-then-roll closed form against a direct integration of the same
// equations of motion (1 microsecond steps): m dv/dt = -mu m g while
// slipping, I dw/dt = mu m g r - rf m g, then rolling at 5 g rf / (7 r).
TEST(StepPush, RollingDistanceMatchesIntegratedMotion) {
  const double v0 = 1.3, mu = 0.4, rf = 0.002, r = 0.03;
  double v = v0, w = 0, x = 0;
  const double dt = 1e-6;
  while (v - w * r > 0) {
    v -= mu * kG * dt;
    w += 2.5 * kG * (mu * r - rf) / (r * r) * dt;
    x += v * dt;
  }
  const double a = 5.0 * kG * rf / (7.0 * r);
  x += v * v / (2 * a);
  // Each integrated step is first order: the integration's own error is
  // about v0 * dt = 1.3e-6 m.
  EXPECT_NEAR(rollingDistance(v0, mu, rf, r, kG), x, 1e-5);
}

TEST(StepPush, RefusesStepsThatNeverStop) {
  Sphere ball("S", 0.03);
  EXPECT_THROW(stepLaunchSpeed(ball, 0.1, Material{0.4, 0.0, 0.0, 0.0}, kG, 1.0 / 240, Integrator::Trapezoid),
               std::invalid_argument);
  EXPECT_THROW(stepLaunchSpeed(ball, 0.1, Material{0.01, 0.001, 0.0, 0.0}, kG, 1.0 / 240, Integrator::Trapezoid),
               std::invalid_argument);
  Cube cube("C", 0.1);
  EXPECT_THROW(stepLaunchSpeed(cube, 0.1, Material{0.0, 0.0, 0.0, 0.0}, kG, 1.0 / 240, Integrator::Trapezoid),
               std::invalid_argument);
}

// An entity alone on the table, pushed by a step, travels that step: the
// step within 0.5%, at 60, 240 and 1000 Hz, in the four directions and at
// an angle.
struct StepCase {
  bool sphere;
  double timestep;
  double step;
  double angle;
};

class StepTravel : public test::PhysicsFixture, public ::testing::WithParamInterface<StepCase> {};

TEST_P(StepTravel, TravelsTheStepWithinHalfAPercent) {
  const StepCase c = GetParam();
  World& w = makeTable(c.timestep);
  const double size = c.sphere ? 0.03 : 0.1;
  std::unique_ptr<Shape> shape;
  if (c.sphere) {
    shape = std::make_unique<Sphere>("E", size);
  } else {
    shape = std::make_unique<Cube>("E", size);
  }
  const double below = shape->below();
  const Material material{0.4, c.sphere ? 0.002 : 0.0, c.sphere ? 0.002 : 0.0, 0.0};
  Shape& e = w.addEntity(std::move(shape), 0.3, material,
                         btVector3(0, seated(w.table().topHeight() + below), 0), 0.0);
  const btVector3 start = e.position();
  w.push(Arrow{"E", std::nullopt, c.angle}, {PushMagnitude::Kind::Step, c.step});
  simulateUntilRest(10.0);
  ASSERT_TRUE(w.allAtRest());
  const btVector3 moved = e.position() - start;
  const Vec3 d = pushDirection(c.angle);
  // The sphere too, since its rolling resistance acts from the push on
  // (it was missing for the first step, and it rolled v1 dt too far).
  EXPECT_NEAR(moved.length(), c.step, 0.005 * c.step);
  // Straight along the push, to 1%: Gauss-Seidel solves a cube's
  // four corner contacts one after another, so its friction is not quite
  // symmetric within a step (measured: 0.34% of the step at 60 Hz).
  EXPECT_NEAR(moved.x() * d.z - moved.z() * d.x, 0.0, 0.01 * c.step);
}

INSTANTIATE_TEST_SUITE_P(
    CubeAndSphere, StepTravel,
    ::testing::Values(StepCase{false, 1.0 / 240, 0.2, 0.0}, StepCase{false, 1.0 / 240, 0.35, 90.0},
                      StepCase{false, 1.0 / 240, 0.1, 200.0}, StepCase{false, 1.0 / 60, 0.2, 270.0},
                      StepCase{true, 1.0 / 240, 0.2, 0.0}, StepCase{true, 1.0 / 240, 0.3, 135.0},
                      StepCase{true, 1.0 / 60, 0.2, 180.0}, StepCase{true, 1.0 / 1000, 0.1, 45.0}),
    // cube_step0p35_angle90_240Hz
    [](const ::testing::TestParamInfo<StepCase>& p) {
      const StepCase& c = p.param;
      return test::testName({c.sphere ? "sphere" : "cube", "step" + test::number(c.step),
                             "angle" + test::number(c.angle), test::number(std::round(1.0 / c.timestep)) + "Hz"});
    });

}  // namespace
}  // namespace tabletop
