#include "physics/step/DynamicsWorld.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "physics/step/ImpactSearch.h"
#include "physics/solver/IslandSolver.h"
#include "physics/contact/PointFlags.h"
#include "physics/shapes/ShapeKinds.h"

// The impacts of a part, resolved at its start (DynamicsWorld).
namespace tabletop {
namespace {

// An impact's sweeps start cold; fewer than about fifty left a face
// striking a face with its four points unevenly loaded, tipping both.
constexpr int kLeastImpactSweeps = 50;

// The kinetic energy of `bodies`, translational and rotational, J.
double kineticEnergy(const btAlignedObjectArray<btRigidBody*>& bodies) {
  double energy = 0.0;
  for (int i = 0; i < bodies.size(); ++i) {
    const btRigidBody* body = bodies[i];
    if (body->getInvMass() == 0) continue;
    const btVector3 w = body->getWorldTransform().getBasis().transpose() * body->getAngularVelocity();
    const btVector3 inv = body->getInvInertiaDiagLocal();
    const auto rotational = [](double invInertia, double rate) { return invInertia > 0 ? rate * rate / invInertia : 0.0; };
    energy += 0.5 * (body->getLinearVelocity().length2() / body->getInvMass() + rotational(inv.x(), w.x()) +
                     rotational(inv.y(), w.y()) + rotational(inv.z(), w.z()));
  }
  return energy;
}

// Sets each body's velocities to its present ones (an inelastic outcome)
// plus the largest share, at most all, of the way to `elastic` that keeps
// the kinetic energy at most `limit`. The energy is quadratic in the share
// s: K(s) = K0 + G s + H s^2.
void blendWithinEnergy(btAlignedObjectArray<btRigidBody*>& bodies,
                       const std::vector<std::pair<btVector3, btVector3>>& elastic, double limit) {
  double k0 = 0, g = 0, h = 0;
  for (int i = 0; i < bodies.size(); ++i) {
    const btRigidBody* body = bodies[i];
    if (body->getInvMass() == 0) continue;
    const btMatrix3x3 toLocal = body->getWorldTransform().getBasis().transpose();
    const btVector3 inv = body->getInvInertiaDiagLocal();
    const btVector3 inertia(inv.x() > 0 ? 1 / inv.x() : 0, inv.y() > 0 ? 1 / inv.y() : 0, inv.z() > 0 ? 1 / inv.z() : 0);
    const double mass = 1 / body->getInvMass();
    const btVector3 v = body->getLinearVelocity(), w = toLocal * body->getAngularVelocity();
    const btVector3 dv = elastic[static_cast<std::size_t>(i)].first - v;
    const btVector3 dw = toLocal * elastic[static_cast<std::size_t>(i)].second - w;
    k0 += 0.5 * (mass * v.length2() + (inertia * w).dot(w));
    g += mass * v.dot(dv) + (inertia * w).dot(dw);
    h += 0.5 * (mass * dv.length2() + (inertia * dw).dot(dw));
  }
  double share = 0.0;
  if (h > 0 && limit >= k0) share = std::min(1.0, (-g + std::sqrt(g * g + 4 * h * (limit - k0))) / (2 * h));
  for (int i = 0; i < bodies.size(); ++i) {
    btRigidBody* body = bodies[i];
    if (body->getInvMass() == 0) continue;
    body->setLinearVelocity(body->getLinearVelocity() + (elastic[static_cast<std::size_t>(i)].first - body->getLinearVelocity()) * share);
    body->setAngularVelocity(body->getAngularVelocity() +
                             (elastic[static_cast<std::size_t>(i)].second - body->getAngularVelocity()) * share);
  }
}

// Every moving body's forces, torques and gyroscopic flags, cleared for an
// impact's solve and given back as it ends.
class ForcesSetAside {
 public:
  explicit ForcesSetAside(const btAlignedObjectArray<btRigidBody*>& bodies) {
    for (int i = 0; i < bodies.size(); ++i) {
      btRigidBody* body = bodies[i];
      saved_.push_back({body, body->getTotalForce(), body->getTotalTorque(), body->getFlags()});
      body->clearForces();
      body->setFlags(body->getFlags() & ~(BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT |
                                          BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_WORLD |
                                          BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY));
    }
  }
  ~ForcesSetAside() {
    for (const Saved& s : saved_) {
      s.body->applyCentralForce(s.force);
      s.body->applyTorque(s.torque);
      s.body->setFlags(s.flags);
    }
  }
  ForcesSetAside(const ForcesSetAside&) = delete;
  ForcesSetAside& operator=(const ForcesSetAside&) = delete;

