#include "physics/step/DynamicsWorld.h"

#include <algorithm>

#include "core/Material.h"
#include "physics/contact/ContactMaterial.h"
#include "physics/contact/ContactKinematics.h"

// Rolling and spinning resistance (DynamicsWorld, correction 2): one
// isotropic angular impulse per touching contact, applied before the solve.
namespace tabletop {

namespace {

// A slip slower than this before the resistance acted is rounding, m/s.
constexpr double kSlipBefore = 1e-9;

// The largest angular impulse about `axis` through `contact` that does not
// reverse a body turning at `rate` about it: (I + m d^2) rate, with d the
// distance from the centre of mass to the axis (0 about the normal).
double stoppingImpulse(const btRigidBody& body, const btVector3& contact, const btVector3& axis,
                       double rate, bool aboutContact) {
  const btVector3 inv = body.getInvInertiaDiagLocal();
  const btMatrix3x3& basis = body.getWorldTransform().getBasis();
  const btVector3 local = basis.transpose() * axis;
  const double invI = inv.x() * local.x() * local.x() + inv.y() * local.y() * local.y() +
                      inv.z() * local.z() * local.z();
  double effective = invI > 0 ? 1.0 / invI : 0.0;
  if (aboutContact) {
    const btVector3 arm = contact - body.getCenterOfMassPosition();
    effective += (arm - axis * axis.dot(arm)).length2() / body.getInvMass();
  }
  return effective * rate;
}

// The weight `a` and `b` press on each other with along `normal` (from b
// to a), N: a's if it lies above b, b's if below.
double pressingWeight(const btRigidBody& a, const btRigidBody& b, const btVector3& normal, const btVector3& gravity) {
  const double down = gravity.dot(normal);  // negative when a is above b
  const double massA = a.getInvMass() > 0 ? 1.0 / a.getInvMass() : 0.0;
  const double massB = b.getInvMass() > 0 ? 1.0 / b.getInvMass() : 0.0;
  return std::max(0.0, -down * massA) + std::max(0.0, down * massB);
}

// The slip of `a` on `b` at `point`, across `normal`, m/s.
btVector3 slipAcross(const btRigidBody& a, const btRigidBody& b, const btVector3& point, const btVector3& normal) {
  const btVector3 slip = a.getVelocityInLocalPoint(point - a.getCenterOfMassPosition()) -
                         b.getVelocityInLocalPoint(point - b.getCenterOfMassPosition());
  return slip - normal * normal.dot(slip);
}

// The relative spin of `a` and `b` once the kinetic friction of this step
// (an impulse up to `friction`, N s, against the slip at `point`) has acted:
// a sphere pushed through its centre starts with no spin, but its slip
// spins it up at once and the rolling resistance acts from then on. Read
// at the step's start, with no spin to resist, it was missed for a step
// and the roll that followed went v dt too far (3% at 60 Hz).
btVector3 spinAfterSlip(const btRigidBody& a, const btRigidBody& b, const btVector3& point, const btVector3& normal,
                        double friction) {
  const btVector3 armA = point - a.getCenterOfMassPosition();
  const btVector3 armB = point - b.getCenterOfMassPosition();
  const btVector3 across = slipAcross(a, b, point, normal);
  const btVector3 spin = a.getAngularVelocity() - b.getAngularVelocity();
  const btScalar speed = across.length();
  if (speed < SIMD_EPSILON || friction <= 0) return spin;
  const btVector3 along = across / speed;
  // At most the impulse that stops the slip within the step.
  const double denominator = a.computeImpulseDenominator(point, along) + b.computeImpulseDenominator(point, along);
  const double impulse = std::min(friction, speed / denominator);
  const btVector3 turnA = a.getInvInertiaTensorWorld() * armA.cross(-along * impulse);
  const btVector3 turnB = b.getInvInertiaTensorWorld() * armB.cross(along * impulse);
  return spin + turnA - turnB;
}

}  // namespace

// For each touching manifold of the last step: the normal impulse N dt, and
// the relative spin split into its rolling part (across the normal) and
// its spinning part (about the normal); each is resisted by an angular
// impulse x N dt, x the combined rolling or spinning friction, clamped so
// that it at most stops the motion.
void DynamicsWorld::applyRollingResistance(const Part& part) {
  resisted_.clear();
  resistedSlips_.clear();
  resistedBodies_.clear();
  btDispatcher* dispatcher = getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    auto* a = const_cast<btRigidBody*>(btRigidBody::upcast(manifold->getBody0()));
    auto* b = const_cast<btRigidBody*>(btRigidBody::upcast(manifold->getBody1()));
    const auto* ma = static_cast<const Material*>(a ? a->getUserPointer() : nullptr);
    const auto* mb = static_cast<const Material*>(b ? b->getUserPointer() : nullptr);
    if (!ma || !mb) continue;
    const Material contact = combine(*ma, *mb);
    if (contact.rollingFriction <= 0 && contact.spinningFriction <= 0) continue;

    double normalImpulse = 0;
    btVector3 normal(0, 0, 0), point(0, 0, 0);
    bool touching = false;
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& cp = manifold->getContactPoint(p);
      if (cp.getAppliedImpulse() <= 0 && (solved_ || normalImpulse > 0 || cp.getDistance() > kTouching)) continue;
      touching = true;
      normal = cp.m_normalWorldOnB;
      point = cp.getPositionWorldOnB();
      normalImpulse += cp.getAppliedImpulse();
    }
    // At a scene's first step nothing has been solved yet: the weight the
    // two bodies press on each other with stands in for the load.
    if (touching && normalImpulse <= 0) normalImpulse = pressingWeight(*a, *b, normal, getGravity()) * part.length;
    if (normalImpulse <= 0) continue;

