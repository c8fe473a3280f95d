#include "physics/collision/SolidOnFaceAlgorithm.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <utility>
#include <vector>

#include <BulletCollision/NarrowPhaseCollision/btPolyhedralContactClipping.h>

#include "physics/collision/ContactResult.h"
#include "physics/collision/ClosestPoints.h"
#include "physics/contact/ContactKinematics.h"
#include "physics/shapes/RoundEnds.h"
#include "physics/shapes/ShapeKinds.h"

namespace tabletop {

SolidOnFaceAlgorithm::SolidOnFaceAlgorithm(const btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* body0,
                           const btCollisionObjectWrapper* body1, btCollisionAlgorithmCreateFunc& otherwise)
    : btActivatingCollisionAlgorithm(info, body0, body1), otherwiseFunc_(otherwise) {
  manifold_ = m_dispatcher->getNewManifold(body0->getCollisionObject(), body1->getCollisionObject());
}

SolidOnFaceAlgorithm::~SolidOnFaceAlgorithm() {
  if (otherwise_) {
    otherwise_->~btCollisionAlgorithm();
    m_dispatcher->freeCollisionAlgorithm(otherwise_);
  }
  if (manifold_) m_dispatcher->releaseManifold(manifold_);
}

void SolidOnFaceAlgorithm::getAllContactManifolds(btManifoldArray& manifolds) {
  if (manifold_) manifolds.push_back(manifold_);
  if (otherwise_) otherwise_->getAllContactManifolds(manifolds);
}

void SolidOnFaceAlgorithm::clearOtherwise() {
  if (!otherwise_) return;
  btManifoldArray manifolds;
  otherwise_->getAllContactManifolds(manifolds);
  for (int i = 0; i < manifolds.size(); ++i) manifolds[i]->clearManifold();
}

void SolidOnFaceAlgorithm::processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                                    const btDispatcherInfo& info, btManifoldResult* result) {
  // Two bodies with faces: the first whose face the other rests on, a
  // box's before a cylinder's before a cone's, else the first body's, so
  // the roles stay put from step to step.
  const int rank0 = faceRank(*body0->getCollisionShape());
  const int rank1 = faceRank(*body1->getCollisionShape());
  const bool firstFaced = rank0 >= rank1;
  const btCollisionObjectWrapper* faced = firstFaced ? body0 : body1;
  const btCollisionObjectWrapper* other = firstFaced ? body1 : body0;
  // The other way round only for a body that can move: the table's top
  // never rests on a solid's face.
  const bool otherWay = std::min(rank0, rank1) > 0 && !faced->getCollisionObject()->isStaticOrKinematicObject();
  if (touchFace(faced, other, firstFaced, info.m_timeStep, result) ||
      (otherWay && touchFace(other, faced, !firstFaced, info.m_timeStep, result))) {
    clearOtherwise();
    return;
  }
  solid_ = -1;
  if (!otherwise_) {
    btCollisionAlgorithmConstructionInfo construction(m_dispatcher, 1);
    construction.m_manifold = nullptr;  // the constructor leaves it unset
    otherwise_ = otherwiseFunc_.CreateCollisionAlgorithm(construction, body0, body1);
  }
  otherwise_->processCollision(body0, body1, info, result);
  if (rank0 == kBoxRank && rank1 == kBoxRank) {
    clipApart(body0, body1, result);
  } else if (addCornersOverFace(faced, other, firstFaced, info.m_timeStep, result)) {
    return;
  }
  manifold_->clearManifold();
  choice_.forget();
}

void SolidOnFaceAlgorithm::clipApart(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                             btManifoldResult* result) {
  btManifoldArray manifolds;
  otherwise_->getAllContactManifolds(manifolds);
  if (manifolds.size() != 1) return;
  // Only points found in this step count (the solve drops the others).
  dropDriftedPoints(*manifolds[0]);
  if (manifolds[0]->getNumContacts() > 0) return;
  const auto* a = static_cast<const btBoxShape*>(body0->getCollisionShape());
  const auto* b = static_cast<const btBoxShape*>(body1->getCollisionShape());
  if (!a->getConvexPolyhedron() || !b->getConvexPolyhedron()) return;
  const btPointCollector closest = closestPoints(*a, body0->getWorldTransform(), *b, body1->getWorldTransform());
  const btScalar reach = manifolds[0]->getContactBreakingThreshold();
  if (!closest.m_hasResult || !(closest.m_distance > 0) || closest.m_distance > reach) return;
  // This result's body 1 is B: its normal points from body 1 to body 0.
  result->setPersistentManifold(manifolds[0]);
  btVertexArray clipped, scratch;
  btPolyhedralContactClipping::clipHullAgainstHull(closest.m_normalOnBInWorld, *a->getConvexPolyhedron(),
                                                   *b->getConvexPolyhedron(), body0->getWorldTransform(),
                                                   body1->getWorldTransform(), -reach, reach, clipped, scratch, *result);
  result->refreshContactPoints();
}

