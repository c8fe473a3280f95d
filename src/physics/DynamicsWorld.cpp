#include "physics/DynamicsWorld.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "physics/ContactResult.h"
#include "physics/FaceEdges.h"
#include "physics/Impacts.h"
#include "physics/IslandSolver.h"
#include "physics/ShapeKinds.h"
#include "physics/SlipEvents.h"

namespace tabletop {
namespace {

// A box against a box or against the table, and a box or a hull against
// the floor: the pairs whose touching points are all found afresh every
// step they touch (polyhedral clipping, PlaneVertices), so a point kept
// from an earlier step that has slid is stale.
bool isClippedBoxPair(const btPersistentManifold& manifold) {
  const auto type = [](const btCollisionObject* o) { return o->getCollisionShape()->getShapeType(); };
  const int a = type(manifold.getBody0()), b = type(manifold.getBody1());
  const auto solidOnPlane = [](int solid, int plane) {
    return plane == STATIC_PLANE_PROXYTYPE && (solid == BOX_SHAPE_PROXYTYPE || solid == CONVEX_HULL_SHAPE_PROXYTYPE ||
                                               solid == CYLINDER_SHAPE_PROXYTYPE);
  };
  if (solidOnPlane(a, b) || solidOnPlane(b, a)) return true;
  const auto clipped = [](int t) { return t == BOX_SHAPE_PROXYTYPE || t == COMPOUND_SHAPE_PROXYTYPE; };
  return (a == BOX_SHAPE_PROXYTYPE || b == BOX_SHAPE_PROXYTYPE) && clipped(a) && clipped(b);
}

// Removes every point but the deepest (ties: the first).
void keepDeepestPoint(btPersistentManifold& manifold) {
  int deepest = 0;
  for (int p = 1; p < manifold.getNumContacts(); ++p) {
    if (manifold.getContactPoint(p).getDistance() <
        manifold.getContactPoint(deepest).getDistance()) {
      deepest = p;
    }
  }
  for (int p = manifold.getNumContacts() - 1; p >= 0; --p) {
    if (p != deepest) manifold.removeContactPoint(p);
  }
}

}  // namespace

DynamicsWorld::DynamicsWorld(btDispatcher* dispatcher, btBroadphaseInterface* broadphase,
                             btConstraintSolver* solver, btCollisionConfiguration* configuration)
    : btDiscreteDynamicsWorld(dispatcher, broadphase, solver, configuration),
      islandSolver_(dynamic_cast<IslandSolver*>(solver)) {
  // Bullet made its own with btAlignedAlloc and placement new.
  if (m_ownsIslandManager) {
    m_islandManager->~btSimulationIslandManager();
    btAlignedFree(m_islandManager);
  }
  m_islandManager = &islands_;
  m_ownsIslandManager = false;
}

// Bullet calls this first in a step, before any velocity changes: the
// velocities the second-order update starts from are read here.
void DynamicsWorld::applyGravity() {
  noteKicked();
  if (smoothAcceleration_ > 0) saveStartVelocities();
  btDiscreteDynamicsWorld::applyGravity();
  applyRollingResistance();
}

void DynamicsWorld::noteKicked() {
  kicked_.clear();
  // Only a contact's slip reads it: none without one.
  if (getDispatcher()->getNumManifolds() == 0) return;
  const auto n = static_cast<std::size_t>(m_nonStaticRigidBodies.size());
  for (std::size_t i = 0; i < n; ++i) {
    const btRigidBody* body = m_nonStaticRigidBodies[static_cast<int>(i)];
    const bool same = i < endVelocities_.size() && endVelocities_.size() == n &&
                      endVelocities_[i].first == body->getLinearVelocity() &&
                      endVelocities_[i].second == body->getAngularVelocity();
    if (!same) kicked_.insert(body);
  }
}

void DynamicsWorld::saveStartVelocities() {
  const auto n = static_cast<std::size_t>(m_nonStaticRigidBodies.size());
  startVelocities_.resize(n);
  startSpins_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const btRigidBody& body = *m_nonStaticRigidBodies[static_cast<int>(i)];
    startVelocities_[i] = body.getLinearVelocity();
    startSpins_[i] = body.getAngularVelocity();
  }
}

