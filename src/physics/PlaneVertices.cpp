#include "physics/PlaneVertices.h"

#include <new>
#include <utility>
#include <vector>

namespace tabletop {

PlaneVertices::PlaneVertices(const btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* body0,
                             const btCollisionObjectWrapper* body1)
    : btActivatingCollisionAlgorithm(info, body0, body1) {
  manifold_ = m_dispatcher->getNewManifold(body0->getCollisionObject(), body1->getCollisionObject());
}

PlaneVertices::~PlaneVertices() {
  if (manifold_) m_dispatcher->releaseManifold(manifold_);
}

void PlaneVertices::processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                                     const btDispatcherInfo&, btManifoldResult* result) {
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
  const btScalar threshold = manifold_->getContactBreakingThreshold();
  std::vector<NearCorner> near;
  const std::vector<btVector3> corners = solidCorners(*solid, solidPose.getBasis().transpose() * -normal);
  for (int i = 0; i < static_cast<int>(corners.size()); ++i) {
    const btVector3 vertex = solidPose * corners[static_cast<std::size_t>(i)];
    const btScalar distance = normal.dot(vertex) - offset;
    if (distance <= threshold) near.push_back({i, distance, vertex});
  }
  if (near.empty()) {
    choice_.forget();
    result->refreshContactPoints();
    return;
  }
  for (const auto& [corner, distance, vertex] : choice_.choose(*solid, std::move(near))) {
    const btVector3 onPlane = vertex - normal * distance;
    // The result's body B is its second body: the normal points from B to A.
    if (planeFirst) {
      result->addContactPoint(-normal, vertex, distance);
    } else {
      result->addContactPoint(normal, onPlane, distance);
    }
  }
  result->refreshContactPoints();
}

btCollisionAlgorithm* PlaneVertices::CreateFunc::CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                                        const btCollisionObjectWrapper* body0,
                                                                        const btCollisionObjectWrapper* body1) {
  void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(sizeof(PlaneVertices));
  return new (memory) PlaneVertices(info, body0, body1);
}

}  // namespace tabletop
