#include "physics/solver/ContactIslands.h"

#include <BulletCollision/BroadphaseCollision/btDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionWorld.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

namespace tabletop {

// As Bullet's own: each body that moves gets the next island tag; then the
// union of what touches.
void ContactIslands::updateActivationState(btCollisionWorld* world, btDispatcher* dispatcher) {
  int index = 0;
  btCollisionObjectArray& objects = world->getCollisionObjectArray();
  for (int i = 0; i < objects.size(); ++i) {
    btCollisionObject* object = objects[i];
    if (!object->isStaticOrKinematicObject()) object->setIslandTag(index++);
    object->setCompanionId(-1);
    object->setHitFraction(1);
  }
  initUnionFind(index);
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    const btCollisionObject* a = manifold->getBody0();
    const btCollisionObject* b = manifold->getBody1();
    if (manifold->getNumContacts() == 0 || !a->mergesSimulationIslands() || !b->mergesSimulationIslands()) continue;
    getUnionFind().unite(a->getIslandTag(), b->getIslandTag());
  }
}

}  // namespace tabletop
