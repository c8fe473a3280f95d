#include "physics/step/DynamicsWorld.h"

#include <algorithm>

#include "physics/collision/ContactResult.h"
#include "physics/collision/PairTable.h"
#include "physics/solver/IslandSolver.h"
#include "physics/step/FaceExits.h"
#include "physics/step/ImpactSearch.h"

// The step of full physics, stage by stage (docs/step.md).
namespace tabletop {
namespace {

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
  if (islandSolver_) islandSolver_->setImpactSweeps(kImpactSweeps);
}

// The step is taken in parts, each ending at the next event inside it
// (cutAtNextEvent, or a slip's stop in solveContacts), at most kMaxParts;
// the last part takes whatever is left whole.
void DynamicsWorld::step(double dt) {
  stepLength_ = dt;
  struck_.clear();
  // Groups apart only where a part may be cut, and more than one body
  // could make more than one group.
  const bool grouped = smoothAcceleration_ > 0 && m_nonStaticRigidBodies.size() > 1;
  split_ = false;
  if (grouped) saveStepStart();
  takeParts(dt, grouped);
  if (split_) stepGroupsApart(dt);
}

void DynamicsWorld::takeParts(double dt, bool grouped) {
  double left = dt;
  for (int index = 0; left > 0 && !crossed_; ++index) {
    if (lastStep_ > 0) scaleCarriedImpulses(left / lastStep_);
    Part part;
    part.index = index;
    part.offset = dt - left;
    part.left = left;
    part.length = left;
    part.mayCut = index + 1 < kMaxParts && smoothAcceleration_ > 0;
    part.grouped = grouped && index == 0;
    stepPart(part);
    ++parts_;
    lastStep_ = part.length;
    left = part.length < left ? left - part.length : 0.0;
    if (left > 0 && index + 2 == kMaxParts) ++partBudgetSteps_;
  }
}

// One part, its stages in order. Bullet's own bookkeeping (kinematic
// velocities, predicted poses, continuous collision, deactivation, motion
// states) runs where its stepSimulation runs it, with the length the part
// had at its start.
void DynamicsWorld::stepPart(Part& part) {
  const btScalar left = part.left;
  m_fixedTimeStep = 0;
  m_localTime = m_latencyMotionStateInterpolation ? 0 : left;
  if (btFuzzyZero(left)) {
    synchronizeMotionStates();
    clearForces();
    return;
  }
  saveKinematicState(left);
  // 1. Start: the velocities the part starts from, gravity, rolling resistance.
  startPart(part);
  predictUnconstraintMotion(left);
  btDispatcherInfo& dispatch = getDispatchInfo();
  dispatch.m_timeStep = left;
  dispatch.m_stepCount = 0;
  dispatch.m_debugDraw = getDebugDrawer();
  createPredictiveContacts(left);
  // 2. Contacts: Bullet's broadphase and narrow phase through tabletop's
  // pair table (collision/ContactDispatcher.h), then its islands.
  performDiscreteCollisionDetection();
  // A body taken again that comes to touch one set aside: the step is
  // taken again as one world (GroupSteps.cpp).
  if (!aside_.empty() && crossesAside()) {
    crossed_ = true;
    clearForces();
    return;
  }
  calculateSimulationIslands();
  countWork();
  // 3-6. Stale points, restitution, events, the solve.
  getSolverInfo().m_timeStep = left;
  solveContacts(part, getSolverInfo());
  // 7. Integration.
  integrate(part);
  updateActions(left);
  updateActivationState(left);
  synchronizeMotionStates();
  clearForces();
}

// Before any velocity changes: the velocities the second-order update
// starts from are read here.
void DynamicsWorld::startPart(Part& part) {
  noteKicked();
  // The bodies whose slip stopped in the part before settle in this one.
  std::swap(settling_[0], settling_[1]);
  settling_[0].clear();
  if (islandSolver_) islandSolver_->setSettling(settling_[1]);
  if (smoothAcceleration_ > 0) saveStartVelocities();
  btDiscreteDynamicsWorld::applyGravity();
  for (const Load& load : loads_) {
    load.body->applyCentralForce(load.force);
    load.body->applyTorque(load.torque);
  }
  applyRollingResistance(part);
}

void DynamicsWorld::changeGravity(double g) {
  const double old = getGravity().length();
  setGravity(btVector3(0, -g, 0));
  scaleCarriedImpulses(old > 0 ? g / old : 0.0);
}

void DynamicsWorld::setLoads(std::vector<Load> loads) {
  loads_ = std::move(loads);
  if (!islandSolver_) return;
  BodySet loaded;
  for (const Load& load : loads_) loaded.insert(load.body);
  islandSolver_->setLoaded(std::move(loaded));
}

void DynamicsWorld::countWork() {
  work_.partBodies += getNumCollisionObjects();
  work_.pairs += getBroadphase()->getOverlappingPairCache()->getNumOverlappingPairs();
  btDispatcher* dispatcher = getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    work_.contactPoints += dispatcher->getManifoldByIndexInternal(m)->getNumContacts();
  }
}

void DynamicsWorld::performDiscreteCollisionDetection() {
  const CarriedImpulses::Guard carried(carried_, *getDispatcher());
  btDiscreteDynamicsWorld::performDiscreteCollisionDetection();
}

