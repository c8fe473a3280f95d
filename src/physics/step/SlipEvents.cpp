#include "physics/step/SlipEvents.h"

#include <algorithm>
#include <cmath>

#include "physics/contact/ContactKinematics.h"
#include "physics/shapes/ShapeKinds.h"

namespace tabletop {
namespace {

// A slip that ends within this share of either end of the part is left to
// the part's solve (DynamicsWorld's slip share): a cut there buys little.
constexpr double kLeastShare = 0.01;

// The moving bodies that touch another moving body (carry it, or ride on
// it) within kLoadTouching: one pass over the manifolds.
void markTouchingAnother(btDispatcher& dispatcher, BodySet& touching) {
  touching.clear();
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    if (!isMoving(*manifold->getBody0()) || !isMoving(*manifold->getBody1())) continue;
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      if (manifold->getContactPoint(p).getDistance() <= kLoadTouching) {
        touching.insert(manifold->getBody0());
        touching.insert(manifold->getBody1());
        break;
      }
    }
  }
}

}  // namespace

void slippingPoints(btDispatcher& dispatcher, double g, double length, double share, std::vector<Slip>& out) {
  out.clear();
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold->getContactPoint(p);
      const btVector3 slip = slipVelocity(*manifold, point);
      if (slip.length() > share * point.m_combinedFriction * g * length) out.push_back({manifold, &point, slip});
    }
  }
}

namespace {

// How much A's slip over B at `point` along `along` changes per unit of
// friction impulse there, s/kg: the inverse masses, and for a lone point
// (a ball, an edge) the turning it gives; the points of a face hold the
// turning between them.
double slipPerImpulse(const btPersistentManifold& manifold, const btManifoldPoint& point, const btVector3& along,
                      int loaded) {
  double k = 0;
  for (const btCollisionObject* object : {manifold.getBody0(), manifold.getBody1()}) {
    const btRigidBody* body = btRigidBody::upcast(object);
    if (!body || body->getInvMass() == 0) continue;
    const btVector3& at = object == manifold.getBody0() ? point.getPositionWorldOnA() : point.getPositionWorldOnB();
    k += loaded == 1 ? body->computeImpulseDenominator(at, along) : body->getInvMass();
  }
  return k;
}

}  // namespace

void slipsThatMayTurn(btDispatcher& dispatcher, const std::vector<Slip>& slips,
                      const std::function<bool(const Slip&)>& counts, BodySet& touching, std::vector<Slip>& out) {
  out.clear();
  bool marked = false;
  for (const Slip& slip : slips) {
    const btCollisionObject* a = slip.manifold->getBody0();
    const btCollisionObject* b = slip.manifold->getBody1();
    if (!counts(slip)) continue;
    if (!(isMoving(*a) && isMoving(*b))) {
      if (!marked) markTouchingAnother(dispatcher, touching), marked = true;
      if (!touching.contains(a) && !touching.contains(b)) continue;
    }
    out.push_back(slip);
  }
}

SlipTurn earliestSlipTurn(const std::vector<Slip>& slips, double g, double length, double share) {
  SlipTurn earliest{length, nullptr, nullptr, btVector3(0, 0, 0), false};
  for (const Slip& slip : slips) {
    const btManifoldPoint& point = *slip.point;
    const double before = slip.velocity.length();
    const btVector3 along = slip.velocity / before;
    const btVector3 now = slipVelocity(*slip.manifold, point);
    const double mu = point.m_combinedFriction;
    const double still = share * mu * g * length;
    const double after = now.dot(along);
    // Turned round, or stopped: the slip ended the part reversed, or still.
    if (!(point.getAppliedImpulse() > 0) || !(after < -still || now.length() <= still)) continue;
    // The contact's load and the friction it used against the slip, N s.
    double load = 0, used = 0;
    int loaded = 0;
    for (int p = 0; p < slip.manifold->getNumContacts(); ++p) {
      const btManifoldPoint& q = slip.manifold->getContactPoint(p);
      if (!(q.getAppliedImpulse() > 0)) continue;
      load += q.getAppliedImpulse();
      ++loaded;
      const btVector3 friction = q.m_lateralFrictionDir1 * q.m_appliedImpulseLateral1 +
                                 q.m_lateralFrictionDir2 * q.m_appliedImpulseLateral2;
      used -= friction.dot(along);
    }
    const double missing = std::max(0.0, mu * load - used) * slipPerImpulse(*slip.manifold, point, along, loaded);
    const double t = length * before / (before - after + missing);
    if (t > kLeastShare * length && t < (1.0 - kLeastShare) * length && t < earliest.time) {
      earliest = {t, slip.manifold, slip.point, along, after < -still};
    }
  }
  return earliest;
}

void PartStart::save(const btAlignedObjectArray<btRigidBody*>& bodies, btDispatcher& dispatcher) {
  bodies_.clear();
  points_.clear();
  for (int i = 0; i < bodies.size(); ++i) {
    btRigidBody* body = bodies[i];
    bodies_.push_back({body, body->getWorldTransform(), body->getLinearVelocity(), body->getAngularVelocity()});
  }
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      btManifoldPoint& point = manifold->getContactPoint(p);
      points_.push_back({&point, point.m_appliedImpulse, point.m_appliedImpulseLateral1,
                         point.m_appliedImpulseLateral2});
    }
  }
}

void PartStart::restore() const {
  for (const Body& b : bodies_) {
    b.body->setWorldTransform(b.place);
    b.body->setLinearVelocity(b.linear);
    b.body->setAngularVelocity(b.angular);
  }
  for (const Point& p : points_) {
    p.point->m_appliedImpulse = p.normal;
    p.point->m_appliedImpulseLateral1 = p.lateral1;
    p.point->m_appliedImpulseLateral2 = p.lateral2;
  }
}

}  // namespace tabletop
