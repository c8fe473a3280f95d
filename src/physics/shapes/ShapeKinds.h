#pragma once

#include <btBulletDynamicsCommon.h>

namespace tabletop {

/// Whether a shape is a ball: the one shape whose contact normal always
/// passes through its centre, so a contact cannot turn it, and two of
/// which meet where their centres are the sum of their radii apart.
inline bool isBall(const btCollisionShape& shape) { return shape.getShapeType() == SPHERE_SHAPE_PROXYTYPE; }
inline bool isBall(const btCollisionObject& object) { return isBall(*object.getCollisionShape()); }

/// Whether a shape is a box (a cube, a SolidBox, a piece of the table).
inline bool isBox(const btCollisionShape& shape) { return shape.getShapeType() == BOX_SHAPE_PROXYTYPE; }

/// Whether an object is a body that moves: a rigid body of finite mass (not
/// the table, the floor or a body held kinematic).
inline bool isMoving(const btCollisionObject& object) {
  const btRigidBody* body = btRigidBody::upcast(&object);
  return body != nullptr && body->getInvMass() > 0;
}

}  // namespace tabletop
