// The report's Table: its edges, its drop test (report 3.4), its compound.

#include "physics/shapes/Table.h"

#include <gtest/gtest.h>

#include "physics/shapes/Cube.h"

namespace tabletop {
namespace {

TableSpec offsetTable() {
  TableSpec t;
  t.width = 1.0;
  t.depth = 0.6;
  t.centreX = 2.0;
  t.centreZ = -1.0;
  return t;
}

TEST(Table, EdgesAreHalfTheSizeFromTheCentre) {
  const Table table(offsetTable());
  EXPECT_DOUBLE_EQ(table.xLeft(), 1.5);
  EXPECT_DOUBLE_EQ(table.xRight(), 2.5);
  EXPECT_DOUBLE_EQ(table.zBack(), -1.3);
  EXPECT_DOUBLE_EQ(table.zFront(), -0.7);
  EXPECT_DOUBLE_EQ(table.topHeight(), 0.75);
}

// Report 3.4: the entity leaves when its centre passes an edge; a centre
// exactly on the edge is still on the table.
TEST(Table, DropTestNamesTheEdgePassed) {
  const Table table(offsetTable());
  EXPECT_EQ(table.statusAt(2.0, -1.0), EntityPositionStatus::OnTable);
  EXPECT_EQ(table.statusAt(2.5, -0.7), EntityPositionStatus::OnTable);
  EXPECT_EQ(table.statusAt(1.5, -1.3), EntityPositionStatus::OnTable);
  EXPECT_EQ(table.statusAt(2.5000001, -1.0), EntityPositionStatus::DropFromRightEdge);
  EXPECT_EQ(table.statusAt(1.4999999, -1.0), EntityPositionStatus::DropFromLeftEdge);
  EXPECT_EQ(table.statusAt(2.0, -0.6999999), EntityPositionStatus::DropFromFrontEdge);
  EXPECT_EQ(table.statusAt(2.0, -1.3000001), EntityPositionStatus::DropFromBackEdge);
  // Past two edges at once: the report tests X before Z.
  EXPECT_EQ(table.statusAt(3.0, 0.0), EntityPositionStatus::DropFromRightEdge);
}

// One static body: a compound of the SolidBox top and four Cylinder legs
// that reach from the ground to the underside of the top.
TEST(Table, IsOneStaticCompoundOfTopAndFourLegs) {
  const TableSpec spec = offsetTable();
  Table table(spec);
  EXPECT_TRUE(table.body().isStaticObject());
  const auto* compound = static_cast<const btCompoundShape*>(table.body().getCollisionShape());
  ASSERT_EQ(compound->getShapeType(), COMPOUND_SHAPE_PROXYTYPE);
  EXPECT_EQ(compound->getNumChildShapes(), 5);
  // Each child's box reaches Bullet's contact breaking threshold beyond
  // the table (PaddedShape), so the compound's does too.
  btVector3 lo, hi;
  table.body().getCollisionShape()->getAabb(table.body().getWorldTransform(), lo, hi);
  const double pad = gContactBreakingThreshold;
  const double rounding = 1e-9;
  EXPECT_NEAR(lo.y(), -pad, rounding);
  EXPECT_NEAR(hi.y(), spec.height + pad, rounding);
  EXPECT_NEAR(lo.x(), table.xLeft() - pad, rounding);
  EXPECT_NEAR(hi.z(), table.zFront() + pad, rounding);
  for (int i = 0; i < 4; ++i) {
    const btVector3 c = table.legCentre(i);
    EXPECT_GT(c.x(), table.xLeft());
    EXPECT_LT(c.x(), table.xRight());
    EXPECT_NEAR(c.y() * 2, spec.height - spec.thickness, 1e-6);
  }
}

// CheckBoundary (report 3.4) moves an entity off OnTable once, and never back.
TEST(Shape, CheckBoundarySetsTheDropOnce) {
  Table table(offsetTable());
  Cube cube("A", 0.1);
  btTransform pose;
  pose.setIdentity();
  pose.setOrigin(btVector3(2.4, 0.8, -1.0));
  cube.createBody(1.0, Material{}, pose);
  EXPECT_FALSE(cube.checkBoundary(table));
  EXPECT_EQ(cube.status(), EntityPositionStatus::OnTable);
  pose.setOrigin(btVector3(2.6, 0.8, -1.0));
  cube.body()->setWorldTransform(pose);
  EXPECT_TRUE(cube.checkBoundary(table));
  EXPECT_EQ(cube.status(), EntityPositionStatus::DropFromRightEdge);
  pose.setOrigin(btVector3(2.0, 0.8, -1.0));
  cube.body()->setWorldTransform(pose);
  EXPECT_FALSE(cube.checkBoundary(table));
  EXPECT_EQ(cube.status(), EntityPositionStatus::DropFromRightEdge);
}

}  // namespace
}  // namespace tabletop
