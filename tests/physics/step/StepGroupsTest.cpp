// StepGroups: the moving bodies whose boxes overlap are one group, joined
// through one another; a fixed body joins nothing; spreading from a body
// gives every body of its group and no other.

#include "physics/step/StepGroups.h"

#include <memory>
#include <vector>

#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>

namespace tabletop {
namespace {

struct World {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  btBoxShape cube{btVector3(0.05, 0.05, 0.05)};
  btBoxShape slab{btVector3(2, 0.05, 2)};
  std::vector<std::unique_ptr<btDefaultMotionState>> motions;
  std::vector<std::unique_ptr<btRigidBody>> bodies;
  btAlignedObjectArray<btRigidBody*> moving;

  btRigidBody* add(btCollisionShape& shape, double mass, const btVector3& at) {
    btTransform place;
    place.setIdentity();
    place.setOrigin(at);
    motions.push_back(std::make_unique<btDefaultMotionState>(place));
    btVector3 inertia(0, 0, 0);
    if (mass > 0) shape.calculateLocalInertia(mass, inertia);
    bodies.push_back(std::make_unique<btRigidBody>(mass, motions.back().get(), &shape, inertia));
    world.addRigidBody(bodies.back().get());
    if (mass > 0) moving.push_back(bodies.back().get());
    return bodies.back().get();
  }
  ~World() {
    for (auto& b : bodies) world.removeRigidBody(b.get());
  }
  void pair() {
    world.updateAabbs();
    broadphase.calculateOverlappingPairs(&dispatcher);
  }
};

TEST(StepGroups, BodiesWhoseBoxesOverlapAreOneGroupAndTheSlabJoinsNone) {
  World w;
  // All on one fixed slab: a chain of three cubes with 2 cm between their
  // faces (their boxes, each grown by the 2 cm contact threshold,
  // overlap), a pair touching 2 m away, and a cube on its own.
  w.add(w.slab, 0, btVector3(0, -0.1, 0));
  btRigidBody* a = w.add(w.cube, 1, btVector3(0, 0, 0));
  btRigidBody* b = w.add(w.cube, 1, btVector3(0.12, 0, 0));
  btRigidBody* c = w.add(w.cube, 1, btVector3(0.24, 0, 0));
  btRigidBody* d = w.add(w.cube, 1, btVector3(1.5, 0, 1.5));
  btRigidBody* e = w.add(w.cube, 1, btVector3(1.6, 0, 1.5));
  btRigidBody* alone = w.add(w.cube, 1, btVector3(-1.5, 0, 1.5));
  w.pair();
  StepGroups groups;
  groups.find(w.moving, *w.broadphase.getOverlappingPairCache());

  BodySet seeds, out;
  seeds.insert(a);
  groups.spread(w.moving, seeds, out);
  EXPECT_TRUE(out.contains(a) && out.contains(b) && out.contains(c));
  EXPECT_FALSE(out.contains(d) || out.contains(e) || out.contains(alone));
  EXPECT_EQ(out.size(), 3u);

  seeds.clear();
  seeds.insert(e);
  seeds.insert(alone);
  groups.spread(w.moving, seeds, out);
  EXPECT_TRUE(out.contains(d) && out.contains(e) && out.contains(alone));
  EXPECT_FALSE(out.contains(a) || out.contains(b) || out.contains(c));
  EXPECT_EQ(out.size(), 3u);

  seeds.clear();
  groups.spread(w.moving, seeds, out);
  EXPECT_TRUE(out.empty());
}

// Two cubes 16 cm apart (their boxes, each grown by the 2 cm contact
// threshold, do not overlap) are two groups; a cube between them, 3 cm from
// each, joins them.
TEST(StepGroups, ABodyBetweenTwoJoinsThem) {
  World w;
  btRigidBody* a = w.add(w.cube, 1, btVector3(0, 0, 0));
  btRigidBody* b = w.add(w.cube, 1, btVector3(0.26, 0, 0));
  w.pair();
  StepGroups groups;
  groups.find(w.moving, *w.broadphase.getOverlappingPairCache());
  BodySet seeds, out;
  seeds.insert(a);
  groups.spread(w.moving, seeds, out);
  EXPECT_FALSE(out.contains(b));

  w.add(w.cube, 1, btVector3(0.13, 0, 0));
  w.pair();
  groups.find(w.moving, *w.broadphase.getOverlappingPairCache());
  groups.spread(w.moving, seeds, out);
  EXPECT_TRUE(out.contains(b));
  EXPECT_EQ(out.size(), 3u);
}

}  // namespace
}  // namespace tabletop
