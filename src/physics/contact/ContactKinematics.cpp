#include "physics/contact/ContactKinematics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/Material.h"
#include "physics/contact/ContactMaterial.h"

namespace tabletop {

btVector3 velocityAt(const btCollisionObject* object, const btVector3& point) {
  const btRigidBody* body = btRigidBody::upcast(object);
  if (!body) return btVector3(0, 0, 0);
  return body->getVelocityInLocalPoint(point - body->getCenterOfMassPosition());
}


// The normal on B points from B towards A: A closes on B when its velocity
// relative to B points against it.
double closingSpeed(const btPersistentManifold& manifold, const btManifoldPoint& point) {
  const btVector3 relative = velocityAt(manifold.getBody0(), point.getPositionWorldOnA()) -
                             velocityAt(manifold.getBody1(), point.getPositionWorldOnB());
  return -relative.dot(point.m_normalWorldOnB);
}

btVector3 slipVelocity(const btPersistentManifold& manifold, const btManifoldPoint& point) {
  const btVector3 relative = velocityAt(manifold.getBody0(), point.getPositionWorldOnA()) -
                             velocityAt(manifold.getBody1(), point.getPositionWorldOnB());
  const btVector3& n = point.m_normalWorldOnB;
  return relative - n * relative.dot(n);
}

double slipSpeed(const btPersistentManifold& manifold, const btManifoldPoint& point) {
  return slipVelocity(manifold, point).length();
}

bool strikesNow(const btPersistentManifold& manifold, const btManifoldPoint& point, double stepLength) {
  const double speed = closingSpeed(manifold, point);
  return speed > kBounceSpeed &&
         point.getDistance() <= std::max(kTouching, speed * std::min(kSameInstant, 0.01 * stepLength));
}

double timeToClose(double gap, double speed, double accel) {
  constexpr double kNever = std::numeric_limits<double>::infinity();
  if (gap <= 0) return 0.0;
  if (accel == 0) return speed > 0 ? gap / speed : kNever;
  // gap = speed t + accel t^2 / 2, its first positive root, in the form
  // that does not cancel when accel t is small against speed.
  const double discriminant = speed * speed + 2.0 * accel * gap;
  if (discriminant < 0) return kNever;
  const double denominator = speed + std::sqrt(discriminant);
  return denominator > 0 ? 2.0 * gap / denominator : kNever;
}

double restitutionOf(const btPersistentManifold& manifold) {
  const auto* a = static_cast<const Material*>(manifold.getBody0()->getUserPointer());
  const auto* b = static_cast<const Material*>(manifold.getBody1()->getUserPointer());
  return a && b ? combine(*a, *b).restitution : 0.0;
}

}  // namespace tabletop
