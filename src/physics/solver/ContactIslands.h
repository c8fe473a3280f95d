#pragma once

#include <BulletCollision/CollisionDispatch/btSimulationIslandManager.h>

namespace tabletop {

/// Bullet's island manager with islands joined by contacts, not by the
/// broadphase's pairs: two bodies share an island when a manifold between
/// them holds a point (within the contact breaking threshold, 2 cm).
/// Bullet joins every overlapping pair, and the broadphases overlap
/// differently (the dynamic tree fattens its boxes), so which bodies were
/// solved together, and so how an island was solved (IslandSolver), hung
/// on the broadphase; a pair without points adds no row to a solve.
class ContactIslands : public btSimulationIslandManager {
 public:
  void updateActivationState(btCollisionWorld* world, btDispatcher* dispatcher) override;
};

}  // namespace tabletop
