#pragma once

#include <memory>

#include <btBulletDynamicsCommon.h>

namespace tabletop::test {

/// Contacts built by hand, for tests of one stage of the step on its own
/// (no collision, no world).

/// A body of `mass` kg at `at`, moving at `velocity`, with its weight
/// under `g` m/s^2 (along -y) applied as a force (none for g = 0).
inline std::unique_ptr<btRigidBody> movingBody(btCollisionShape& shape, double mass, const btVector3& at,
                                               const btVector3& velocity, double g) {
  btVector3 inertia;
  shape.calculateLocalInertia(mass, inertia);
  auto body = std::make_unique<btRigidBody>(btRigidBody::btRigidBodyConstructionInfo(mass, nullptr, &shape, inertia));
  body->setWorldTransform(btTransform(btQuaternion::getIdentity(), at));
  body->setLinearVelocity(velocity);
  if (g != 0) body->applyCentralForce(btVector3(0, -mass * g, 0));
  return body;
}

/// The four corners of the base of a cube of half side `half`, unturned,
/// centred at (0, half, 0) on a fixed body whose top is y = 0: touching
/// points of `manifold` (the cube A, the support B), the normal up, with
/// friction `mu`.
inline void addBaseCorners(btPersistentManifold& manifold, double half, double mu) {
  for (const double x : {-half, half}) {
    for (const double z : {-half, half}) {
      const btVector3 corner(x, 0, z);
      btManifoldPoint point(btVector3(x, -half, z), corner, btVector3(0, 1, 0), 0);
      point.m_positionWorldOnA = corner;
      point.m_positionWorldOnB = corner;
      point.m_combinedFriction = mu;
      manifold.addManifoldPoint(point);
    }
  }
}

}  // namespace tabletop::test
