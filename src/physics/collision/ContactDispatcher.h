#pragma once

#include <memory>
#include <vector>

#include <btBulletCollisionCommon.h>
#include <BulletCollision/CollisionDispatch/btConvexConvexAlgorithm.h>

#include "physics/contact/BodySet.h"
#include "physics/collision/ContactResult.h"
#include "physics/collision/SolidOnFaceAlgorithm.h"
#include "physics/collision/SolidOnPlaneAlgorithm.h"

namespace tabletop {

/// Bullet's collision dispatcher with the pair table's finders
/// (PairTable.h) and these changes to how contact points are kept:
///  - every manifold breaks at Bullet's absolute threshold
///    (gContactBreakingThreshold, 2 cm), not one relative to the shape,
///    which a sliding face outran every step, so the solver never started
///    warm;
///  - the narrow phase adds its points through a ContactResult, which
///    merges a new point with a kept one only within a radius scaled to
///    the smaller body;
///  - two balls get their points ahead of touching, as every other pair.
/// docs/bullet-corrections.md says why and what was measured.
class ContactDispatcher : public btCollisionDispatcher {
 public:
  explicit ContactDispatcher(btCollisionConfiguration* configuration);

  /// Sets `bodies` aside until bringBack(): no pair with one of them is
  /// looked at, and the manifolds of each (with the table, the ground or
  /// another body set aside: StepGroups puts bodies that may touch in one
  /// group) leave the list every stage reads, kept as they are.
  void setAside(const BodySet& bodies);
  /// Puts the manifolds set aside back at the end of the list.
  void bringBack();
  const BodySet* asideBodies() const { return aside_; }
  /// Bullet's, for a manifold set aside too.
  void releaseManifold(btPersistentManifold* manifold) override;

 private:
  const BodySet* aside_ = nullptr;
  std::vector<btPersistentManifold*> asideManifolds_;
  // Bullet's convex-convex algorithm with multipoint perturbation.
  std::unique_ptr<btConvexConvexAlgorithm::CreateFunc> multipoint_;
  SolidOnPlaneAlgorithm::CreateFunc planeFinder_;
  std::vector<std::unique_ptr<SolidOnFaceAlgorithm::CreateFunc>> faceFinders_;  // one per row
  // The points each pair's ContactResult finds and is offered, one
  // storage for all.
  ContactResult::FoundPoints found_;
  OfferedPoints offered_;

  // Bullet's default near callback with a ContactResult in place of its
  // btManifoldResult.
  static void nearCallback(btBroadphasePair& pair, btCollisionDispatcher& dispatcher, const btDispatcherInfo& info);
};

}  // namespace tabletop
