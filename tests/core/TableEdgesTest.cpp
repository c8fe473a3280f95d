// The report's drop test (3.4), which every mode uses.

#include "core/TableEdges.h"

#include <gtest/gtest.h>

namespace tabletop {
namespace {

const TableEdges kTable{-0.6, 0.6, -0.4, 0.4};

// Report 3.4: a centre exactly on an edge is still on the table.
TEST(TableEdges, DropStatusAtEveryEdge) {
  EXPECT_EQ(dropStatus({0.6, 0, 0.4}, kTable), EntityPositionStatus::OnTable);
  EXPECT_EQ(dropStatus({-0.6, 0, -0.4}, kTable), EntityPositionStatus::OnTable);
  EXPECT_EQ(dropStatus({0.6000001, 0, 0}, kTable), EntityPositionStatus::DropFromRightEdge);
  EXPECT_EQ(dropStatus({-0.6000001, 0, 0}, kTable), EntityPositionStatus::DropFromLeftEdge);
  EXPECT_EQ(dropStatus({0, 0, 0.4000001}, kTable), EntityPositionStatus::DropFromFrontEdge);
  EXPECT_EQ(dropStatus({0, 0, -0.4000001}, kTable), EntityPositionStatus::DropFromBackEdge);
  EXPECT_EQ(dropStatus({0.7, 0, -0.5}, kTable), EntityPositionStatus::DropFromRightEdge);  // X first
}

}  // namespace
}  // namespace tabletop