void DynamicsWorld::shortenPart(double length) {
  const double ratio = length / partLength_;
  // The rolling resistance was given for the whole part: the rest goes back.
  for (const auto& [body, impulse] : resisted_) body->applyTorqueImpulse(-impulse * (1.0 - ratio));
  for (auto& resisted : resisted_) resisted.second *= ratio;
  for (ResistedSlip& slip : resistedSlips_) slip.friction *= ratio;
  scaleCarriedImpulses(ratio);
  partLength_ = length;
}

void DynamicsWorld::scaleCarriedImpulses(double ratio) {
  if (ratio == 1.0) return;
  for (int m = 0; m < getDispatcher()->getNumManifolds(); ++m) {
    btPersistentManifold* manifold = getDispatcher()->getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      btManifoldPoint& point = manifold->getContactPoint(p);
      point.m_appliedImpulse *= ratio;
      point.m_appliedImpulseLateral1 *= ratio;
      point.m_appliedImpulseLateral2 *= ratio;
    }
  }
}

// The step is taken in parts, each ending at the next impact inside it
// (solveConstraints shortens the part), at most kMaxParts; the last part
// takes whatever is left whole.
void DynamicsWorld::step(double dt) {
  stepLength_ = dt;
  struck_.clear();
  double left = dt;
  for (int part = 0; left > 0; ++part) {
    if (lastStep_ > 0) scaleCarriedImpulses(left / lastStep_);
    partLength_ = left;
    partOffset_ = dt - left;
    mayCut_ = part + 1 < kMaxParts && smoothAcceleration_ > 0;
    // maxSubSteps = 0: exactly one step of the given length.
    stepSimulation(left, 0);
    lastStep_ = partLength_;
    left = partLength_ < left ? left - partLength_ : 0.0;
  }
}

// Bodies touching nothing turn as the free rigid body does (FreeFlight.h):
// found before the solve (which leaves out their gyroscopic term), their
// spin set before the integration, their orientation after it.
void DynamicsWorld::integrateTransforms(btScalar) {
  freeFlight_.start(startSpins_, partLength_);
  integrateMotions();
  freeFlight_.finish();
}