int SolidOnFaceAlgorithm::faceRank(const btCollisionShape& shape) {
  switch (shape.getShapeType()) {
    case BOX_SHAPE_PROXYTYPE: return kBoxRank;
    case CYLINDER_SHAPE_PROXYTYPE: return 2;
    case CONVEX_HULL_SHAPE_PROXYTYPE: return 1;
    default: return 0;
  }
}

SolidOnFaceAlgorithm::Face SolidOnFaceAlgorithm::outerFace(const btCollisionObjectWrapper* boxWrap,
                                           const btCollisionObjectWrapper* solidWrap, btScalar timeStep) {
  near_.clear();
  const auto* solid = static_cast<const btConvexShape*>(solidWrap->getCollisionShape());
  const btTransform& boxPose = boxWrap->getWorldTransform();
  const btTransform& solidPose = solidWrap->getWorldTransform();
  const FacedShape& shape = facesFor(*boxWrap->getCollisionShape());
  Face face;
  if (shape.first > shape.last) return face;  // none

  // The face the solid lies farthest out from, along its normal: where it
  // rests if it rests on the body.
  int end = 0;
  btScalar separation = -BT_LARGE_FLOAT;
  for (int i = shape.first; i <= shape.last; ++i) {
    for (int e = 0; e < 2; ++e) {
      const btVector3 n = boxPose.getBasis().getColumn(i) * (e == 0 ? 1 : -1);
      const btVector3 lowest = solidPose * solid->localGetSupportingVertex(solidPose.getBasis().transpose() * -n);
      const btScalar apart = n.dot(lowest - boxPose.getOrigin()) - shape.out(i, e);
      if (apart > separation) separation = apart, face.axis = i, end = e;
    }
  }
  face.normal = boxPose.getBasis().getColumn(face.axis) * (end == 0 ? 1 : -1);
  face.round = shape.round;
  face.half = shape.half;
  face.radius = shape.radius[end];
  face.thickness = shape.out(face.axis, 0) + shape.out(face.axis, 1);
  const btScalar offset = face.normal.dot(boxPose.getOrigin()) + shape.out(face.axis, end);
  if (face.normal.dot(solidPose.getOrigin()) <= offset) return face;  // its centre is not out over the face
  nearCorners(*solid, solidPose, face.normal, offset, manifold_->getContactBreakingThreshold(),
              {solidWrap->getCollisionObject(), boxWrap->getCollisionObject(), timeStep}, corners_, near_);
  face.out = true;
  return face;
}

const SolidOnFaceAlgorithm::FacedShape& SolidOnFaceAlgorithm::facesFor(const btCollisionShape& shape) {
  for (int k = 0; k < 2; ++k) {
    if (facedShapes_[k] == &shape) return faces_[k];
  }
  const int k = facedShapes_[0] == nullptr ? 0 : 1;
  facedShapes_[k] = &shape;
  faces_[k] = facesOf(shape);
  return faces_[k];
}

