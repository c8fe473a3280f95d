// IslandSolver on hand-built islands: a cube on its four bottom corners on
// a fixed box, resting or sliding, solved for one part and compared with
// the closed forms of Coulomb friction (no collision, no world: the
// solver alone, as DynamicsWorld hands it one island).

#include "physics/solver/IslandSolver.h"

#include <cmath>
#include <memory>
#include <string>

#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>

#include "support/HandBuiltContacts.h"

namespace tabletop {
namespace {

constexpr double kG = 9.81;     // m/s^2
constexpr double kHalf = 0.05;  // m, the cube's half side
constexpr double kMass = 1.3;   // kg
// An exact solve gives each row the compliance kDirectCfm: a row carrying
// a force F closes at kDirectCfm F (m/s per N). No row carries more than
// the weight, so velocities are exact to this, turns to this over the
// half side, impulses to the mass times it.
constexpr double kExact = IslandSolver::kDirectCfm * kMass * kG;  // m/s
// Parts a swept resting island is solved for, each warm-started from the
// last, as the steps of a run do; and the sweeps' residual velocity then,
// m/s (a micrometre in ten seconds).
constexpr int kParts = 20;
constexpr double kSwept = 1e-7;

// The cube at the origin's height kHalf on a fixed box whose top is y = 0,
// moving at `velocity`, its weight applied as a force, and a manifold of
// its four bottom corners, touching, with friction `mu`.
struct Island {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btBoxShape cubeShape{btVector3(kHalf, kHalf, kHalf)};
  btBoxShape groundShape{btVector3(1, 0.1, 1)};
  std::unique_ptr<btRigidBody> cube;
  btCollisionObject ground;
  btPersistentManifold* manifold = nullptr;

  Island(const btVector3& velocity, double mu) {
    cube = test::movingBody(cubeShape, kMass, btVector3(0, kHalf, 0), velocity, kG);
    ground.setCollisionShape(&groundShape);
    ground.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(0, -0.1, 0)));
    ground.setCollisionFlags(btCollisionObject::CF_STATIC_OBJECT);
    manifold = dispatcher.getNewManifold(cube.get(), &ground);
    test::addBaseCorners(*manifold, kHalf, mu);
  }
  ~Island() { dispatcher.releaseManifold(manifold); }

  // One part of `dt` s, solved as the step solves an island.
  void solve(IslandSolver& solver, double dt) {
    btContactSolverInfo info;
    info.m_timeStep = dt;
    info.m_numIterations = 10;
    info.m_minimumSolverBatchSize = 1;
    info.m_splitImpulse = 1;
    info.m_splitImpulsePenetrationThreshold = 0;
    info.m_warmstartingFactor = 1;
    btCollisionObject* bodies[] = {cube.get()};
    solver.solveGroup(bodies, 1, &manifold, 1, nullptr, 0, info, nullptr, &dispatcher);
  }
  double normalImpulse() const {
    double sum = 0;
    for (int p = 0; p < manifold->getNumContacts(); ++p) sum += manifold->getContactPoint(p).getAppliedImpulse();
    return sum;
  }
};

std::string describe(double angle, double mu, double rate) {
  return "slip at " + std::to_string(angle) + " deg, mu " + std::to_string(mu) + ", " + std::to_string(rate) + " Hz";
}

// A cube sliding at v0 > mu g dt keeps sliding: the part takes mu g dt off
// its speed along its slip, and the normal impulse is its weight's, m g dt;
// it neither veers, rises nor pitches (the exact solve shifts the load to
// the leading corners, so the friction under the centre turns nothing).
// One slow enough to stop inside the part ends it at rest: static friction
// holds it there. Swept over directions, friction and rates, for both
// choices that pivot a sliding island.
TEST(IslandSolver, ASlidingCubeLosesMuGdtAlongItsSlipAndStopsWhereThatIsAll) {
  for (const ContactSolver choice : {ContactSolver::Automatic, ContactSolver::Dantzig}) {
    for (const double angle : {0.0, 37.0, 90.0}) {
      for (const double mu : {0.2, 0.5}) {
        for (const double rate : {30.0, 60.0, 240.0}) {
          const double dt = 1.0 / rate, a = angle * SIMD_PI / 180;
          const btVector3 along(std::cos(a), 0, std::sin(a));
          const std::string where = describe(angle, mu, rate);
          IslandSolver solver(choice, kDirectRowLimit, kG);
          Island sliding(along * 0.5, mu);
          sliding.solve(solver, dt);
          const btVector3 v = sliding.cube->getLinearVelocity();
          EXPECT_NEAR(v.dot(along), 0.5 - mu * kG * dt, kExact) << where;
          EXPECT_NEAR((v - along * v.dot(along)).length(), 0.0, kExact) << where;
          EXPECT_NEAR(sliding.cube->getAngularVelocity().length(), 0.0, kExact / kHalf) << where;
          EXPECT_NEAR(sliding.normalImpulse(), kMass * kG * dt, kMass * kExact) << where;

          Island stopping(along * (0.5 * mu * kG * dt), mu);
          stopping.solve(solver, dt);
          EXPECT_NEAR(stopping.cube->getLinearVelocity().length(), 0.0, kExact) << where;
          EXPECT_NEAR(stopping.cube->getAngularVelocity().length(), 0.0, kExact / kHalf) << where;
          EXPECT_NEAR(stopping.normalImpulse(), kMass * kG * dt, kMass * kExact) << where;
          EXPECT_EQ(solver.use().direct, 2) << where;
          EXPECT_EQ(solver.use().largestIsland, 1) << where;
        }
      }
    }
  }
}

// At rest, the island carries the cube's weight and nothing moves: pivoted
// (dantzig) exactly from the first part; swept (auto sweeps a body resting
// on a fixed support, and sequential impulses sweep everything) to the
// sweeps' residual once warm-started over kParts parts.
TEST(IslandSolver, ARestingCubeCarriesItsWeightAndStaysStill) {
  for (const double rate : {30.0, 60.0, 240.0}) {
    const double dt = 1.0 / rate;
    const std::string where = std::to_string(rate) + " Hz";
    IslandSolver pivoted(ContactSolver::Dantzig, kDirectRowLimit, kG);
    Island once(btVector3(0, 0, 0), 0.5);
    once.solve(pivoted, dt);
    EXPECT_NEAR(once.cube->getLinearVelocity().length(), 0.0, kExact) << where;
    EXPECT_NEAR(once.cube->getAngularVelocity().length(), 0.0, kExact / kHalf) << where;
    EXPECT_NEAR(once.normalImpulse(), kMass * kG * dt, kMass * kExact) << where;
    EXPECT_EQ(pivoted.use().direct, 1) << where;
    for (const ContactSolver choice : {ContactSolver::Automatic, ContactSolver::SequentialImpulse}) {
      IslandSolver swept(choice, kDirectRowLimit, kG);
      Island resting(btVector3(0, 0, 0), 0.5);
      for (int part = 0; part < kParts; ++part) resting.solve(swept, dt);
      const std::string how = std::string(toString(choice)) + ", " + where;
      EXPECT_NEAR(resting.cube->getLinearVelocity().length(), 0.0, kSwept) << how;
      EXPECT_NEAR(resting.cube->getAngularVelocity().length(), 0.0, kSwept / kHalf) << how;
      EXPECT_NEAR(resting.normalImpulse(), kMass * kG * dt, kMass * kSwept) << how;
      EXPECT_EQ(swept.use().swept, kParts) << how;
      EXPECT_EQ(swept.use().direct, 0) << how;
    }
  }
}

}  // namespace
}  // namespace tabletop
