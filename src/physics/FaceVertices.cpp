#include "physics/FaceVertices.h"

#include <cmath>
#include <new>
#include <utility>
#include <vector>

#include <BulletCollision/NarrowPhaseCollision/btPolyhedralContactClipping.h>

#include "physics/ContactResult.h"
#include "physics/Impacts.h"
#include "physics/ShapeKinds.h"

namespace tabletop {

FaceVertices::FaceVertices(const btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* body0,
                           const btCollisionObjectWrapper* body1, btCollisionAlgorithmCreateFunc& otherwise)
    : btActivatingCollisionAlgorithm(info, body0, body1), otherwiseFunc_(otherwise) {
  manifold_ = m_dispatcher->getNewManifold(body0->getCollisionObject(), body1->getCollisionObject());
}

FaceVertices::~FaceVertices() {
  if (otherwise_) {
    otherwise_->~btCollisionAlgorithm();
    m_dispatcher->freeCollisionAlgorithm(otherwise_);
  }
  if (manifold_) m_dispatcher->releaseManifold(manifold_);
}

void FaceVertices::getAllContactManifolds(btManifoldArray& manifolds) {
  if (manifold_) manifolds.push_back(manifold_);
  if (otherwise_) otherwise_->getAllContactManifolds(manifolds);
}

void FaceVertices::clearOtherwise() {
  if (!otherwise_) return;
  btManifoldArray manifolds;
  otherwise_->getAllContactManifolds(manifolds);
  for (int i = 0; i < manifolds.size(); ++i) manifolds[i]->clearManifold();
}

void FaceVertices::processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                                    const btDispatcherInfo& info, btManifoldResult* result) {
  // Two bodies with faces: the first whose face the other rests on, a
  // box's before a cylinder's, else the first body's, so the roles stay put
  // from step to step.
  const bool box0 = isBox(*body0->getCollisionShape());
  const bool box1 = isBox(*body1->getCollisionShape());
  const bool firstFaced = box0 || (!box1 && hasFaces(*body0->getCollisionShape()));
  const btCollisionObjectWrapper* faced = firstFaced ? body0 : body1;
  const btCollisionObjectWrapper* other = firstFaced ? body1 : body0;
  if (touchFace(faced, other, firstFaced, info.m_timeStep, result) ||
      (hasFaces(*other->getCollisionShape()) && touchFace(other, faced, !firstFaced, info.m_timeStep, result))) {
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
  if (box0 && box1) {
    clipApart(body0, body1, result);
  } else if (addCornersOverFace(faced, other, firstFaced, info.m_timeStep, result)) {
    return;
  }
  manifold_->clearManifold();
  choice_.forget();
}

void FaceVertices::clipApart(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
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

bool FaceVertices::hasFaces(const btCollisionShape& shape) {
  return isBox(shape) || shape.getShapeType() == CYLINDER_SHAPE_PROXYTYPE;
}

FaceVertices::Face FaceVertices::outerFace(const btCollisionObjectWrapper* boxWrap,
                                           const btCollisionObjectWrapper* solidWrap, btScalar timeStep) {
  near_.clear();
  const btCollisionShape& faced = *boxWrap->getCollisionShape();
  const auto* solid = static_cast<const btConvexShape*>(solidWrap->getCollisionShape());
  const btTransform& boxPose = boxWrap->getWorldTransform();
  const btTransform& solidPose = solidWrap->getWorldTransform();
  const btVector3 half = halfExtents(faced);
  // A box's six faces; a cylinder's two ends, across its axis.
  const bool cylinder = !isBox(faced);
  const int first = cylinder ? static_cast<const btCylinderShape&>(faced).getUpAxis() : 0;
  const int last = cylinder ? first : 2;

  // The face the solid lies farthest out from, along its normal: where it
  // rests if it rests on the body.
  Face face;
  btScalar side = 1, separation = -BT_LARGE_FLOAT;
  for (int i = first; i <= last; ++i) {
    for (const btScalar s : {btScalar(1), btScalar(-1)}) {
      const btVector3 n = boxPose.getBasis().getColumn(i) * s;
      const btVector3 lowest = solidPose * solid->localGetSupportingVertex(solidPose.getBasis().transpose() * -n);
      const btScalar apart = n.dot(lowest - boxPose.getOrigin()) - half[i];
      if (apart > separation) separation = apart, face.axis = i, side = s;
    }
  }
  face.normal = boxPose.getBasis().getColumn(face.axis) * side;
  face.round = cylinder;
  const btScalar offset = face.normal.dot(boxPose.getOrigin()) + half[face.axis];
  if (face.normal.dot(solidPose.getOrigin()) <= offset) return face;  // its centre is not out over the face
  nearCorners(*solid, solidPose, face.normal, offset, manifold_->getContactBreakingThreshold(),
              {solidWrap->getCollisionObject(), boxWrap->getCollisionObject(), timeStep}, corners_, near_);
  face.out = true;
  return face;
}

btVector3 FaceVertices::halfExtents(const btCollisionShape& faced) {
  return isBox(faced) ? static_cast<const btBoxShape&>(faced).getHalfExtentsWithMargin()
                      : static_cast<const btCylinderShape&>(faced).getHalfExtentsWithMargin();
}

bool FaceVertices::overFace(const btCollisionObjectWrapper* boxWrap, const Face& face, const NearCorner& corner) {
  const btVector3 half = halfExtents(*boxWrap->getCollisionShape());
  const btVector3 local = boxWrap->getWorldTransform().invXform(corner.point);
  if (face.round) {
    // A cylinder's end: a disc of its radius (the extent across its axis).
    const int j = (face.axis + 1) % 3, k = (face.axis + 2) % 3;
    return std::hypot(local[j], local[k]) <= half[j] + kOverEdge;
  }
  for (int j = 0; j < 3; ++j) {
    if (j != face.axis && std::abs(local[j]) > half[j] + kOverEdge) return false;
  }
  return true;
}

bool FaceVertices::touchFace(const btCollisionObjectWrapper* boxWrap, const btCollisionObjectWrapper* solidWrap,
                             bool boxFirst, btScalar timeStep, btManifoldResult* result) {
  const Face face = outerFace(boxWrap, solidWrap, timeStep);
  if (!face.out) return false;
  for (const NearCorner& c : near_) {
    if (!overFace(boxWrap, face, c)) return false;
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

bool FaceVertices::addCornersOverFace(const btCollisionObjectWrapper* boxWrap,
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

btCollisionAlgorithm* FaceVertices::CreateFunc::CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                                       const btCollisionObjectWrapper* body0,
                                                                       const btCollisionObjectWrapper* body1) {
  void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(sizeof(FaceVertices));
  return new (memory) FaceVertices(info, body0, body1, *otherwise);
}

}  // namespace tabletop