void DynamicsWorld::integrateMotions() {
  const btScalar timeStep = partLength_;
  const bool smooth = secondOrder_ && smoothAcceleration_ > 0;
  // The poses a mean turn starts from, kept only when a body turns so.
  if (smooth && !meanTurn_.empty()) {
    startPoses_.resize(static_cast<std::size_t>(m_nonStaticRigidBodies.size()));
    for (int i = 0; i < m_nonStaticRigidBodies.size(); ++i) {
      startPoses_[static_cast<std::size_t>(i)] = m_nonStaticRigidBodies[i]->getWorldTransform();
    }
  }
  endVelocities_.resize(static_cast<std::size_t>(m_nonStaticRigidBodies.size()));
  for (int i = 0; i < m_nonStaticRigidBodies.size(); ++i) {
    const btRigidBody* body = m_nonStaticRigidBodies[i];
    endVelocities_[static_cast<std::size_t>(i)] = {body->getLinearVelocity(), body->getAngularVelocity()};
  }
  btDiscreteDynamicsWorld::integrateTransforms(timeStep);
  if (!smooth) return;
  const btScalar limit = smoothAcceleration_ * timeStep;
  for (int i = 0; i < m_nonStaticRigidBodies.size(); ++i) {
    btRigidBody* body = m_nonStaticRigidBodies[i];
    if (!body->isActive() || body->isStaticOrKinematicObject()) continue;
    const btVector3 change = body->getLinearVelocity() - startVelocities_[static_cast<std::size_t>(i)];
    if (change.length2() > limit * limit) continue;  // an impact: keep Bullet's update
    if (stopped_.contains(body)) continue;  // likewise
    // Velocity changes linearly until a slip stops, then stays: the mean
    // over the part is the end velocity less half the change times the
    // share of the part spent slipping (1 unless the slip stopped in it).
    // Only the change across the contact's normal comes from the slip.
    btVector3 mean = change;
    const auto slip = slips_.find(body);
    if (slip != slips_.end() && slip->second.stop.share < 1.0) {
      const BodySlip& s = slip->second;
      const btVector3& n = s.stop.normal;
      btVector3 across = change - n * change.dot(n);
      // After the stop, only the friction that takes back the rolling
      // resistance's slip changes the velocity, evenly to the part's end.
      const btScalar size = across.length();
      if (s.stopTaken > 0 && size > 0) {
        const double after = std::min<double>(size, s.stopTaken * (1.0 - s.stop.share) * body->getInvMass());
        across -= across * (after / size);
      }
      mean = change - across * (1.0 - s.stop.share);
    }
    btTransform pose = body->getWorldTransform();
    // The same for the spin of a body slipping on a face, about its
    // normal: only the face's friction changes it. Turned by its end rate,
    // a cube spun on the table turned 37% short at 60 Hz (first order).
    // Not where sweeps solved it: their friction is not at its bound, and
    // turned so, the 55-cube pyramid drifted 0.32 mm, not 0.21.
    const bool swept = islandSolver_ && islandSolver_->swept().contains(body);
    if (slip != slips_.end() && slip->second.faceLimit > 0 && !meanTurn_.contains(body) && !swept) {
      const SlipStop& face = slip->second.face;
      const double spinChange = face.normal.dot(body->getAngularVelocity() - startSpins_[static_cast<std::size_t>(i)]);
      if (spinChange != 0) {
        const btQuaternion back(face.normal, -spinChange * face.share * (timeStep / 2));
        pose.setRotation((back * pose.getRotation()).normalized());
      }
    }
    // A body whose rows were held at the mean (ImpactScan) turns by its
    // mean rate too: its rows let each point close by the mean of its start
    // and end speeds, and turned by the end rate, a corner the turn brought
    // down went past its row. A cube pivoting on the table's edge at 1 kHz
    // then had its edge points' impulses alternate from step to step, and
    // grew a sideways spin from rounding to 0.02 rad/s; a cylinder rolling
    // on its rims went 0.5 mm under them at 60 Hz.
    if (meanTurn_.contains(body)) {
      const btVector3 turn = body->getAngularVelocity() - startSpins_[static_cast<std::size_t>(i)];
      btTransformUtil::integrateTransform(startPoses_[static_cast<std::size_t>(i)], body->getLinearVelocity(),
                                          body->getAngularVelocity() - turn / 2, timeStep, pose);
    }
    pose.setOrigin(pose.getOrigin() - mean * (timeStep / 2));
    body->proceedToTransform(pose);
  }
}

void DynamicsWorld::performDiscreteCollisionDetection() {
  carried_.save(*getDispatcher());
  btDiscreteDynamicsWorld::performDiscreteCollisionDetection();
  carried_.restore(*getDispatcher());
}