 private:
  struct Saved {
    btRigidBody* body;
    btVector3 force, torque;
    int flags;
  };
  std::vector<Saved> saved_;
};

}  // namespace

// The touching points that close at an impact's speed bounce now, at the
// start of the part, in a solve of their own: restitution e on them alone
// (0 on every other point, Bullet's speed threshold off), no gravity, no
// warm start, no position correction, positions unchanged. The part then
// starts from the velocities after the impact, as a smooth part, and no
// point gets restitution in its solve.
void DynamicsWorld::resolveTouchingImpacts(const Part& part, btContactSolverInfo& solverInfo) {
  btDispatcher* dispatcher = getDispatcher();
  bool any = false;      // a point strikes now
  bool bounces = false;  // ... with restitution
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    const double restitution = restitutionOf(*manifold);
    // A sideways impact between two moving bodies is taken at its instant
    // even with no bounce: solved with the part, it held them together
    // through the part, though nothing presses them together after it (a
    // cube pushed into a touching one with less friction braked it with
    // its own, 6.4 mm short at 60 Hz). A landing stays in the part's solve,
    // which pivots it: gravity keeps it pressed after the impact, and the
    // impact's sweeps left a cylinder landing over a box's edge 0.7 mm in.
    const bool bothMove = isMoving(*manifold->getBody0()) && isMoving(*manifold->getBody1());
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      btManifoldPoint& point = manifold->getContactPoint(p);
      const bool sideways = bothMove && std::abs(point.m_normalWorldOnB.y()) < kLoadNormal;
      const bool strikes = smoothAcceleration_ > 0 && (restitution > 0 || sideways) &&
                           strikesNow(*manifold, point, stepLength_);
      point.m_combinedRestitution = strikes ? restitution : 0.0;
      if (strikes) point.m_contactPointFlags |= kBouncedFlag;
      any |= strikes;
      bounces |= strikes && restitution > 0;
    }
  }
  if (!any) return;

  // Gravity and gyroscopic terms are set aside for the impact's solve.
  const ForcesSetAside quiet(m_nonStaticRigidBodies);
  std::vector<btScalar> carried;
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold->getContactPoint(p);
      carried.insert(carried.end(), {point.m_appliedImpulse, point.m_appliedImpulseLateral1, point.m_appliedImpulseLateral2});
    }
  }

  btContactSolverInfo impact = solverInfo;
  impact.m_solverMode &= ~SOLVER_USE_WARMSTARTING;
  impact.m_splitImpulse = 0;
  impact.m_erp = 0;
  impact.m_erp2 = 0;
  impact.m_restitutionVelocityThreshold = 0;
  impact.m_leastSquaresResidualThreshold = 0;
  impact.m_numIterations = std::max(kImpactSweeps * solverInfo.m_numIterations, kLeastImpactSweeps);
  impact.m_timeStep = part.length;
  // One group of every body and manifold, handed to the solver directly:
  // the world's island pass may run once a step only (it sorts Bullet's
  // union-find in place, and a second sort scrambles the islands, which
  // left every body unsupported for the rest of the part).
  btAlignedObjectArray<btCollisionObject*> bodies;
  std::vector<std::pair<btVector3, btVector3>> before;
  for (int i = 0; i < m_nonStaticRigidBodies.size(); ++i) {
    btRigidBody* body = m_nonStaticRigidBodies[i];
    bodies.push_back(body);
    before.emplace_back(body->getLinearVelocity(), body->getAngularVelocity());
  }
  // Swept where a point bounces: restitution is exact only without the
  // pivoting's compliance, and the energy blend below assumes a
  // dissipative solve. With no bounce it is solved as an island is
  // (pivoted where it fits): the sweeps left a corner strike turned a few
  // degrees from where finer steps converge.
  IslandSolver* islands = bounces ? islandSolver_ : nullptr;
  const auto solve = [&] {
    const IslandSolver::SweepsOnly swept(islands);
    m_constraintSolver->solveGroup(&bodies[0], bodies.size(), dispatcher->getInternalManifoldPointer(),
                                   dispatcher->getNumManifolds(), nullptr, 0, impact, m_debugDrawer, dispatcher);
  };
  const double energyBefore = kineticEnergy(m_nonStaticRigidBodies);
  // A bouncing point may still be a few micrometres apart: it bounces as
  // at touch (strikesNow), its gap put back after.
  HeldGaps::Storage heldGaps;
  HeldGaps gaps(heldGaps);
  std::vector<btManifoldPoint*> bouncing;
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      btManifoldPoint& point = manifold->getContactPoint(p);
      if (!bounced(point)) {
        // Between two moving bodies, a point farther apart than a resting
        // contact takes no part in an instant's impact: it is the next
        // impact, which the events stage cuts the part at. Held as a
        // closing within the part, a ball struck towards the next in a
        // row, 5 mm off, struck it in the same solve. A fixed support's
        // points stay, holding a body struck towards it (left out, a
        // random scene's body came back off the table with energy gained).
        const bool bothMove = isMoving(*manifold->getBody0()) && isMoving(*manifold->getBody1());
        if (bothMove && point.getDistance() > kLoadTouching) {
          gaps.storage().emplace_back(&point, point.getDistance());
          point.setDistance(BT_LARGE_FLOAT);
        }
        continue;
      }
      bouncing.push_back(&point);
      if (point.getDistance() > 0) {
        gaps.storage().emplace_back(&point, point.getDistance());
        point.setDistance(0);
      }
    }
  }
  solve();
  // Newton's law at each point of a simultaneous impact can give energy
  // from nowhere: a heavy cube resting on a light cylinder struck sideways
  // got the bounce of the cylinder's foot, and a face striking a face in
  // four points comes out a hair faster from the sweeps. Then the outcome
  // is the inelastic one plus the largest share of the elastic one's
  // difference from it that gives no energy.
  if (kineticEnergy(m_nonStaticRigidBodies) > energyBefore) {
    std::vector<std::pair<btVector3, btVector3>> elastic;
    for (int i = 0; i < m_nonStaticRigidBodies.size(); ++i) {
      btRigidBody* body = m_nonStaticRigidBodies[i];
      elastic.emplace_back(body->getLinearVelocity(), body->getAngularVelocity());
      body->setLinearVelocity(before[static_cast<std::size_t>(i)].first);
      body->setAngularVelocity(before[static_cast<std::size_t>(i)].second);
    }
    for (btManifoldPoint* point : bouncing) point->m_combinedRestitution = 0;
    solve();
    blendWithinEnergy(m_nonStaticRigidBodies, elastic, energyBefore);
  }
  noteStruck(part);
  // Every point starts the part's own solve from what it carried, but the
  // bounced ones, which start from nothing; none bounces again in it.
  std::size_t k = 0;
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold->getNumContacts(); ++p, k += 3) {
      btManifoldPoint& point = manifold->getContactPoint(p);
      const bool fresh = bounced(point);
      point.m_appliedImpulse = fresh ? 0 : carried[k];
      point.m_appliedImpulseLateral1 = fresh ? 0 : carried[k + 1];
      point.m_appliedImpulseLateral2 = fresh ? 0 : carried[k + 2];
      point.m_combinedRestitution = 0;
    }
  }
  // The second-order update reads the part's smooth change from here.
  if (smoothAcceleration_ > 0) saveStartVelocities();
}

