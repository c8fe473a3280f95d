#pragma once

#include <memory>

#include <btBulletCollisionCommon.h>
#include <BulletCollision/CollisionDispatch/btConvexConvexAlgorithm.h>

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
///    the smaller body;
///  - a cylinder against a box or a cylinder gets a whole face contact in
///    one step. Bullet's GJK finds one point a step, wandering round the
///    rim of a cylinder standing on the table; the manifold keeps four,
///    and each new one displaced a point that carried part of the load, so
///    a cylinder at rest crept. With Bullet's perturbation (the pair tried
///    at three small turns each step, its default for multipoint contacts)
///    the rim's points are all found at once (docs/bullet-corrections.md). Spheres are left out (the turns moved
///    a rolling ball's points off its lowest point and it sank into the
///    table), and so are cones (convex hulls): a cone placed resting on a
///    box was then found deeper in it than the 10 um a scene's start
///    allows. Box pairs already get whole faces by polyhedral clipping.
class ContactDispatcher : public btCollisionDispatcher {
 public:
  explicit ContactDispatcher(btCollisionConfiguration* configuration);

 private:
  // Bullet's convex-convex algorithm with multipoint perturbation.
  std::unique_ptr<btConvexConvexAlgorithm::CreateFunc> multipoint_;

  // Bullet's default near callback with a ContactResult in place of its
  // btManifoldResult.
  static void nearCallback(btBroadphasePair& pair, btCollisionDispatcher& dispatcher, const btDispatcherInfo& info);
};

}  // namespace tabletop
