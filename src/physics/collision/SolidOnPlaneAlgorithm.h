#pragma once

#include <btBulletCollisionCommon.h>
#include <BulletCollision/CollisionDispatch/btActivatingCollisionAlgorithm.h>

#include "physics/collision/SolidCorners.h"

namespace tabletop {

/// A box, a convex hull (a cone) or a cylinder against the floor plane:
/// the corners of the face nearest the plane (a cylinder's rims as 32
/// points), at most four, chosen by a CornerChoice and found again each
/// step, as polyhedral clipping finds a box's whole face on the table.
/// Bullet's plane test adds one corner a step (and a few by perturbation)
/// and keeps the rest from earlier steps; on a sliding cube those slid
/// along with it from where it touched, and it yawed and stopped short of
/// its closed-form slide (docs/bullet-corrections.md).
/// Because every touching vertex comes back each step, the pair's drifted
/// points can be dropped, as a box pair's are (PairTable.h).
class SolidOnPlaneAlgorithm : public btActivatingCollisionAlgorithm {
 public:
  SolidOnPlaneAlgorithm(const btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* body0,
                const btCollisionObjectWrapper* body1);
  ~SolidOnPlaneAlgorithm() override;

  void processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& info, btManifoldResult* result) override;
  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override {
    return 1;
  }
  void getAllContactManifolds(btManifoldArray& manifolds) override {
    if (manifold_) manifolds.push_back(manifold_);
  }

  /// Registered with a dispatcher for box and hull against the plane.
  struct CreateFunc : public btCollisionAlgorithmCreateFunc {
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                   const btCollisionObjectWrapper* body0,
                                                   const btCollisionObjectWrapper* body1) override;
  };

 private:
  btPersistentManifold* manifold_ = nullptr;
  CornerChoice choice_;
  // Kept from step to step for their storage: the solid's corners and
  // those near the plane.
  std::vector<btVector3> corners_;
  std::vector<NearCorner> near_;
};

}  // namespace tabletop
