#include "physics/DynamicsWorld.h"

namespace tabletop {
namespace {

bool isSphere(const btCollisionObject* object) {
  return object->getCollisionShape()->getShapeType() == SPHERE_SHAPE_PROXYTYPE;
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

void DynamicsWorld::solveConstraints(btContactSolverInfo& solverInfo) {
  btDispatcher* dispatcher = getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    if (manifold->getNumContacts() > 1 &&
        (isSphere(manifold->getBody0()) || isSphere(manifold->getBody1()))) {
      keepDeepestPoint(*manifold);
    }
  }
  btDiscreteDynamicsWorld::solveConstraints(solverInfo);
}

}  // namespace tabletop
