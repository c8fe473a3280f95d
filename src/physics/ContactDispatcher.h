#pragma once

#include <btBulletCollisionCommon.h>

namespace tabletop {

/// Bullet's collision dispatcher with two changes to how contact points
/// are kept:
///  - every manifold breaks at Bullet's absolute threshold
///    (gContactBreakingThreshold, 2 cm), not at one relative to the shape
///    (its angular motion disc times 2 cm: 1.7 mm for a 0.1 m cube, so a
///    face sliding 8 mm per step lost every point every step and the
///    solver never started warm);
///  - the narrow phase adds its points through a ContactResult, which
///    merges a new point with a kept one only within a radius scaled to
///    the smaller body.
class ContactDispatcher : public btCollisionDispatcher {
 public:
  explicit ContactDispatcher(btCollisionConfiguration* configuration);

 private:
  // Bullet's default near callback with a ContactResult in place of its
  // btManifoldResult.
  static void nearCallback(btBroadphasePair& pair, btCollisionDispatcher& dispatcher, const btDispatcherInfo& info);
};

}  // namespace tabletop
