#include "physics/IslandSolver.h"

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

namespace tabletop {

IslandSolver::IslandSolver(int rowLimit) : btMLCPSolver(&dantzig_), rowLimit_(rowLimit) {}

btScalar IslandSolver::solveGroupCacheFriendlySetup(btCollisionObject** bodies, int numBodies,
                                                    btPersistentManifold** manifolds, int numManifolds,
                                                    btTypedConstraint** constraints, int numConstraints,
                                                    const btContactSolverInfo& info, btIDebugDraw* debugDrawer) {
  // Rows before setup: a normal and two friction rows per contact point.
  long rows = 0;
  for (int m = 0; m < numManifolds; ++m) rows += 3L * manifolds[m]->getNumContacts();
  directNow_ = numConstraints == 0 && rows <= rowLimit_;
  if (directNow_) {
    return btMLCPSolver::solveGroupCacheFriendlySetup(bodies, numBodies, manifolds, numManifolds, constraints,
                                                      numConstraints, info, debugDrawer);
  }
  return btSequentialImpulseConstraintSolver::solveGroupCacheFriendlySetup(
      bodies, numBodies, manifolds, numManifolds, constraints, numConstraints, info, debugDrawer);
}

btScalar IslandSolver::solveGroupCacheFriendlyIterations(btCollisionObject** bodies, int numBodies,
                                                         btPersistentManifold** manifolds, int numManifolds,
                                                         btTypedConstraint** constraints, int numConstraints,
                                                         const btContactSolverInfo& info, btIDebugDraw* debugDrawer) {
  if (directNow_) {
    return btMLCPSolver::solveGroupCacheFriendlyIterations(bodies, numBodies, manifolds, numManifolds, constraints,
                                                           numConstraints, info, debugDrawer);
  }
  return btSequentialImpulseConstraintSolver::solveGroupCacheFriendlyIterations(
      bodies, numBodies, manifolds, numManifolds, constraints, numConstraints, info, debugDrawer);
}

}  // namespace tabletop
