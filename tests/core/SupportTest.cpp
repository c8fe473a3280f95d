// Support: a value named only at output; every name it prints reads back
// as the same value, and entities never collide with the reserved names.
#include "core/Support.h"

#include <gtest/gtest.h>

namespace tabletop {
namespace {

TEST(Support, NamesReadBackAsTheSameValue) {
  for (const Support& s : {Support(), Support::table(), Support::ground(), Support::entity("A")}) {
    EXPECT_EQ(Support::named(s.name()), s) << s.name();
  }
}

TEST(Support, KindsAndEntitiesAreToldApart) {
  EXPECT_TRUE(Support::named("").isNone());
  EXPECT_EQ(Support::named("table").kind(), Support::Kind::Table);
  EXPECT_EQ(Support::named("ground").kind(), Support::Kind::Ground);
  EXPECT_EQ(Support::named("big").entityName(), "big");
  EXPECT_NE(Support::entity("A"), Support::entity("B"));
  EXPECT_TRUE(Support::entity("A") < Support::entity("B") || Support::entity("B") < Support::entity("A"));
  EXPECT_EQ(Support::table().entityName(), "");
}

}  // namespace
}  // namespace tabletop
