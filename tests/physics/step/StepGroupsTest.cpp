// StepGroups: the moving bodies whose boxes overlap are one group, joined
// through one another; a fixed body joins nothing; spreading from a body
// gives every body of its group and no other.

#include "physics/step/StepGroups.h"

#include <initializer_list>
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
  // The bodies of the groups of `seeds`, with the pairs as they stand.
  BodySet groupsOf(std::initializer_list<btRigidBody*> seeds) {
    world.updateAabbs();
    broadphase.calculateOverlappingPairs(&dispatcher);
    StepGroups groups;
    groups.find(moving, *broadphase.getOverlappingPairCache());
    BodySet from, out;
    for (btRigidBody* body : seeds) from.insert(body);
    groups.spread(moving, from, out);
    return out;
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
  const BodySet chain = w.groupsOf({a});
  EXPECT_TRUE(chain.contains(a) && chain.contains(b) && chain.contains(c));
  EXPECT_EQ(chain.size(), 3u);
  const BodySet two = w.groupsOf({e, alone});
  EXPECT_TRUE(two.contains(d) && two.contains(e) && two.contains(alone));
  EXPECT_EQ(two.size(), 3u);
  EXPECT_TRUE(w.groupsOf({}).empty());
}

// Two cubes 16 cm apart (their boxes, each grown by the 2 cm contact
// threshold, do not overlap) are two groups; a cube between them, 3 cm from
// each, joins them.
TEST(StepGroups, ABodyBetweenTwoJoinsThem) {
  World w;
  btRigidBody* a = w.add(w.cube, 1, btVector3(0, 0, 0));
  btRigidBody* b = w.add(w.cube, 1, btVector3(0.26, 0, 0));
  EXPECT_FALSE(w.groupsOf({a}).contains(b));

  w.add(w.cube, 1, btVector3(0.13, 0, 0));
  const BodySet joined = w.groupsOf({a});
  EXPECT_TRUE(joined.contains(b));
  EXPECT_EQ(joined.size(), 3u);
}

}  // namespace
}  // namespace tabletop