SolidOnFaceAlgorithm::FacedShape SolidOnFaceAlgorithm::facesOf(const btCollisionShape& shape) {
  FacedShape faces;
  if (isBox(shape)) {
    faces.first = 0, faces.last = 2;
    faces.half = static_cast<const btBoxShape&>(shape).getHalfExtentsWithMargin();
    return faces;
  }
  faces.round = true;
  if (shape.getShapeType() == CYLINDER_SHAPE_PROXYTYPE) {
    const auto& cylinder = static_cast<const btCylinderShape&>(shape);
    const int up = cylinder.getUpAxis();
    faces.first = faces.last = up;
    faces.half = cylinder.getHalfExtentsWithMargin();
    faces.radius[0] = faces.radius[1] = faces.half[(up + 1) % 3];
    faces.ends[0] = faces.ends[1] = faces.half[up];
    return faces;
  }
  if (shape.getShapeType() != CONVEX_HULL_SHAPE_PROXYTYPE) return faces;
  // A truncated cone (Cylinder.cpp): a hull of two regular rings about its
  // y axis, grown by its margin. Each end is a polygon; the disc inscribed
  // in it counts as the face. Any other hull has none.
  const auto& hull = static_cast<const btConvexHullShape&>(shape);
  const btVector3* points = hull.getUnscaledPoints();
  const int n = hull.getNumPoints();
  if (n < 6) return faces;
  btScalar top = points[0].y(), bottom = points[0].y();
  for (int p = 1; p < n; ++p) top = std::max(top, points[p].y()), bottom = std::min(bottom, points[p].y());
  const btScalar m = hull.getMargin();
  for (int e = 0; e < 2; ++e) {
    const btScalar level = e == 0 ? top : bottom;
    const HullRing ring = hullRing(hull, level);
    if (ring.count < 3 || ring.high - ring.low > kRingTolerance) return faces;
    faces.radius[e] = ring.high * std::cos(SIMD_PI / ring.count) + m;
  }
  faces.first = faces.last = 1;
  faces.ends[0] = top + m;
  faces.ends[1] = m - bottom;
  return faces;
}

bool SolidOnFaceAlgorithm::overFace(const btCollisionObjectWrapper* boxWrap, const Face& face, const NearCorner& corner) {
  const btVector3 local = boxWrap->getWorldTransform().invXform(corner.point);
  if (face.round) {
    const int j = (face.axis + 1) % 3, k = (face.axis + 2) % 3;
    return std::hypot(local[j], local[k]) <= face.radius + kOverEdge;
  }
  for (int j = 0; j < 3; ++j) {
    if (j != face.axis && std::abs(local[j]) > face.half[j] + kOverEdge) return false;
  }
  return true;
}

bool SolidOnFaceAlgorithm::touchFace(const btCollisionObjectWrapper* boxWrap, const btCollisionObjectWrapper* solidWrap,
                             bool boxFirst, btScalar timeStep, btManifoldResult* result) {
  const Face face = outerFace(boxWrap, solidWrap, timeStep);
  if (!face.out) return false;
  // A corner deeper in than the body behind the face is not in it at
  // all: the solid does not rest on this face.
  for (const NearCorner& c : near_) {
    if (!overFace(boxWrap, face, c) || c.distance < -face.thickness) return false;
  }
  result->setPersistentManifold(manifold_);
  const int solidBody = boxFirst ? 1 : 0;
  if (solidBody != solid_) choice_.forget();  // the kept corners were the other body's
  solid_ = solidBody;
  if (near_.empty()) {
    choice_.forget();
  } else {
    const auto* solid = static_cast<const btConvexShape*>(solidWrap->getCollisionShape());
    addCornerPoints(*result, choice_.choose(*solid, near_), face.normal, boxFirst);
  }
  result->refreshContactPoints();
  // Every point is found again each step it touches: one kept from an
  // earlier step that has slid is stale.
  dropDriftedPoints(*manifold_);
  return true;
}

bool SolidOnFaceAlgorithm::addCornersOverFace(const btCollisionObjectWrapper* boxWrap,
                                      const btCollisionObjectWrapper* solidWrap, bool boxFirst, btScalar timeStep,
                                      btManifoldResult* result) {
  const Face face = outerFace(boxWrap, solidWrap, timeStep);
  std::vector<NearCorner>& over = over_;
  over.clear();
  if (face.out) {
    for (const NearCorner& c : near_) {
      if (overFace(boxWrap, face, c)) over.push_back(c);
    }
  }
  if (over.empty()) return false;
  btPersistentManifold* otherwise = result->getPersistentManifold();
  result->setPersistentManifold(manifold_);
  const auto* solid = static_cast<const btConvexShape*>(solidWrap->getCollisionShape());
  addCornerPoints(*result, choice_.choose(*solid, over), face.normal, boxFirst);
  result->refreshContactPoints();
  dropDriftedPoints(*manifold_);
  result->setPersistentManifold(otherwise);
  return true;
}

btCollisionAlgorithm* SolidOnFaceAlgorithm::CreateFunc::CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                                       const btCollisionObjectWrapper* body0,
                                                                       const btCollisionObjectWrapper* body1) {
  void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(sizeof(SolidOnFaceAlgorithm));
  return new (memory) SolidOnFaceAlgorithm(info, body0, body1, *otherwise);
}

}  // namespace tabletop