void DynamicsWorld::solveConstraints(btContactSolverInfo& solverInfo) {
  btDispatcher* dispatcher = getDispatcher();
  freeFlight_.find(m_nonStaticRigidBodies, *dispatcher);
  const bool untouched = dispatcher->getNumManifolds() == 0 &&
                         getBroadphase()->getOverlappingPairCache()->getNumOverlappingPairs() == 0;
  if (untouched) {
    solveUntouched(solverInfo);
    return;
  }
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    if (manifold->getNumContacts() > 1 &&
        (isBall(*manifold->getBody0()) || isBall(*manifold->getBody1()))) {
      keepDeepestPoint(*manifold);
    } else if (isClippedBoxPair(*manifold)) {
      dropDriftedPoints(*manifold);
    }
  }
  resolveTouchingImpacts(solverInfo);
  pointBoxes_.start(*dispatcher);
  const ImpactScan scan(*dispatcher, impactStorage_);
  if (mayCut_) {
    const double cut = std::min({scan.earliestImpact(partLength_, kBounceSpeed),
                                 scan.earliestSeparatedImpact(*getBroadphase()->getOverlappingPairCache(),
                                                              partLength_, kBounceSpeed),
                                 earliestFaceExit(*dispatcher, partLength_, pointBoxes_)});
    if (cut < partLength_) shortenPart(cut);
  }
  // A part in which a slip turns round or stops is cut there and solved
  // again (SlipEvents.h), once: the next part takes what is left.
  const std::vector<btManifoldPoint*> alongLine = holdFrictionAlongLine();
  const SlipTurn turned =
      solvePart(solverInfo, scan, mayCut_ && secondOrder_ ? PartSolve::kMayCutAtSlip : PartSolve::kWhole);
  for (btManifoldPoint* point : alongLine) {
    point->m_contactPointFlags &= ~(BT_CONTACT_FLAG_LATERAL_FRICTION_INITIALIZED | kFirstFrictionRowOnly);
  }
  lastSlipEnd_.reset();
  if (!turned.manifold) return;
  solvePart(solverInfo, scan, PartSolve::kAfterSlipCut);
  // Held along one line only where the contact slid along one: each
  // point of a spinning face slips its own way, and its rows laid along
  // one point's line braked a spun box on the slab 3% too weakly.
  const ContactKey key = contactOf(*turned.manifold);
  const bool alongOneLine = std::all_of(slipping_.begin(), slipping_.end(), [&](const Slip& slip) {
    return contactOf(*slip.manifold) != key || slip.velocity.normalized().dot(turned.along) > kOneLine;
  });
  if (alongOneLine) lastSlipEnd_ = SlipEnd{key, turned.along, turned.reversed};
  // A slip that ends the part at zero does not slide into the next one,
  // where a slip made at its start (by rolling resistance) is no stop; one
  // left short of zero (the time is estimated) is cut again there.
  const double still = kSlipShare * turned.point->m_combinedFriction * getGravity().length() * partLength_;
  if (slipSpeed(*turned.manifold, *turned.point) <= still) {
    const auto [first, last] = std::equal_range(sliding_.begin(), sliding_.end(), contactOf(*turned.manifold));
    sliding_.erase(first, last);
  }
}

void DynamicsWorld::solveUntouched(btContactSolverInfo& solverInfo) {
  solverInfo.m_timeStep = partLength_;
  meanTurn_.clear();
  btDiscreteDynamicsWorld::solveConstraints(solverInfo);
  closing_.clear();
  noteSolved(closing_, {});
  forgetBounced();
  lastSlipEnd_.reset();
}

void DynamicsWorld::noteSolved(const ClosingPoints& closing, const std::vector<Slip>& slipping) {
  solved_ = true;
  stopped_.clear();
  for (const auto& [manifold, point] : closing) {
    if (!(point->getAppliedImpulse() > 0)) continue;
    stopped_.insert(manifold->getBody0());
    stopped_.insert(manifold->getBody1());
  }
  if (!stopped_.empty()) spreadStops();
  findSlipStops(slipping);
}

