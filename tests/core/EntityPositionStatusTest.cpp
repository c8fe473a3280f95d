#include "core/EntityPositionStatus.h"

#include <gtest/gtest.h>

#include "core/StateHash.h"

namespace tabletop {
namespace {

TEST(EntityPositionStatus, ReportNamesRoundTrip) {
  for (auto s : {EntityPositionStatus::OnTable, EntityPositionStatus::DropFromLeftEdge,
                 EntityPositionStatus::DropFromFrontEdge, EntityPositionStatus::DropFromRightEdge,
                 EntityPositionStatus::DropFromBackEdge, EntityPositionStatus::FinishDropSimulation}) {
    EXPECT_EQ(statusFromString(toString(s)), s);
  }
  EXPECT_EQ(toString(EntityPositionStatus::DropFromFrontEdge), "DropFromFrontEdge");
}

TEST(EntityPositionStatus, OnlyTheFourDropsAreDropping) {
  EXPECT_FALSE(isDropping(EntityPositionStatus::OnTable));
  EXPECT_FALSE(isDropping(EntityPositionStatus::FinishDropSimulation));
  EXPECT_TRUE(isDropping(EntityPositionStatus::DropFromBackEdge));
  EXPECT_EQ(edgeName(EntityPositionStatus::DropFromLeftEdge), "Left");
}

TEST(StateHash, ChangesWithAnyBitOfState) {
  EntityState a;
  a.position = {0.1, 0.2, 0.3};
  const auto h = stateHash({a});
  EXPECT_EQ(h, stateHash({a}));
  EntityState b = a;
  b.linearVelocity.z = 1e-300;
  EXPECT_NE(h, stateHash({b}));
  EXPECT_EQ(formatHash(0x1234).size(), 16u);
}

}  // namespace
}  // namespace tabletop