// Each pair with a bounced point, once, with that point's normal, at the
// part's start. (The impact solve does not warm-start, so Bullet leaves
// its impulses out of the points.)
void DynamicsWorld::noteStruck(const Part& part) {
  btDispatcher* dispatcher = getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold->getContactPoint(p);
      if (!bounced(point)) continue;
      struck_.push_back({manifold->getBody0(), manifold->getBody1(), point.m_normalWorldOnB, part.offset});
      break;
    }
  }
}

void DynamicsWorld::forgetBounced() {
  btDispatcher* dispatcher = getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      manifold->getContactPoint(p).m_contactPointFlags &= ~kBouncedFlag;
    }
  }
}

// Marks the points whose bodies close along the normal faster than smooth
// forces could make them in one step.
bool DynamicsWorld::markImpacts(double timeStep) {
  if (!(smoothAcceleration_ > 0)) return false;
  bool any = false;
  const double limit = smoothAcceleration_ * timeStep;
  btDispatcher* dispatcher = getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      btManifoldPoint& point = manifold->getContactPoint(p);
      if (closingSpeed(*manifold, point) > limit) {
        point.m_contactPointFlags |= kImpactFlag;
        any = true;
      }
    }
  }
  return any;
}

// Drops the solved impulses of the marked points, so that the next step
// does not start from them.
void DynamicsWorld::forgetImpacts() {
  btDispatcher* dispatcher = getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      btManifoldPoint& point = manifold->getContactPoint(p);
      if (!(point.m_contactPointFlags & kImpactFlag)) continue;
      point.m_appliedImpulse = 0;
      point.m_appliedImpulseLateral1 = 0;
      point.m_appliedImpulseLateral2 = 0;
      point.m_contactPointFlags &= ~kImpactFlag;
    }
  }
}

}  // namespace tabletop
