#pragma once

#include <vector>

#include <btBulletDynamicsCommon.h>

#include "core/FreeRotation.h"
#include "physics/contact/BodySet.h"

namespace tabletop {

/// Every one of Bullet's gyroscopic flags on a rigid body (Settings::gyroscopic
/// picks one; a part that turns a body itself clears them for its solve).
inline constexpr int kGyroscopicFlags =
    BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT | BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_WORLD | BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY;

/// The bodies that touch nothing in a part (no contact point of any
/// manifold, so no row of the solver acts on them) and bear no applied
/// torque turn as a free rigid body does: their spin and orientation follow Euler's equations' exact
/// solution (core/FreeRotation.h) from the part's start, in place of
/// Bullet's rotation and its gyroscopic term, which lost 7.6% of a tumbling
/// box's energy in 10 s at 60 Hz (docs/free-rotation.md). Their centres,
/// and every body that touches something, move as before.
class FreeFlight {
 public:
  /// Before the part's solve, its contacts found: the free bodies, whose
  /// gyroscopic term the solve is to leave out.
  void find(const btAlignedObjectArray<btRigidBody*>& bodies, btDispatcher& dispatcher);
  /// After the solve, before the transforms are integrated: gives each free
  /// body its exact spin at the part's end and its gyroscopic flags back.
  /// `startSpins` holds each non-static body's spin at the part's start
  /// (none if its size is not the bodies': then Bullet's turn stays).
  void start(const std::vector<btVector3>& startSpins, double dt);
  /// After: puts the free bodies at their exact orientation, keeping the
  /// centre the integration gave (a body whose motion a continuous
  /// collision sweep cut short keeps Bullet's pose).
  void finish();

 private:
  struct Free {
    btRigidBody* body;
    int index;  // in the world's non-static bodies
    int flags;  // its own, with the gyroscopic term
    btQuaternion orientation{0, 0, 0, 1};  // at the part's end
    bool turned = false;
  };
  std::vector<Free> free_;
  BodySet touching_;
};

}  // namespace tabletop
