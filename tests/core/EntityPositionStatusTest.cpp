#include "core/EntityPositionStatus.h"

#include <gtest/gtest.h>

#include "core/StateHash.h"

namespace tabletop {
namespace {

TEST(EntityPositionStatus, ReportNamesRoundTrip) {
  for (auto s : {EntityPositionStatus::OnTable, EntityPositionStatus::DropFromLeftEdge,
                 EntityPositionStatus::DropFromFrontEdge, EntityPositionStatus::DropFromRightEdge,
                 EntityPositionStatus::DropFromBackEdge, EntityPositionStatus::FinishDropSimulation,
                 EntityPositionStatus::OffTable, EntityPositionStatus::OnGround}) {
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

// The status rule (EntityPositionStatus.h): where an entity starts...
TEST(EntityPositionStatus, AnEntityStartsOnTheTableOnlyOverIt) {
  using K = Support::Kind;
  EXPECT_EQ(startStatus(K::Table, false), EntityPositionStatus::OnTable);  // on the table, or a stack on it
  EXPECT_EQ(startStatus(K::None, true), EntityPositionStatus::OnTable);    // in the air over the top
  EXPECT_EQ(startStatus(K::Ground, true), EntityPositionStatus::OffTable);  // under the table
  EXPECT_EQ(startStatus(K::Ground, false), EntityPositionStatus::OffTable);
  EXPECT_EQ(startStatus(K::None, false), EntityPositionStatus::OffTable);  // in the air beside it
  EXPECT_TRUE(neverOnTable(EntityPositionStatus::OffTable));
  EXPECT_TRUE(neverOnTable(EntityPositionStatus::OnGround));
  EXPECT_FALSE(neverOnTable(EntityPositionStatus::FinishDropSimulation));
}

// ...and what coming down makes of each status.
TEST(EntityPositionStatus, ComingDownEndsADropForGoodAndSettlesAnEntityOffTheTable) {
  using S = EntityPositionStatus;
  for (bool table : {false, true}) {
    EXPECT_EQ(comeDown(S::DropFromLeftEdge, false, table), S::DropFromLeftEdge);
    EXPECT_EQ(comeDown(S::DropFromLeftEdge, true, table), S::FinishDropSimulation);
    EXPECT_EQ(comeDown(S::FinishDropSimulation, false, table), S::FinishDropSimulation);
    EXPECT_EQ(comeDown(S::OnTable, false, table), S::OnTable);
    EXPECT_EQ(comeDown(S::OnGround, false, table), S::OffTable);
    EXPECT_EQ(comeDown(S::OffTable, false, table), S::OffTable);
  }
  EXPECT_EQ(comeDown(S::OffTable, true, false), S::OnGround);
  EXPECT_EQ(comeDown(S::OnGround, true, false), S::OnGround);
  EXPECT_EQ(comeDown(S::OffTable, true, true), S::OnTable);  // came down on the table top
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
