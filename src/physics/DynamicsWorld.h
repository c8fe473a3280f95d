#pragma once

#include <btBulletDynamicsCommon.h>

namespace tabletop {

/// Bullet's discrete dynamics world with two corrections to its contacts,
/// each found by comparing rolling spheres with the closed form
/// a = 5 g rf / (7 r).
///
/// 1. Stale points. A sphere touches a convex body at one point, but
///    Bullet's persistent manifold keeps up to four points from earlier
///    steps until they drift past the breaking threshold. On a rolling
///    sphere those old points lie off its lowest point, no longer touching,
///    yet still take part in the solve: a 3 cm sphere with rf = 2 mm
///    decelerated at 0.556 m/s^2 instead of 0.467. Before each solve, every
///    manifold that involves a sphere keeps only its deepest point.
///
/// 2. Rolling friction. Bullet 3.24 clamps rolling friction on two fixed
///    horizontal axes separately, a square friction cone: a ball rolling at
///    45 degrees to them is braked sqrt(2) times too hard (a diagonal step
///    came out 0.716 of its length). This world applies rolling resistance
///    itself, as one angular impulse rf N dt against the rolling part of
///    each contact's relative spin, clamped so it never reverses the roll;
///    spinning friction likewise about the normal (Bullet gates its spin
///    row on rolling friction, so it goes too). N dt is the contact's
///    normal impulse of the previous step. Bodies carry their Material in
///    their user pointer; Bullet's own rolling and spinning friction are 0.
class DynamicsWorld : public btDiscreteDynamicsWorld {
 public:
  using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;

  void solveConstraints(btContactSolverInfo& solverInfo) override;
  /// Adds gravity to the forces of the coming step, and applies the
  /// rolling-resistance impulses.
  void applyGravity() override;

 private:
  void applyRollingResistance();
};

}  // namespace tabletop
