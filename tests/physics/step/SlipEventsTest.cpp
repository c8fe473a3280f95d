// Slip events on hand-built contacts: which points slip at a part's start,
// and when, inside a part, a slip that its solve stopped reached zero,
// against the closed form of kinetic friction's constant deceleration.

#include "physics/step/SlipEvents.h"

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/HandBuiltContacts.h"

namespace tabletop {
namespace {

constexpr double kG = 9.81;     // m/s^2
constexpr double kHalf = 0.05;  // m
constexpr double kMass = 0.8;   // kg

// A cube on the four corners of its base on a fixed floor, sliding at
// `velocity`, with friction `mu` at each corner.
struct SlidingCube {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btBoxShape shape{btVector3(kHalf, kHalf, kHalf)};
  btStaticPlaneShape floorShape{btVector3(0, 1, 0), 0};
  btCollisionObject floor;
  std::unique_ptr<btRigidBody> cube;
  btPersistentManifold* manifold = nullptr;

  SlidingCube(const btVector3& velocity, double mu) {
    cube = test::movingBody(shape, kMass, btVector3(0, kHalf, 0), velocity, 0.0);
    floor.setCollisionShape(&floorShape);
    manifold = dispatcher.getNewManifold(cube.get(), &floor);
    test::addBaseCorners(*manifold, kHalf, mu);
  }
  ~SlidingCube() { dispatcher.releaseManifold(manifold); }
};

// Every corner of a cube sliding faster than share x mu g length slips;
// none of one sliding slower, nor of one at rest.
TEST(SlipEvents, APointSlipsWhenItsSlipIsMoreThanTheShareOfWhatFrictionTakes) {
  const double mu = 0.4, length = 1.0 / 60, share = 1e-3;
  const double threshold = share * mu * kG * length;  // m/s
  std::vector<Slip> slips;
  for (const double speed : {0.0, 0.5 * threshold, 2.0 * threshold, 0.7}) {
    SlidingCube sliding(btVector3(0, 0, -speed), mu);
    slippingPoints(sliding.dispatcher, kG, length, share, slips);
    EXPECT_EQ(slips.size(), speed > threshold ? 4u : 0u) << speed << " m/s";
    for (const Slip& slip : slips) EXPECT_EQ(slip.velocity, btVector3(0, 0, -speed));
  }
}

// A cube sliding at v0 < mu g length stops inside the part, at
// v0 / (mu g). The part's solve held it still at the end, with the
// friction impulse m v0 (less than mu m g length, the limit): the time is
// found from that friction and what kinetic friction would have added.
// A slip that stops within a hundredth of the part from either end is
// left to the part's solve (the part's length comes back).
TEST(SlipEvents, ASlipStoppedByTheSolveStoppedAtVOverMuG) {
  for (const double mu : {0.2, 0.6}) {
    for (const double rate : {30.0, 60.0, 240.0}) {
      for (const double share : {0.005, 0.3, 0.8, 0.995}) {
        const double length = 1.0 / rate, v0 = share * mu * kG * length;
        const std::string where = "mu " + std::to_string(mu) + ", " + std::to_string(rate) + " Hz, stop at " +
                                  std::to_string(share) + " of the part";
        SlidingCube sliding(btVector3(v0, 0, 0), mu);
        std::vector<Slip> slips;
        slippingPoints(sliding.dispatcher, kG, length, 1e-3, slips);
        ASSERT_EQ(slips.size(), 4u) << where;
        // What the solve leaves: the cube still, each corner a quarter of
        // the weight's impulse and of the friction that stopped it.
        sliding.cube->setLinearVelocity(btVector3(0, 0, 0));
        for (int p = 0; p < 4; ++p) {
          btManifoldPoint& point = sliding.manifold->getContactPoint(p);
          point.m_appliedImpulse = 0.25 * kMass * kG * length;
          point.m_lateralFrictionDir1 = btVector3(1, 0, 0);
          point.m_appliedImpulseLateral1 = -0.25 * kMass * v0;
        }
        const SlipTurn turn = earliestSlipTurn(slips, kG, length, 1e-3);
        const bool inside = share > 0.01 && share < 0.99;
        EXPECT_NEAR(turn.time, inside ? v0 / (mu * kG) : length, 1e-15) << where;
        EXPECT_EQ(turn.manifold != nullptr, inside) << where;
        if (inside) {
          EXPECT_FALSE(turn.reversed) << where;
        }
      }
    }
  }
}

}  // namespace
}  // namespace tabletop
