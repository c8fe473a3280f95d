#pragma once

#include <vector>

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
///    Boxes meet the same fault where they part: their face contacts are
///    clipped afresh every step while they touch, but once a separating
///    axis exists the clipping adds nothing and the old points stay. A cube
///    gliding over the table's edge tilts by a micro-radian as its centre
///    passes the edge, the top no longer touches its face, and the points
///    left from the step before, carried along with the cube, held its
///    centre up: it tipped 2 cm late, when they had drifted past Bullet's
///    breaking threshold. So a manifold of a box with a box or the table
///    (not the ground plane, whose detector adds one point a step and
///    needs the old ones) drops every
///    point whose two sides have slid more than kStaleDrift apart along
///    the contact plane, which no point found in this step has.
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
///
/// And, when asked, one change to its integration:
///
/// 3. Second-order positions. Bullet moves a body by x += v1 dt with the
///    velocity v1 at the end of the step (semi-implicit Euler). Under a
///    steady acceleration a (gravity, sliding friction) that is short by
///    a dt^2 / 2 every step, a T dt / 2 after a time T: 8 mm of a 0.4 s
///    fall at 240 Hz, the whole error of free flight and of a sliding
///    sphere. With the trapezoid rule, x += (v0 + v1) dt / 2, the position
///    is exact for any acceleration that is constant through the step. The
///    rule is right only where the velocity changed smoothly; an impact
///    changes it at an instant, and averaging would move the body back
///    into what it struck. So a body's position is corrected by
///    -(v1 - v0) dt / 2 only when its velocity changed by no more than a
///    smooth force can give in one step (setSmoothAcceleration); larger
///    changes keep Bullet's update. Orientations keep Bullet's update.
///
/// And two changes to warm starting, Bullet's reuse of each contact's
/// impulses from the step before as the solver's first guess:
///
/// 4. Impacts are not reused. A contact whose bodies were closing faster
///    than smooth forces can make them in one step was an impact; its
///    impulse stopped that approach and is not a load the next step needs.
///    Reused, it flung the two bodies apart again and the solver's
///    iterations had to take it back: a 2 cm cube striking another at
///    20 m/s came away spinning at 10 rad/s and 1% slower than it. Its
///    impulses are dropped once the step's solve is done (a reader of the
///    step's contacts sees 0 for them). And a step with an impact gets
///    five times the solver's iterations: sequential impulses stop a heavy
///    body landing on a light one only over many sweeps, and a 3 kg ball
///    landing on a 0.3 kg slab drove the slab's corner 1 cm into the
///    table, whose recovery then lifted the ball (a random run gained
///    0.5% of its energy after a push; with five times the sweeps, 0.1%).
/// 5. Steps of another length. A resting load's impulse is its force times
///    the step, so impulses carried into a step of another length (the
///    world's substeps) are scaled by the ratio of the lengths.
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
