#pragma once

#include <BulletDynamics/MLCPSolvers/btDantzigSolver.h>
#include <BulletDynamics/MLCPSolvers/btMLCPSolver.h>

namespace tabletop {

/// The Dantzig contact solver (ContactSolver::Dantzig): Bullet's MLCP
/// solver, which solves an island's contacts exactly by Dantzig's pivoting
/// method, for islands of at most `rowLimit` rows (each contact point has
/// a normal row and two friction rows). Larger islands, whose dense
/// pivoting would cost the cube of their rows, get Bullet's sequential
/// impulses instead, as does any island the pivoting fails on (Bullet's
/// own fallback, counted by getNumFallbacks()).
///
/// The world must hand it one island at a time (its solver info's
/// m_minimumSolverBatchSize of 1), or small islands are batched together.
class IslandSolver : public btMLCPSolver {
 public:
  explicit IslandSolver(int rowLimit);

 protected:
  btScalar solveGroupCacheFriendlySetup(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds,
                                        int numManifolds, btTypedConstraint** constraints, int numConstraints,
                                        const btContactSolverInfo& info, btIDebugDraw* debugDrawer) override;
  btScalar solveGroupCacheFriendlyIterations(btCollisionObject** bodies, int numBodies,
                                             btPersistentManifold** manifolds, int numManifolds,
                                             btTypedConstraint** constraints, int numConstraints,
                                             const btContactSolverInfo& info, btIDebugDraw* debugDrawer) override;

 private:
  btDantzigSolver dantzig_;
  int rowLimit_;
  bool directNow_ = false;  // the island being solved is solved directly
};

}  // namespace tabletop