// Solves the part. With kMayCutAtSlip, a part in which a slip turned round is
// put back as it was before the solve and shortened to that time, and the
// turn is returned: the part is to be solved again.
SlipTurn DynamicsWorld::solvePart(btContactSolverInfo& solverInfo, const ImpactScan& scan, PartSolve how) {
  btDispatcher* dispatcher = getDispatcher();
  // A part shorter than the step (cut at an impact, or what was left after
  // one) carries on what it was given, not what it solved: its impulses
  // also hold velocity corrections that do not grow with the part, and the
  // next, longer part would scale them up with its length (a remnant of
  // 1 ns once gave the next step a start of 2,500 N s). A part cut where a
  // slip turned (the second solve, at least a hundredth of the part, with
  // no impact in it) carries on what it solved: its loads, which the
  // rolling resistance of the next part reads (given none at a push's
  // first step, a ball rolled a part unresisted).
  std::vector<std::pair<btManifoldPoint*, btVector3>>& carried = partCarried_;
  carried.clear();
  if (partLength_ < stepLength_ && how != PartSolve::kAfterSlipCut) {
    for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
      btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
      for (int p = 0; p < manifold->getNumContacts(); ++p) {
        btManifoldPoint& point = manifold->getContactPoint(p);
        carried.emplace_back(&point, btVector3(point.m_appliedImpulse, point.m_appliedImpulseLateral1,
                                               point.m_appliedImpulseLateral2));
      }
    }
  }
  solverInfo.m_timeStep = partLength_;
  const int iterations = solverInfo.m_numIterations;
  const bool impacts = markImpacts(solverInfo.m_timeStep);
  if (impacts) solverInfo.m_numIterations = kImpactSweeps * iterations;
  // The points closing at the part's start that meet inside it even at
  // that speed: a body one of them stops changes its velocity at once, not
  // smoothly. (A part cut at an impact reaches its point only at its end.)
  ClosingPoints& closing = closing_;
  closing.clear();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold->getContactPoint(p);
      const double speed = closingSpeed(*manifold, point);
      if (speed > stopSpeed() && point.getDistance() <= speed * partLength_) closing.emplace_back(manifold, &point);
    }
  }
  const double g = getGravity().length();
  std::vector<Slip>& slipping = slipping_;
  slipping.clear();
  if (secondOrder_) slippingPoints(*dispatcher, g, partLength_, kSlipShare, slipping);
  // A body one of those points may stop keeps Bullet's rows on its other
  // points: held at the mean, they let a cone's rim, landing over a box's
  // edge, go 0.75 mm into the box at 60 Hz (0.29 mm without).
  meanTurn_.clear();
  stopping_.clear();
  for (const auto& [manifold, point] : closing) {
    stopping_.insert(manifold->getBody0());
    stopping_.insert(manifold->getBody1());
  }
  if (secondOrder_) scan.holdMeanVelocity(partLength_, stopping_, heldGaps_, meanTurn_);
  holdEdgeCurvature(*dispatcher, partLength_, stepLength_, secondOrder_, heldGaps_, pointBoxes_);
  holdEdgeLevers(*dispatcher, partLength_, heldPlaces_, pointBoxes_);
  // A slip counts if its contact slid through the part before, or if it is
  // more than friction takes in the part (a push's): rolling resistance
  // makes a small slip of its own at a part's start, which friction stops
  // at once, and cutting there cut every part of a rolling ball.
  const auto counts = [&](const Slip& slip) {
    return slid(sliding_, contactOf(*slip.manifold)) ||
           slip.velocity.length() > slip.point->m_combinedFriction * g * partLength_;
  };
  std::vector<Slip>& mayTurn = mayTurn_;
  mayTurn.clear();
  if (how == PartSolve::kMayCutAtSlip && !impacts) slipsThatMayTurn(*dispatcher, slipping, counts, mayTurn);
  if (!mayTurn.empty()) partStart_.save(m_nonStaticRigidBodies, *dispatcher);
  // The island pass sorts Bullet's union-find in place, and a second pass
  // over it scrambles the islands (DynamicsWorldImpacts.cpp): solved again,
  // a part cut at a slip left every body of a scene with more than one
  // island unsupported, and they fell 0.9 mm. The islands are found afresh.
  if (how == PartSolve::kAfterSlipCut) calculateSimulationIslands();
  if (islandSolver_) islandSolver_->forgetSwept();
  btDiscreteDynamicsWorld::solveConstraints(solverInfo);
  const SlipTurn turn = !mayTurn.empty() ? earliestSlipTurn(mayTurn, g, partLength_, kSlipShare)
                                         : SlipTurn{partLength_, nullptr, nullptr, btVector3(0, 0, 0), false};
  const bool turned = turn.manifold != nullptr;
  if (!turned) noteSolved(closing, slipping);
  for (const auto& [point, impulses] : carried) {
    point->m_appliedImpulse = impulses.x();
    point->m_appliedImpulseLateral1 = impulses.y();
    point->m_appliedImpulseLateral2 = impulses.z();
  }
  // Backwards: a point held twice gets its first, true gap back.
  for (auto held = heldGaps_.rbegin(); held != heldGaps_.rend(); ++held) held->first->setDistance(held->second);
  heldGaps_.clear();
  for (auto held = heldPlaces_.rbegin(); held != heldPlaces_.rend(); ++held) {
    held->point->m_positionWorldOnA = held->onA;
    held->point->m_positionWorldOnB = held->onB;
  }
  heldPlaces_.clear();
  solverInfo.m_numIterations = iterations;
  if (impacts) forgetImpacts();
  if (!turned) {
    forgetBounced();
    return turn;
  }
  partStart_.restore();
  shortenPart(turn.time);
  return turn;
}

}  // namespace tabletop
