#include "physics/PlaneVertices.h"

#include <algorithm>
#include <cmath>
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

namespace {

constexpr int kRimPoints = 32;  // a cylinder's rims, as points

// The solid's corners in its own frame: a polyhedron's vertices (a hull's
// drawn out by its margin along `down`, the way to the plane, where its
// surface is), or points around a cylinder's two rims.
std::vector<btVector3> corners(const btConvexShape& solid, const btVector3& down) {
  std::vector<btVector3> out;
  if (solid.getShapeType() == CYLINDER_SHAPE_PROXYTYPE) {
    const btVector3 half = static_cast<const btCylinderShape&>(solid).getHalfExtentsWithMargin();
    for (int i = 0; i < kRimPoints; ++i) {
      const double a = 2.0 * SIMD_PI * i / kRimPoints;
      for (const double y : {-half.y(), half.y()}) out.emplace_back(half.x() * std::cos(a), y, half.z() * std::sin(a));
    }
    return out;
  }
  const auto& polyhedron = static_cast<const btPolyhedralConvexShape&>(solid);
  const btScalar outset = solid.getShapeType() == BOX_SHAPE_PROXYTYPE ? btScalar(0) : solid.getMargin();
  for (int i = 0; i < polyhedron.getNumVertices(); ++i) {
    btVector3 v;
    polyhedron.getVertex(i, v);
    out.push_back(v + down * outset);
  }
  return out;
}

}  // namespace

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
  std::vector<std::pair<btScalar, btVector3>> near;  // distance to the plane, world point
  for (const btVector3& local : corners(*solid, solidPose.getBasis().transpose() * -normal)) {
    const btVector3 vertex = solidPose * local;
    const btScalar distance = normal.dot(vertex) - offset;
    if (distance <= threshold) near.emplace_back(distance, vertex);
  }
  if (near.empty()) {
    result->refreshContactPoints();
    return;
  }
  // The face nearest the plane: the corners within a tenth of the solid's
  // smallest half size of the lowest (a small cube's top corners are near
  // the plane too), spread out if more than a manifold keeps (a rim's 32
  // points give four at right angles, not four neighbours).
  btVector3 low, high;
  solid->getAabb(btTransform::getIdentity(), low, high);
  const btVector3 size = high - low;
  const btScalar band = 0.05 * std::min({size.x(), size.y(), size.z()});
  std::sort(near.begin(), near.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  const btScalar lowest = near.front().first;
  near.erase(std::remove_if(near.begin(), near.end(), [&](const auto& p) { return p.first > lowest + band; }),
             near.end());
  std::vector<std::pair<btScalar, btVector3>> chosen{near.front()};
  while (chosen.size() < std::min<std::size_t>(MANIFOLD_CACHE_SIZE, near.size())) {
    std::size_t best = 0;
    btScalar farthest = -1;
    for (std::size_t i = 0; i < near.size(); ++i) {
      btScalar closest = BT_LARGE_FLOAT;
      for (const auto& c : chosen) closest = std::min(closest, (near[i].second - c.second).length2());
      if (closest > farthest) farthest = closest, best = i;
    }
    if (farthest <= 0) break;
    chosen.push_back(near[best]);
  }
  for (const auto& [distance, vertex] : chosen) {
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