    const btVector3 spinning = normal * normal.dot(a->getAngularVelocity() - b->getAngularVelocity());
    const btVector3 spin = spinAfterSlip(*a, *b, point, normal, contact.friction * normalImpulse);
    const btVector3 slipBefore = slipAcross(*a, *b, point, normal);
    const struct {
      btVector3 part;
      double coefficient;
      bool aboutContact;
    } parts[] = {{spin - normal * normal.dot(spin), contact.rollingFriction, true},
                 {spinning, contact.spinningFriction, false}};
    for (const auto& resisted : parts) {
      const btScalar rate = resisted.part.length();
      if (resisted.coefficient <= 0 || rate < SIMD_EPSILON) continue;
      const btVector3 axis = resisted.part / rate;
      double impulse = resisted.coefficient * normalImpulse;
      for (const btRigidBody* body : {a, b}) {
        if (body->getInvMass() == 0) continue;
        impulse = std::min(impulse, stoppingImpulse(*body, point, axis, rate, resisted.aboutContact));
      }
      // As an angular impulse now, not a torque: Bullet's friction rows
      // read angular velocities without the step's external torque and add
      // it after the solve, which left a steady slip of tau dt r / I.
      if (a->getInvMass() != 0) a->applyTorqueImpulse(-axis * impulse), resisted_.emplace_back(a, -axis * impulse), resistedBodies_.insert(a);
      if (b->getInvMass() != 0) b->applyTorqueImpulse(axis * impulse), resisted_.emplace_back(b, axis * impulse), resistedBodies_.insert(b);
    }
    // The slip the resistance made is its own: the friction that takes it
    // back is not a slip's (findSlipStops). A slip before it acted (a
    // push's) is the contact's (slidIn).
    const btVector3 made = slipAcross(*a, *b, point, normal) - slipBefore;
    const btScalar madeSpeed = made.length();
    double friction = 0;
    if (madeSpeed > SIMD_EPSILON) {
      const btVector3 along = made / madeSpeed;
      friction = madeSpeed / (a->computeImpulseDenominator(point, along) + b->computeImpulseDenominator(point, along));
    }
    resistedSlips_.push_back({contactOf(*manifold), friction, slipBefore.length() > kSlipBefore});
  }
  // By contact, then in the order recorded, for resistedSlip's search.
  resistedOrder_.resize(resistedSlips_.size());
  for (std::size_t i = 0; i < resistedOrder_.size(); ++i) resistedOrder_[i] = i;
  std::sort(resistedOrder_.begin(), resistedOrder_.end(), [&](std::size_t x, std::size_t y) {
    const ContactKey& a = resistedSlips_[x].contact;
    const ContactKey& b = resistedSlips_[y].contact;
    return a != b ? a < b : x < y;
  });
}

}  // namespace tabletop
