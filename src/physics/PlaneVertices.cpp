#include "physics/PlaneVertices.h"

#include <algorithm>
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
  const auto* solid = static_cast<const btPolyhedralConvexShape*>(solidWrap->getCollisionShape());
  const btTransform& planePose = planeWrap->getWorldTransform();
  const btTransform& solidPose = solidWrap->getWorldTransform();
  const btVector3 normal = planePose.getBasis() * plane->getPlaneNormal();
  const btScalar offset = plane->getPlaneConstant() + normal.dot(planePose.getOrigin());
  // A hull's surface lies its margin outside its points; a box's vertices
  // are its corners already.
  const btScalar outset = solid->getShapeType() == BOX_SHAPE_PROXYTYPE ? btScalar(0) : solid->getMargin();

  result->setPersistentManifold(manifold_);
  const btScalar threshold = manifold_->getContactBreakingThreshold();
  // The lowest vertices, at most as many as a manifold keeps: a small
  // cube has its top corners within the threshold too.
  std::vector<std::pair<btScalar, btVector3>> near;
  for (int i = 0; i < solid->getNumVertices(); ++i) {
    btVector3 local;
    solid->getVertex(i, local);
    const btVector3 vertex = solidPose * local - normal * outset;
    const btScalar distance = normal.dot(vertex) - offset;
    if (distance <= threshold) near.emplace_back(distance, vertex);
  }
  std::sort(near.begin(), near.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  if (near.size() > MANIFOLD_CACHE_SIZE) near.resize(MANIFOLD_CACHE_SIZE);
  for (const auto& [distance, vertex] : near) {
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
