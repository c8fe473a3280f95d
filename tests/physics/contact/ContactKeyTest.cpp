// ContactKey: contacts named by their bodies and ordered by the bodies'
// places in the world, so that the order (which breaks ties among slips)
// does not depend on where the bodies happen to sit in memory.

#include "physics/contact/ContactKey.h"

#include <algorithm>
#include <vector>

#include <btBulletCollisionCommon.h>
#include <gtest/gtest.h>

namespace tabletop {
namespace {

TEST(ContactKey, ContactsAreOrderedByTheirBodiesPlacesInTheWorldNotTheirAddresses) {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher(&configuration);
  btDbvtBroadphase broadphase;
  btCollisionWorld world(&dispatcher, &broadphase, &configuration);
  btSphereShape ball(0.05);
  std::vector<btCollisionObject> objects(3);
  for (auto& o : objects) o.setCollisionShape(&ball);
  // Added last first: the world's order is the reverse of the addresses'.
  for (int i = 2; i >= 0; --i) world.addCollisionObject(&objects[static_cast<std::size_t>(i)]);
  btCollisionObject *first = &objects[2], *second = &objects[1], *third = &objects[0];
  ASSERT_EQ(first->getWorldArrayIndex(), 0);
  ASSERT_EQ(third->getWorldArrayIndex(), 2);
  ASSERT_TRUE(std::less<const btCollisionObject*>()(third, second));
  ASSERT_TRUE(std::less<const btCollisionObject*>()(second, first));

  const ContactKey a{first, second}, b{first, third}, c{second, third};
  EXPECT_LT(a, b);
  EXPECT_LT(b, c);
  EXPECT_FALSE(b < a);
  EXPECT_FALSE(a < a);
  EXPECT_EQ(a, (ContactKey{first, second}));
  EXPECT_NE(a, (ContactKey{second, first}));

  btPersistentManifold* manifold = dispatcher.getNewManifold(second, third);
  EXPECT_EQ(contactOf(*manifold), c);
  SlidingContacts sliding{a, c};
  EXPECT_TRUE(slid(sliding, c));
  EXPECT_FALSE(slid(sliding, b));
  dispatcher.releaseManifold(manifold);
  for (auto& o : objects) world.removeCollisionObject(&o);
}

}  // namespace
}  // namespace tabletop
