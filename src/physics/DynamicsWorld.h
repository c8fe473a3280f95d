#pragma once

#include <vector>

#include <btBulletDynamicsCommon.h>

namespace tabletop {

/// Bullet's discrete dynamics world with its contacts and integration
/// corrected where a closed form showed them wrong (docs/bullet-corrections.md
/// has what was measured):
///  1. stale contact points are dropped before the solve: a sphere's
///     manifold keeps its deepest point; box-box and box-table points whose
///     sides slid apart along the contact plane go;
///  2. rolling and spinning resistance are one isotropic angular impulse
///     per contact (Bullet's square friction cone braked a diagonal roll
///     sqrt(2) times too hard);
///  3. optionally, positions follow the trapezoid rule where the velocity
///     changed smoothly (exact for a constant acceleration), Bullet's update
///     where an impact changed it;
///  4. impacts are not warm-started, and their step gets five times the
///     iterations;
///  5. impulses carried into a step of another length (a substep) are
///     scaled by the ratio of the lengths.
class DynamicsWorld : public btDiscreteDynamicsWorld {
 public:
  using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;

  /// The largest acceleration smooth forces (gravity, sliding friction)
  /// give a body, m/s^2: a velocity change beyond it times the step is an
  /// impact (0, the default: every contact is reused and no update is
  /// second order).
  void setSmoothAcceleration(double limit) { smoothAcceleration_ = limit; }
  double smoothAcceleration() const { return smoothAcceleration_; }
  /// Turns the second-order position update on (off by default).
  void setSecondOrderPositions(bool on) { secondOrder_ = on; }

  /// One step of `dt` seconds, no interpolation; carried impulses are
  /// scaled when `dt` differs from the step before.
  void step(double dt);

  void solveConstraints(btContactSolverInfo& solverInfo) override;
  /// Reads the velocities a step starts from, adds gravity to the forces
  /// of the coming step, and applies the rolling-resistance impulses.
  void applyGravity() override;

 protected:
  void integrateTransforms(btScalar timeStep) override;

 private:
  void applyRollingResistance();

  bool markImpacts(double timeStep);
  void forgetImpacts();

  double smoothAcceleration_ = 0.0;
  bool secondOrder_ = false;
  double lastStep_ = 0.0;  // the length of the step before, s (0: none yet)
  std::vector<btVector3> startVelocities_;  // per non-static body, at the step's start
};

}  // namespace tabletop
