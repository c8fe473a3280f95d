#include "physics/collision/SolidOnPlaneAlgorithm.h"

#include <new>
#include <utility>
#include <vector>

namespace tabletop {

SolidOnPlaneAlgorithm::SolidOnPlaneAlgorithm(const btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* body0,
                             const btCollisionObjectWrapper* body1)
    : btActivatingCollisionAlgorithm(info, body0, body1) {
  manifold_ = m_dispatcher->getNewManifold(body0->getCollisionObject(), body1->getCollisionObject());
}

SolidOnPlaneAlgorithm::~SolidOnPlaneAlgorithm() {
  if (manifold_) m_dispatcher->releaseManifold(manifold_);
}

void SolidOnPlaneAlgorithm::processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                                     const btDispatcherInfo& info, btManifoldResult* result) {
  const bool planeFirst = body0->getCollisionShape()->getShapeType() == STATIC_PLANE_PROXYTYPE;
  const btCollisionObjectWrapper* planeWrap = planeFirst ? body0 : body1;
  const btCollisionObjectWrapper* solidWrap = planeFirst ? body1 : body0;
  const auto* plane = static_cast<const btStaticPlaneShape*>(planeWrap->getCollisionShape());
  const auto* solid = static_cast<const btConvexShape*>(solidWrap->getCollisionShape());
  const btTransform& planePose = planeWrap->getWorldTransform();
  const btTransform& solidPose = solidWrap->getWorldTransform();
  const btVector3 normal = planePose.getBasis() * plane->getPlaneNormal();
  const btScalar offset = plane->getPlaneConstant() + normal.dot(planePose.getOrigin());

  result->setPersistentManifold(manifold_);
  nearCorners(*solid, solidPose, normal, offset, manifold_->getContactBreakingThreshold(),
              {solidWrap->getCollisionObject(), planeWrap->getCollisionObject(), info.m_timeStep}, corners_, near_);
  if (near_.empty()) {
    choice_.forget();
  } else {
    addCornerPoints(*result, choice_.choose(*solid, near_), normal, planeFirst);
  }
  result->refreshContactPoints();
}

btCollisionAlgorithm* SolidOnPlaneAlgorithm::CreateFunc::CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                                        const btCollisionObjectWrapper* body0,
                                                                        const btCollisionObjectWrapper* body1) {
  void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(sizeof(SolidOnPlaneAlgorithm));
  return new (memory) SolidOnPlaneAlgorithm(info, body0, body1);
}

}  // namespace tabletop
