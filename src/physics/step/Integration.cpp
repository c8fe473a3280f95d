#include "physics/step/DynamicsWorld.h"

#include <cmath>

#include "physics/contact/ContactKinematics.h"
#include "physics/solver/IslandSolver.h"

// Stage 7, integration (docs/step.md): positions follow the trapezoid rule
// where a body's velocity changed smoothly in the part, the end velocity
// where an impact or a contact stopping it changed it at once.
namespace tabletop {

// The bodies whose velocities changed since the last part ended (a push,
// a scene's start).
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

// Bodies touching nothing turn as the free rigid body does (FreeFlight.h):
// their spin set before the integration, their orientation after it.
// A body under a torque (setLoads()) turns by its mean spin, second order:
// its spin changes smoothly through the part.
void DynamicsWorld::integrate(const Part& part) {
  for (const Load& load : loads_) {
    if (!load.torque.fuzzyZero()) meanTurn_.insert(load.body);
  }
  freeFlight_.start(startSpins_, part.length);
  integrateMotions(part);
  freeFlight_.finish();
  for (const auto& [body, flags] : rollingFlags_) body->setFlags(flags);
  rollingFlags_.clear();
}

void DynamicsWorld::integrateMotions(const Part& part) {
  const btScalar timeStep = part.length;
  const bool smooth = secondOrder_ && smoothAcceleration_ > 0;
  if (smooth) {
    rolling_.record(*getDispatcher(), aside_);
    keptOut_.collect(*getDispatcher(), m_nonStaticRigidBodies, timeStep);
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
    const auto at = static_cast<std::size_t>(i);
    if (rolling_.turning()) {
      rolling_.turnAt(*body, startPoses_[at], (body->getLinearVelocity() + startVelocities_[at]) / 2,
                      (body->getAngularVelocity() + startSpins_[at]) / 2, timeStep, pose);
    }
    keptOut_.keepOut(i, startPoses_[at], pose);
    body->proceedToTransform(pose);
  }
}

// A body resting on one that an impact stops is stopped with it where the
// velocity of their touching, loaded points changed at once along the
// normal. Moved by the mean of its start and end velocities, a cylinder
// resting on a box whose raised side struck the table went on at its start
// speed for half the part and sank 0.5 mm into the box at 60 Hz. A body the
// struck one only drags along by friction changes smoothly and keeps the
// mean. At most one pass per manifold.
void DynamicsWorld::spreadStops() {
  btDispatcher* dispatcher = getDispatcher();
  const int numManifolds = dispatcher->getNumManifolds();
  if (startVelocities_.size() != static_cast<std::size_t>(m_nonStaticRigidBodies.size())) return;
  // Each moving body's index among the moving ones, and its manifolds, by
  // its index in the collision world: a body that joins looks only at its
  // own manifolds, so the spread costs bodies plus manifolds.
  const auto numObjects = static_cast<std::size_t>(getNumCollisionObjects());
  StopSpread& spread = stopSpread_;
  spread.moving.assign(numObjects, -1);
  for (int i = 0; i < m_nonStaticRigidBodies.size(); ++i) {
    const int at = m_nonStaticRigidBodies[i]->getWorldArrayIndex();
    if (at >= 0) spread.moving[static_cast<std::size_t>(at)] = i;
  }
  spread.manifoldsOf.resize(numObjects);
  for (std::vector<int>& list : spread.manifoldsOf) list.clear();
  for (int m = 0; m < numManifolds; ++m) {
    const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    for (const btCollisionObject* body : {manifold->getBody0(), manifold->getBody1()}) {
      const int at = body->getWorldArrayIndex();
      if (at >= 0 && static_cast<std::size_t>(at) < numObjects) spread.manifoldsOf[static_cast<std::size_t>(at)].push_back(m);
    }
  }
  const auto jumps = [&](const btCollisionObject* object, const btManifoldPoint& point) {
    const int at = object->getWorldArrayIndex();
    const int i = at >= 0 && static_cast<std::size_t>(at) < numObjects ? spread.moving[static_cast<std::size_t>(at)] : -1;
    if (i < 0) return false;
    const btRigidBody& body = *m_nonStaticRigidBodies[i];
    const auto s = static_cast<std::size_t>(i);
    const btVector3 lever = point.getPositionWorldOnB() - body.getCenterOfMassPosition();
    const btVector3 change = body.getLinearVelocity() - startVelocities_[s] +
                             (body.getAngularVelocity() - startSpins_[s]).cross(lever);
    return std::abs(change.dot(point.m_normalWorldOnB)) > stopSpeed();
  };
  // Every manifold is looked at once, and again each time a body of it
  // joins: the set that comes out is the closure, whatever the order.
  std::vector<int>& work = spread.work;
  work.clear();
  for (int m = numManifolds - 1; m >= 0; --m) work.push_back(m);
  while (!work.empty()) {
    const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(work.back());
    work.pop_back();
    const bool hasA = stopped_.contains(manifold->getBody0()), hasB = stopped_.contains(manifold->getBody1());
    if (hasA == hasB) continue;
    const btCollisionObject* other = hasA ? manifold->getBody1() : manifold->getBody0();
    if (other->isStaticOrKinematicObject()) continue;
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold->getContactPoint(p);
      if (point.getDistance() <= kLoadTouching && point.getAppliedImpulse() > 0 && jumps(other, point)) {
        stopped_.insert(other);
        const int at = other->getWorldArrayIndex();
        if (at >= 0 && static_cast<std::size_t>(at) < numObjects) {
          for (const int next : spread.manifoldsOf[static_cast<std::size_t>(at)]) work.push_back(next);
        }
        break;
      }
    }
  }
}

}  // namespace tabletop
