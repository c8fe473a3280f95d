// BodySet: which bodies are in it, by their index in the collision world,
// and those not in a world by themselves.

#include "physics/contact/BodySet.h"

#include <gtest/gtest.h>

namespace tabletop {
namespace {

btCollisionObject bodyAt(int worldIndex) {
  btCollisionObject body;
  body.setWorldArrayIndex(worldIndex);
  return body;
}

TEST(BodySet, HoldsWhatWasInsertedUntilCleared) {
  btCollisionObject a = bodyAt(3), b = bodyAt(0), c = bodyAt(7), outside = bodyAt(-1), alsoOutside = bodyAt(-1);
  BodySet set;
  EXPECT_TRUE(set.empty());
  set.insert(&a);
  set.insert(&outside);
  set.insert(&a);  // twice: still one
  EXPECT_FALSE(set.empty());
  EXPECT_TRUE(set.contains(&a));
  EXPECT_TRUE(set.contains(&outside));
  EXPECT_FALSE(set.contains(&b));  // below the highest index marked
  EXPECT_FALSE(set.contains(&c));  // beyond it
  EXPECT_FALSE(set.contains(&alsoOutside));
  set.clear();
  EXPECT_TRUE(set.empty());
  EXPECT_FALSE(set.contains(&a));
  EXPECT_FALSE(set.contains(&outside));
  // Filled again after a clear, it holds only what was inserted since.
  set.insert(&c);
  EXPECT_TRUE(set.contains(&c));
  EXPECT_FALSE(set.contains(&a));
}

}  // namespace
}  // namespace tabletop
