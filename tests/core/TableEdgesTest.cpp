// The report's drop test (3.4), which every mode uses.

#include "core/TableEdges.h"

#include <cmath>

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

// A body sliding to an edge under friction (constant deceleration a) passes
// it at the root of x0 + v0 t - a t^2 / 2 = edge: the crossing found from
// the step's two ends is that time to 1e-12 s, at every edge, every rate
// and wherever the crossing falls inside the step.
TEST(TableEdges, EdgeCrossingIsAtItsOwnTimeInsideTheStep) {
  const double a = 0.25 * 9.81, v0 = 1.5;
  for (const double rate : {30.0, 60.0, 240.0}) {
    const double dt = 1.0 / rate;
    for (const double start : {0.45, 0.3, 0.1}) {  // metres before the edge (it stops after 0.459)
      const double crossing = (v0 - std::sqrt(v0 * v0 - 2 * a * start)) / a;
      const double t0 = std::floor(crossing / dt) * dt;  // the step holding it
      const auto x = [&](double t) { return v0 * t - 0.5 * a * t * t; };
      const auto v = [&](double t) { return v0 - a * t; };
      struct Case { EntityPositionStatus drop; Vec3 axis; double edge; };
      for (const Case& c : {Case{EntityPositionStatus::DropFromRightEdge, {1, 0, 0}, kTable.xRight},
                            Case{EntityPositionStatus::DropFromLeftEdge, {-1, 0, 0}, kTable.xLeft},
                            Case{EntityPositionStatus::DropFromFrontEdge, {0, 0, 1}, kTable.zFront},
                            Case{EntityPositionStatus::DropFromBackEdge, {0, 0, -1}, kTable.zBack}}) {
        const double from = std::abs(c.edge) - start;  // distance of the start from the centre line
        const Vec3 p0 = c.axis * (from + x(t0)), p1 = c.axis * (from + x(t0 + dt));
        const double s = edgeCrossing(p0, c.axis * v(t0), p1, dt, c.drop, kTable);
        EXPECT_NEAR(t0 + s * dt, crossing, 1e-12) << rate << " Hz, " << start << " m";
      }
    }
  }
  // No crossing inside the step: the step's end.
  EXPECT_EQ(edgeCrossing({0, 0, 0}, {1, 0, 0}, {0.1, 0, 0}, 0.1, EntityPositionStatus::DropFromRightEdge, kTable), 1.0);
}

}  // namespace
}  // namespace tabletop
