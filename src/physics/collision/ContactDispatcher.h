#pragma once

#include <memory>

#include <btBulletCollisionCommon.h>
#include <BulletCollision/CollisionDispatch/btConvexConvexAlgorithm.h>

#include "physics/collision/ContactResult.h"
#include "physics/collision/SolidOnFaceAlgorithm.h"
#include "physics/collision/SolidOnPlaneAlgorithm.h"

namespace tabletop {

/// Bullet's collision dispatcher with these changes to how contact points
/// are found and kept:
///  - every manifold breaks at Bullet's absolute threshold
///    (gContactBreakingThreshold, 2 cm), not one relative to the shape,
///    which a sliding face outran every step, so the solver never started
///    warm;
///  - the narrow phase adds its points through a ContactResult, which
///    merges a new point with a kept one only within a radius scaled to
///    the smaller body;
///  - a cylinder against a box or a cylinder gets a whole face contact in
///    one step, by Bullet's perturbation (the pair tried at three small
///    turns), where GJK alone finds one rim point a step and a cylinder at
///    rest crept (spheres and cones are left out);
///  - a box, a cylinder or a hull resting on a box's face gets the corners
///    of its face there (SolidOnFaceAlgorithm), and the floor likewise
///    (SolidOnPlaneAlgorithm); docs/bullet-corrections.md says why and what was
///    measured.
class ContactDispatcher : public btCollisionDispatcher {
 public:
  explicit ContactDispatcher(btCollisionConfiguration* configuration);

 private:
  // Bullet's convex-convex algorithm with multipoint perturbation.
  std::unique_ptr<btConvexConvexAlgorithm::CreateFunc> multipoint_;
  SolidOnPlaneAlgorithm::CreateFunc planeVertices_;
  std::unique_ptr<SolidOnFaceAlgorithm::CreateFunc> cylinderOnBox_, hullOnBox_, boxOnBox_, cylinderOnCylinder_, hullOnCylinder_,
      hullOnHull_;
  // The points each pair's ContactResult finds, one storage for all.
  ContactResult::FoundPoints found_;

  // Bullet's default near callback with a ContactResult in place of its
  // btManifoldResult.
  static void nearCallback(btBroadphasePair& pair, btCollisionDispatcher& dispatcher, const btDispatcherInfo& info);
};

}  // namespace tabletop