void DynamicsWorld::solveContacts(Part& part, btContactSolverInfo& solverInfo) {
  btDispatcher* dispatcher = getDispatcher();
  // The bodies touching nothing, whose turn is the free rigid body's.
  freeFlight_.find(m_nonStaticRigidBodies, *dispatcher);
  const bool untouched = dispatcher->getNumManifolds() == 0 &&
                         getBroadphase()->getOverlappingPairCache()->getNumOverlappingPairs() == 0;
  if (untouched) {
    solveUntouched(part, solverInfo);
    return;
  }
  // 3. Stale points.
  dropStalePoints();
  if (part.grouped) savePointsStart();
  if (part.index == 0 && (pointsBack_ || putBackAll_)) {
    putBackPoints(pointsBack_);
    pointsBack_ = nullptr;
    putBackAll_ = false;
  }
  // Bodies rolling on a line that turned: their velocity turned with it.
  if (secondOrder_ && smoothAcceleration_ > 0) carryRolling();
  // 4. Restitution: touching points closing at an impact's speed bounce now.
  resolveTouchingImpacts(part, solverInfo);
  // 5. Events: the part ends at the next impact or face exit inside it.
  pointBoxes_.start(*dispatcher);
  const ImpactScan scan(*dispatcher, impactStorage_);
  // With events in some groups only, the part takes the whole step, uncut;
  // those groups are taken again after it (GroupSteps.cpp).
  PartSolve how = part.mayCut && secondOrder_ ? PartSolve::kMayCutAtSlip : PartSolve::kWhole;
  if (part.grouped) {
    double cut = part.length;
    const Grouping grouping = groupEvents(part, scan, cut);
    if (grouping == Grouping::kSome) {
      split_ = true;
      how = PartSolve::kWhole;
    } else if (cut < part.length) {
      shortenPart(part, cut);
    }
  } else if (part.mayCut) {
    cutAtNextEvent(part, scan);
  }
  // 6. The solve. A part in which a slip turns round or stops is cut there
  // and solved again (SlipEvents.h), once: the next part takes what is left.
  const SlipTurn turned = [&] {
    const FrictionAlongLine held(holdFrictionAlongLine());
    return solvePart(part, solverInfo, scan, how);
  }();
  lastSlipEnd_.reset();
  if (!turned.manifold) return;
  solvePart(part, solverInfo, scan, PartSolve::kAfterSlipCut);
  noteSlipEnd(part, turned);
}

// As the pair table says (PairTable.h): a ball's manifold keeps its
// deepest point; a pair whose points are found afresh drops those whose
// sides slid apart along the contact plane.
void DynamicsWorld::dropStalePoints() {
  btDispatcher* dispatcher = getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    const PointUpkeep upkeep = pairRule(*manifold->getBody0(), *manifold->getBody1()).upkeep;
    if (upkeep == PointUpkeep::kDeepestOnly && manifold->getNumContacts() > 1) {
      keepDeepestPoint(*manifold);
    } else if (upkeep == PointUpkeep::kFoundAfresh) {
      dropDriftedPoints(*manifold);
    }
  }
}

void DynamicsWorld::carryRolling() {
  const std::vector<btRigidBody*>& moved = rolling_.transport(*getDispatcher(), kicked_);
  // Bodies rolling on a line leave their gyroscopic term out of this
  // part's solve: the turn it gives them is their line's, carried above
  // (from the part after they start rolling) and taken by their step;
  // Bullet's one-sided step of it lost (implicit) or gained (explicit,
  // midpoint) spin at first order.
  for (btRigidBody* body : rolling_.rolling()) {
    rollingFlags_.emplace_back(body, body->getFlags());
    body->setFlags(body->getFlags() & ~kGyroscopicFlags);
  }
  if (moved.empty() || startVelocities_.size() != static_cast<std::size_t>(m_nonStaticRigidBodies.size())) return;
  rolled_.clear();
  for (const btRigidBody* body : moved) rolled_.insert(body);
  for (int i = 0; i < m_nonStaticRigidBodies.size(); ++i) {
    const btRigidBody* body = m_nonStaticRigidBodies[i];
    if (!rolled_.contains(body)) continue;
    startVelocities_[static_cast<std::size_t>(i)] = body->getLinearVelocity();
    startSpins_[static_cast<std::size_t>(i)] = body->getAngularVelocity();
  }
}

double DynamicsWorld::earliestEvent(const Part& part, const ImpactScan& scan, BodySet* eventful) {
  btDispatcher* dispatcher = getDispatcher();
  return std::min({scan.earliestImpact(part.length, kBounceSpeed, eventful),
                   scan.earliestSeparatedImpact(*getBroadphase()->getOverlappingPairCache(), part.length,
                                                kBounceSpeed, eventful),
                   earliestFaceExit(*dispatcher, part.length, pointBoxes_, eventful)});
}

void DynamicsWorld::cutAtNextEvent(Part& part, const ImpactScan& scan) {
  const double cut = earliestEvent(part, scan, nullptr);
  if (cut < part.length) shortenPart(part, cut);
}

}  // namespace tabletop
