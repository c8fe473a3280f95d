// ContactIslands: islands joined by contact points, never by a pair that
// holds none, nor through a body that does not move (the table).

#include "physics/solver/ContactIslands.h"

#include <memory>
#include <vector>

#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>

namespace tabletop {
namespace {

TEST(ContactIslands, BodiesShareAnIslandOnlyThroughAManifoldHoldingAPoint) {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher(&configuration);
  btDbvtBroadphase broadphase;
  btCollisionWorld world(&dispatcher, &broadphase, &configuration);
  btSphereShape ball(0.05);
  btStaticPlaneShape planeShape(btVector3(0, 1, 0), 0);
  std::vector<std::unique_ptr<btRigidBody>> bodies;
  for (int i = 0; i < 4; ++i) {
    bodies.push_back(std::make_unique<btRigidBody>(1.0, nullptr, &ball, btVector3(1e-3, 1e-3, 1e-3)));
    bodies.back()->setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(0.3 * i, 0.05, 0)));
    world.addCollisionObject(bodies.back().get());
  }
  btCollisionObject floor;
  floor.setCollisionShape(&planeShape);
  floor.setCollisionFlags(btCollisionObject::CF_STATIC_OBJECT);
  world.addCollisionObject(&floor);
  const auto touch = [&](btCollisionObject* a, btCollisionObject* b, bool withPoint) {
    btPersistentManifold* manifold = dispatcher.getNewManifold(a, b);
    if (withPoint) manifold->addManifoldPoint(btManifoldPoint(btVector3(0, 0, 0), btVector3(0, 0, 0), btVector3(0, 1, 0), 0));
  };
  touch(bodies[0].get(), bodies[1].get(), true);   // 0 and 1 touch
  touch(bodies[1].get(), bodies[2].get(), false);  // 1 and 2 are near, no point
  for (auto& body : bodies) touch(body.get(), &floor, true);  // all on the floor

  ContactIslands islands;
  islands.updateActivationState(&world, &dispatcher);
  btUnionFind& sets = islands.getUnionFind();
  const auto island = [&](int i) { return sets.find(bodies[i]->getIslandTag()); };
  EXPECT_EQ(island(0), island(1));
  EXPECT_NE(island(1), island(2));
  EXPECT_NE(island(2), island(3));
  EXPECT_NE(island(0), island(3));
  EXPECT_EQ(floor.getIslandTag(), -1);  // the floor is in none

  while (dispatcher.getNumManifolds() > 0) dispatcher.releaseManifold(dispatcher.getManifoldByIndexInternal(0));
  for (auto& body : bodies) world.removeCollisionObject(body.get());
  world.removeCollisionObject(&floor);
}

}  // namespace
}  // namespace tabletop
